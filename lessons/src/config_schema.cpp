#include "legofeup/lessons/config_schema.hpp"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <type_traits>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/world_file.hpp"

namespace legofeup::lessons {
namespace {

// A setting bound to one member of the configuration. `access` is a generic lambda,
// `[](auto& c) -> auto& { return c.member; }`, so the same accessor reads a const
// configuration and writes a mutable one: reading never copies the configuration. Real
// values are stored as `written × scale` (degrees → radians).
template <class T, class Access>
Setting bound(std::string key, std::string field, std::string help, SettingType type, Access access,
              double scale = 1.0) {
    Setting s;
    s.key = std::move(key);
    s.field = std::move(field);
    s.help = std::move(help);
    s.type = type;
    s.get = [access, scale](const RunConfig& c) -> SettingValue {
        if constexpr (std::is_same_v<T, double>) {
            return access(c) / scale;
        } else {
            static_cast<void>(scale);  // only real values are scaled
            return access(c);
        }
    };
    s.set = [access, scale](RunConfig& c, const SettingValue& v) {
        if constexpr (std::is_same_v<T, double>) {
            access(c) = std::get<double>(v) * scale;
        } else {
            static_cast<void>(scale);
            access(c) = std::get<T>(v);
        }
    };
    return s;
}

template <class Access>
Setting real(std::string key, std::string field, std::string help, Access access) {
    return bound<double>(std::move(key), std::move(field), std::move(help), SettingType::Real,
                         access);
}

template <class Access>
Setting degrees(std::string key, std::string field, std::string help, Access access) {
    return bound<double>(std::move(key), std::move(field), std::move(help), SettingType::Real,
                         access, kPi / 180.0);
}

template <class Access>
Setting boolean(std::string key, std::string field, std::string help, Access access) {
    return bound<bool>(std::move(key), std::move(field), std::move(help), SettingType::Boolean,
                       access);
}

template <class Access>
Setting point(std::string key, std::string field, std::string help, Access access) {
    return bound<Vector2>(std::move(key), std::move(field), std::move(help), SettingType::Point,
                          access);
}

// A whole number bound to an int member; the reader refuses negative numbers, validate()
// the rest of the range.
template <class Access>
Setting whole(std::string key, std::string field, std::string help, Access access) {
    Setting s;
    s.key = std::move(key);
    s.field = std::move(field);
    s.help = std::move(help);
    s.type = SettingType::Integer;
    s.get = [access](const RunConfig& c) -> SettingValue {
        return static_cast<std::int64_t>(access(c));
    };
    s.set = [access](RunConfig& c, const SettingValue& v) {
        access(c) = static_cast<int>(std::get<std::int64_t>(v));
    };
    return s;
}

// A Text setting naming a file: a built-in's name, or a path relative to the configuration.
Setting file(std::string key, std::string field, std::string help, std::string RunConfig::*member,
             const std::vector<std::string>& (*built_in_names)()) {
    Setting s;
    s.key = std::move(key);
    s.field = std::move(field);
    s.help = std::move(help);
    s.type = SettingType::Text;
    s.get = [member](const RunConfig& c) -> SettingValue { return c.*member; };
    s.set = [member](RunConfig& c, const SettingValue& v) { c.*member = std::get<std::string>(v); };
    s.built_in_files = built_in_names;
    return s;
}

// A real value that is only set when written (another value applies unless it is): `access`
// is a generic lambda returning the std::optional<double> member, `applies` gives the value
// that applies while it is unset (stored units).
template <class Access, class Applies>
Setting optional_real(std::string key, std::string field, std::string help, Access access,
                      Applies applies, double scale = 1.0) {
    Setting s{
        std::move(key), std::move(field), std::move(help), SettingType::Real, {}, {}, {}, {}, {}};
    s.get = [access, applies, scale](const RunConfig& c) -> SettingValue {
        return access(c).value_or(applies(c)) / scale;
    };
    s.set = [access, scale](RunConfig& c, const SettingValue& v) {
        access(c) = std::get<double>(v) * scale;
    };
    s.is_set = [access](const RunConfig& c) { return access(c).has_value(); };
    return s;
}

// One part of a pose override (the world's start pose unless set).
Setting pose_part(std::string key, std::string field, std::string help,
                  PoseOverride RunConfig::*pose, std::optional<double> PoseOverride::*part,
                  double scale = 1.0) {
    return optional_real(
        std::move(key), std::move(field), std::move(help),
        [ pose, part ](auto& c) -> auto& { return c.*pose.*part; },
        [](const RunConfig&) { return 0.0; }, scale);
}

// One sensor's own eq. 2 parameters: `ir_curve.front_c_m` (field ir_curve.front.c_m, as
// validate() names the sensor's curve) overrides the shared `ir_curve.c_m` for that sensor.
void add_sensor_curve_settings(std::vector<Setting>& s, IrSensor sensor) {
    const auto index = static_cast<std::size_t>(sensor);
    const std::string name = sensor == kFrontSensor ? "front" : "rear";
    const std::string field = ir_sensor_curve_name(sensor) + ".";
    const std::string unit = "the " + name + " sensor's own ";
    s.push_back(optional_real(
        "ir_curve." + name + "_a", field + "a", unit + "a, m per fit unit; unset: ir_curve.a",
        [index](auto& c) -> auto& { return c.ir_sensor_curves[index].a; },
        [](const RunConfig& c) { return c.ir_curve.a; }));
    s.push_back(optional_real(
        "ir_curve." + name + "_c_m", field + "c_m", unit + "C_M; unset: ir_curve.c_m",
        [index](auto& c) -> auto& { return c.ir_sensor_curves[index].c_m; },
        [](const RunConfig& c) { return c.ir_curve.c_m; }));
    s.push_back(optional_real(
        "ir_curve." + name + "_c_r", field + "c_r", unit + "C_R; unset: ir_curve.c_r",
        [index](auto& c) -> auto& { return c.ir_sensor_curves[index].c_r; },
        [](const RunConfig& c) { return c.ir_curve.c_r; }));
    s.push_back(optional_real(
        "ir_curve." + name + "_b", field + "b", unit + "b, fit units; unset: ir_curve.b",
        [index](auto& c) -> auto& { return c.ir_sensor_curves[index].b; },
        [](const RunConfig& c) { return c.ir_curve.b; }));
}

// A Choice bound to an enum member: `values` named by to_string, read back with `parse`
// (the reader has already checked the text is one of the choices).
template <class Enum, class Access, class Parse>
Setting choice(std::string key, std::string field, std::string help,
               std::initializer_list<Enum> values, Parse parse, Access access) {
    Setting s{
        std::move(key), std::move(field), std::move(help), SettingType::Choice, {}, {}, {}, {}, {}};
    for (const Enum value : values) {
        s.choices.emplace_back(to_string(value));
    }
    s.get = [access](const RunConfig& c) -> SettingValue {
        return std::string(to_string(access(c)));
    };
    s.set = [access, parse](RunConfig& c, const SettingValue& v) {
        if (const auto value = parse(std::get<std::string>(v))) {
            access(c) = *value;
        }
    };
    return s;
}

// The further lessons' settings: [localisation], filter kind, and each filter's tuning.
void add_lesson_filter_settings(std::vector<Setting>& s) {
    s.push_back(choice(
        "filter.kind", "filter.kind", "the pose filter: ekf or ukf (may change while running)",
        {FilterKind::Ekf, FilterKind::Ukf}, filter_kind_from_string,
        [](auto& c) -> auto& { return c.lesson.kind; }));
    s.push_back(boolean(
        "filter.compare_kinds", "filter.compare_kinds",
        "also run the other kind (EKF/UKF) on the same frames, for comparison only",
        [](auto& c) -> auto& { return c.lesson.compare_kinds; }));
    s.push_back(real(
        "filter.ukf_kappa", "filter.ukf_kappa",
        "UKF spread κ: sigma points at ±√((n+κ)P), weights κ/(n+κ) and 1/(2(n+κ))",
        [](auto& c) -> auto& { return c.lesson.ukf.kappa; }));
    s.push_back(choice(
        "localisation.method", "localisation.method",
        "what corrects the odometry: walls (IR), beacons (bearings), gyro_fusion (5-state EKF "
        "with encoders, accelerometers, gyro), compass or laser (scan matching in a map)",
        {Localisation::Walls, Localisation::Beacons, Localisation::GyroFusion,
         Localisation::Compass, Localisation::Laser},
        localisation_from_string, [](auto& c) -> auto& { return c.lesson.localisation; }));

    s.push_back(real(
        "beacons.r_bearing", "beacons.r_bearing", "variance of one beacon bearing, rad²",
        [](auto& c) -> auto& { return c.lesson.beacons.r_bearing; }));
    s.push_back(boolean(
        "beacons.gate", "beacons.gate_enabled", "reject bearings whose NIS exceeds the χ²(1) gate",
        [](auto& c) -> auto& { return c.lesson.beacons.gate_enabled; }));
    s.push_back(real(
        "beacons.gate_probability", "beacons.gate_probability",
        "probability of the bearing gate, in (0, 1)",
        [](auto& c) -> auto& { return c.lesson.beacons.gate_probability; }));

    s.push_back(real(
        "wheel_speed_kf.q_angle", "wheel_speed_kf.q_angle", "Q11 of each wheel's KF, °²",
        [](auto& c) -> auto& { return c.lesson.wheel_speed.q_angle; }));
    s.push_back(real(
        "wheel_speed_kf.q_rate", "wheel_speed_kf.q_rate", "Q22 of each wheel's KF, (°/s)²",
        [](auto& c) -> auto& { return c.lesson.wheel_speed.q_rate; }));
    s.push_back(real(
        "wheel_speed_kf.r_right", "wheel_speed_kf.r_right", "R of the right encoder, °²",
        [](auto& c) -> auto& { return c.lesson.wheel_speed.r_right; }));
    s.push_back(real(
        "wheel_speed_kf.r_left", "wheel_speed_kf.r_left", "R of the left encoder, °²",
        [](auto& c) -> auto& { return c.lesson.wheel_speed.r_left; }));
    s.push_back(real(
        "wheel_speed_kf.p0", "wheel_speed_kf.p0", "P0 = p0·I of each wheel's KF",
        [](auto& c) -> auto& { return c.lesson.wheel_speed.p0; }));

    s.push_back(real(
        "velocity_kf.q_v", "velocity_kf.q_v", "Q11 of the (v, ω) KF, (m/s)² per period",
        [](auto& c) -> auto& { return c.lesson.velocity.q_v; }));
    s.push_back(real(
        "velocity_kf.q_w", "velocity_kf.q_w", "Q22 of the (v, ω) KF, (rad/s)² per period",
        [](auto& c) -> auto& { return c.lesson.velocity.q_w; }));
    s.push_back(real(
        "velocity_kf.r_v", "velocity_kf.r_v", "R11: variance of the encoder speed, (m/s)²",
        [](auto& c) -> auto& { return c.lesson.velocity.r_v; }));
    s.push_back(real(
        "velocity_kf.r_w", "velocity_kf.r_w", "R22: variance of the encoder turn rate, (rad/s)²",
        [](auto& c) -> auto& { return c.lesson.velocity.r_w; }));
    s.push_back(real(
        "velocity_kf.p0", "velocity_kf.p0", "P0 = p0·I of the (v, ω) KF",
        [](auto& c) -> auto& { return c.lesson.velocity.p0; }));

    s.push_back(real(
        "gyro_fusion.q_position", "gyro_fusion.q_position",
        "5-state EKF: Q of x and y per period, m²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_position; }));
    s.push_back(real(
        "gyro_fusion.q_heading", "gyro_fusion.q_heading", "5-state EKF: Q of θ per period, rad²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_heading; }));
    s.push_back(real(
        "gyro_fusion.q_v", "gyro_fusion.q_v", "5-state EKF: Q of v per period, (m/s)²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_v; }));
    s.push_back(real(
        "gyro_fusion.q_w", "gyro_fusion.q_w", "5-state EKF: Q of ω per period, (rad/s)²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.q_w; }));
    s.push_back(real(
        "gyro_fusion.r_v_encoders", "gyro_fusion.r_v_encoders",
        "variance of the encoder speed, (m/s)²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_v_encoders; }));
    s.push_back(real(
        "gyro_fusion.r_w_encoders", "gyro_fusion.r_w_encoders",
        "variance of the encoder turn rate, (rad/s)²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_w_encoders; }));
    s.push_back(real(
        "gyro_fusion.r_w_gyro", "gyro_fusion.r_w_gyro", "variance of the gyro rate, (rad/s)²",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.r_w_gyro; }));
    s.push_back(boolean(
        "gyro_fusion.use_gyro", "gyro_fusion.use_gyro", "false: encoders (and accelerometers) only",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.use_gyro; }));
    s.push_back(boolean(
        "gyro_fusion.use_accelerometers", "gyro_fusion.use_accelerometers",
        "false: predict at constant velocity",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.use_accelerometers; }));
    s.push_back(real(
        "gyro_fusion.encoder_gate_probability", "gyro_fusion.encoder_gate_probability",
        "slip gate: reject the encoders' (v, ω) when their NIS against the gyro-corrected state "
        "exceeds the χ²(2) quantile at this probability; 0: off",
        [](auto& c) -> auto& { return c.lesson.gyro_fusion.encoder_gate_probability; }));

    s.push_back(real(
        "compass.k_d", "compass.k_d", "eq. 5: translation error coefficient k_D, m per m",
        [](auto& c) -> auto& { return c.lesson.compass.k_d; }));
    s.push_back(real(
        "compass.k_dtheta", "compass.k_dtheta",
        "eq. 5: rotation error per distance k_Dθ, rad² per m",
        [](auto& c) -> auto& { return c.lesson.compass.k_dtheta; }));
    s.push_back(real(
        "compass.k_theta", "compass.k_theta", "eq. 5: rotation error per turn k_θ, rad² per rad",
        [](auto& c) -> auto& { return c.lesson.compass.k_theta; }));
    s.push_back(real(
        "compass.r_compass", "compass.r_compass", "variance of the compass heading, rad²",
        [](auto& c) -> auto& { return c.lesson.compass.r_compass; }));
    s.push_back(boolean(
        "compass.use_compass", "compass.use_compass", "false: odometry only (P still grows)",
        [](auto& c) -> auto& { return c.lesson.compass.use_compass; }));

    s.push_back(real(
        "calibration.gyro_offset", "calibration.gyro_offset", "raw gyro value at rest, counts",
        [](auto& c) -> auto& { return c.lesson.calibration.gyro_offset; }));
    s.push_back(real(
        "calibration.gyro_counts_per_dps", "calibration.gyro_counts_per_dps", "gyro counts per °/s",
        [](auto& c) -> auto& { return c.lesson.calibration.gyro_counts_per_dps; }));
    s.push_back(real(
        "calibration.accel_counts_per_g", "calibration.accel_counts_per_g",
        "accelerometer counts per g",
        [](auto& c) -> auto& { return c.lesson.calibration.accel_counts_per_g; }));
    s.push_back(boolean(
        "calibration.remove_accel_bias", "calibration.remove_accel_bias",
        "remove the accelerometers' bias before use, estimated from the run's readings and "
        "encoders; false: use the readings as they are",
        [](auto& c) -> auto& { return c.lesson.calibration.remove_accel_bias; }));
}

// The simulated sensors of the further lessons (off unless enabled) and the displacement
// event; validation names them "simulator.<sensor>.<name>".
void add_simulated_sensor_settings(std::vector<Setting>& s) {
    const auto sim_real = [&s](const std::string& key, std::string help, auto access) {
        s.push_back(real(key, "simulator." + key, std::move(help), access));
    };
    const auto sim_bool = [&s](const std::string& key, std::string help, auto access) {
        s.push_back(boolean(key, "simulator." + key, std::move(help), access));
    };
    sim_bool(
        "beacon_scanner.enabled", "simulate the 360° bearing-only beacon scanner",
        [](auto& c) -> auto& { return c.physical.beacon_scanner.enabled; });
    sim_real(
        "beacon_scanner.detection_probability",
        "probability of seeing each beacon in line of sight per scan, 0 … 1",
        [](auto& c) -> auto& { return c.physical.beacon_scanner.detection_probability; });
    sim_real(
        "beacon_scanner.bearing_noise", "σ of each bearing, rad",
        [](auto& c) -> auto& { return c.physical.beacon_scanner.bearing_noise; });
    sim_real(
        "beacon_scanner.period", "s between scans",
        [](auto& c) -> auto& { return c.physical.beacon_scanner.period; });
    sim_bool(
        "gyro.enabled", "simulate the single-axis gyroscope",
        [](auto& c) -> auto& { return c.physical.gyro.enabled; });
    sim_real(
        "gyro.offset", "raw value at rest, counts",
        [](auto& c) -> auto& { return c.physical.gyro.offset; });
    sim_real(
        "gyro.noise", "σ of the gyro's white noise, counts",
        [](auto& c) -> auto& { return c.physical.gyro.noise; });
    sim_real(
        "gyro.bias_sigma", "σ of the gyro bias drawn at the start, counts",
        [](auto& c) -> auto& { return c.physical.gyro.bias_sigma; });
    sim_real(
        "gyro.bias_drift", "random walk of the gyro bias, counts/√s",
        [](auto& c) -> auto& { return c.physical.gyro.bias_drift; });
    sim_bool(
        "accelerometers.enabled", "simulate the two accelerometers over the wheels",
        [](auto& c) -> auto& { return c.physical.accelerometers.enabled; });
    sim_real(
        "accelerometers.noise", "σ of each axis's white noise, counts",
        [](auto& c) -> auto& { return c.physical.accelerometers.noise; });
    sim_real(
        "accelerometers.bias_sigma", "σ of each axis's constant bias, counts",
        [](auto& c) -> auto& { return c.physical.accelerometers.bias_sigma; });
    sim_bool(
        "compass_sensor.enabled", "simulate the magnetic compass",
        [](auto& c) -> auto& { return c.physical.compass.enabled; });
    sim_real(
        "compass_sensor.noise_deg", "σ of the compass noise before 1° rounding, °",
        [](auto& c) -> auto& { return c.physical.compass.noise_deg; });
    sim_bool(
        "displacement.enabled", "move the robot suddenly once (the filter is not told)",
        [](auto& c) -> auto& { return c.simulator.displacement.enabled; });
    sim_real(
        "displacement.time", "simulated time of the displacement, s",
        [](auto& c) -> auto& { return c.simulator.displacement.time; });
    sim_real(
        "displacement.dx", "displacement along the world x axis, m",
        [](auto& c) -> auto& { return c.simulator.displacement.dx; });
    sim_real(
        "displacement.dy", "displacement along the world y axis, m",
        [](auto& c) -> auto& { return c.simulator.displacement.dy; });
    s.push_back(degrees(
        "displacement.dtheta_deg", "simulator.displacement.dtheta", "turn of the displacement, °",
        [](auto& c) -> auto& { return c.simulator.displacement.dtheta; }));
}

// A scanner's geometry and mount under `section` ("laser" for the filter's belief,
// "laser_scanner" for the simulated scanner), validated as "<field_prefix>.geometry.*" and
// "<field_prefix>.mount.*".
template <class Access>
void add_scanner_geometry(std::vector<Setting>& s, const std::string& section,
                          const std::string& field_prefix, Access scanner) {
    const std::string k = section + ".";
    const std::string g = field_prefix + ".geometry.";
    const std::string m = field_prefix + ".mount.";
    s.push_back(whole(
        k + "beam_count", g + "beam_count",
        "beams per scan (1 … 1024; URG-04LX: 682)", [scanner](auto& c) -> auto& {
            return scanner(c).geometry.beam_count;
        }));
    s.push_back(degrees(
        k + "angle_min_deg", g + "angle_min",
        "direction of the first beam, ° counter-clockwise from the scanner's forward axis",
        [scanner](auto& c) -> auto& { return scanner(c).geometry.angle_min; }));
    s.push_back(degrees(
        k + "angle_increment_deg", g + "angle_increment",
        "angle between neighbouring beams, ° (field of view = beam_count · increment)",
        [scanner](auto& c) -> auto& { return scanner(c).geometry.angle_increment; }));
    s.push_back(real(
        k + "range_min", g + "range_min",
        "shorter readings are errors, m", [scanner](auto& c) -> auto& {
            return scanner(c).geometry.range_min;
        }));
    s.push_back(real(
        k + "range_max", g + "range_max",
        "longest reading the scanner reports, m", [scanner](auto& c) -> auto& {
            return scanner(c).geometry.range_max;
        }));
    s.push_back(real(
        k + "mount_x", m + "x",
        "scanner position ahead of the axle centre, m", [scanner](auto& c) -> auto& {
            return scanner(c).mount.x;
        }));
    s.push_back(real(
        k + "mount_y", m + "y",
        "scanner position left of the centre line, m", [scanner](auto& c) -> auto& {
            return scanner(c).mount.y;
        }));
    s.push_back(degrees(
        k + "mount_heading_deg", m + "theta",
        "scanner's forward axis relative to the robot's, °", [scanner](auto& c) -> auto& {
            return scanner(c).mount.theta;
        }));
}

// [laser]: the laser scan-matching filter of paper 001 (validated as "lesson.laser.*").
void add_laser_settings(std::vector<Setting>& s) {
    const auto laser_real = [&s](const std::string& name, std::string help, auto access) {
        s.push_back(real("laser." + name, "lesson.laser." + name, std::move(help), access));
    };
    laser_real(
        "q_x_static", "eq. 13: Q of x added at every prediction, m²",
        [](auto& c) -> auto& { return c.lesson.laser.q_x_static; });
    laser_real(
        "q_y_static", "eq. 13: Q of y added at every prediction, m²",
        [](auto& c) -> auto& { return c.lesson.laser.q_y_static; });
    laser_real(
        "q_theta_static", "eq. 13: Q of θ added at every prediction, rad²",
        [](auto& c) -> auto& { return c.lesson.laser.q_theta_static; });
    laser_real(
        "q_x_dynamic", "eq. 13: Q of x per metre of odometry increment |Δx|, m²/m",
        [](auto& c) -> auto& { return c.lesson.laser.q_x_dynamic; });
    laser_real(
        "q_y_dynamic", "eq. 13: Q of y per metre of odometry increment |Δy|, m²/m",
        [](auto& c) -> auto& { return c.lesson.laser.q_y_dynamic; });
    laser_real(
        "q_theta_dynamic", "eq. 13: Q of θ per radian of odometry increment |Δθ|, rad²/rad",
        [](auto& c) -> auto& { return c.lesson.laser.q_theta_dynamic; });
    laser_real(
        "r_x", "eq. 16: R of the ICP pose observation's x, m²",
        [](auto& c) -> auto& { return c.lesson.laser.r_x; });
    laser_real(
        "r_y", "eq. 16: R of the ICP pose observation's y, m²",
        [](auto& c) -> auto& { return c.lesson.laser.r_y; });
    laser_real(
        "r_theta", "eq. 16: R of the ICP pose observation's θ, rad²",
        [](auto& c) -> auto& { return c.lesson.laser.r_theta; });

    const auto icp_real = [&s](const std::string& name, std::string help, auto access) {
        s.push_back(real("laser.icp_" + name, "lesson.laser.icp." + name, std::move(help), access));
    };
    s.push_back(choice(
        "laser.icp_metric", "lesson.laser.icp.metric",
        "ICP error: point_to_point or point_to_line (distance to the map's surface)",
        {IcpMetric::PointToPoint, IcpMetric::PointToLine}, icp_metric_from_string,
        [](auto& c) -> auto& { return c.lesson.laser.icp.metric; }));
    s.push_back(whole(
        "laser.icp_max_iterations", "lesson.laser.icp.max_iterations",
        "ICP gives up (not converged) after this many iterations",
        [](auto& c) -> auto& { return c.lesson.laser.icp.max_iterations; }));
    icp_real(
        "max_correspondence_distance",
        "ICP: a scan point farther than this from the expected scan is an outlier, m",
        [](auto& c) -> auto& { return c.lesson.laser.icp.max_correspondence_distance; });
    icp_real(
        "trim_fraction", "ICP: fraction of the worst pairs dropped each iteration, 0 … 0.9",
        [](auto& c) -> auto& { return c.lesson.laser.icp.trim_fraction; });
    icp_real(
        "translation_epsilon", "ICP converged when a step moves less than this, m …",
        [](auto& c) -> auto& { return c.lesson.laser.icp.translation_epsilon; });
    icp_real(
        "rotation_epsilon", "… and turns less than this, rad",
        [](auto& c) -> auto& { return c.lesson.laser.icp.rotation_epsilon; });

    s.push_back(whole(
        "laser.min_matched_points", "lesson.laser.min_matched_points",
        "mismatch gate: a match with fewer inlier points is not used (prediction only; the "
        "paper names this condition, §III-B, but gives no number)",
        [](auto& c) -> auto& { return c.lesson.laser.min_matched_points; }));
    s.push_back(boolean(
        "laser.kidnap_recovery", "lesson.laser.kidnap_recovery",
        "after many mismatches in a row, inflate P and tighten ICP (paper §IV-B)",
        [](auto& c) -> auto& { return c.lesson.laser.kidnap_recovery; }));
    s.push_back(whole(
        "laser.recovery_after_mismatches", "lesson.laser.recovery_after_mismatches",
        "consecutive mismatches that start the recovery",
        [](auto& c) -> auto& { return c.lesson.laser.recovery_after_mismatches; }));
    laser_real(
        "recovery_covariance_factor", "recovery: P is multiplied by this",
        [](auto& c) -> auto& { return c.lesson.laser.recovery_covariance_factor; });
    laser_real(
        "recovery_correspondence_factor",
        "recovery: ICP's correspondence distance is multiplied by this (≤ 1: stricter)",
        [](auto& c) -> auto& { return c.lesson.laser.recovery_correspondence_factor; });

    add_scanner_geometry(
        s, "laser", "lesson.laser", [](auto& c) -> auto& { return c.lesson.laser; });
    // The field is the one the loop's validate() uses when the map is missing.
    s.push_back(file("laser.map", "map",
                     "the filter's map: a built-in map (standard_arena, office) or a map YAML "
                     "file; empty: the world's map (a different one is an outdated map)",
                     &RunConfig::laser_map_file, built_in_map_names));
}

// [laser_scanner] and [kidnap]: the simulated laser rangefinder and the kidnapping event.
void add_laser_simulation_settings(std::vector<Setting>& s) {
    const auto scanner_real = [&s](const std::string& name, std::string help, auto access) {
        s.push_back(real("laser_scanner." + name, "simulator.laser_scanner." + name,
                         std::move(help), access));
    };
    s.push_back(boolean(
        "laser_scanner.enabled", "simulator.laser_scanner.enabled",
        "simulate the laser rangefinder (URG-04LX-like)",
        [](auto& c) -> auto& { return c.physical.laser_scanner.enabled; }));
    add_scanner_geometry(
        s, "laser_scanner", "simulator.laser_scanner",
        [](auto& c) -> auto& { return c.physical.laser_scanner; });
    scanner_real(
        "scan_period", "s between scans (a whole number of control periods)",
        [](auto& c) -> auto& { return c.physical.laser_scanner.scan_period; });
    scanner_real(
        "sigma_near", "σ of the range noise up to noise_knee, m",
        [](auto& c) -> auto& { return c.physical.laser_scanner.sigma_near; });
    scanner_real(
        "noise_knee", "range beyond which σ = sigma_relative · range, m",
        [](auto& c) -> auto& { return c.physical.laser_scanner.noise_knee; });
    scanner_real(
        "sigma_relative", "σ of the range noise beyond noise_knee, as a fraction of the range",
        [](auto& c) -> auto& { return c.physical.laser_scanner.sigma_relative; });
    scanner_real(
        "dropout_probability", "probability that a beam returns no measurement, 0 … 1",
        [](auto& c) -> auto& { return c.physical.laser_scanner.dropout_probability; });

    s.push_back(boolean(
        "kidnap.enabled", "simulator.kidnap.enabled",
        "lift the robot once and put it down elsewhere (the filter is not told)",
        [](auto& c) -> auto& { return c.simulator.kidnap.enabled; }));
    s.push_back(real(
        "kidnap.time", "simulator.kidnap.time", "simulated time of the kidnapping, s",
        [](auto& c) -> auto& { return c.simulator.kidnap.time; }));
    s.push_back(real(
        "kidnap.x", "simulator.kidnap.pose.x", "where the robot is put down: x, m",
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.x; }));
    s.push_back(real(
        "kidnap.y", "simulator.kidnap.pose.y", "where the robot is put down: y, m",
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.y; }));
    s.push_back(degrees(
        "kidnap.heading_deg", "simulator.kidnap.pose.theta", "heading it is put down with, °",
        [](auto& c) -> auto& { return c.simulator.kidnap.pose.theta; }));
}

const char* routine_name(RoutineSpec::Kind kind) {
    switch (kind) {
        case RoutineSpec::Kind::Square:
            return "square";
        case RoutineSpec::Kind::Line:
            return "line";
        case RoutineSpec::Kind::Circle:
            return "circle";
        case RoutineSpec::Kind::Goto:
            return "goto";
        case RoutineSpec::Kind::Manual:
            return "manual";
        case RoutineSpec::Kind::Shuttle:
            return "shuttle";
        case RoutineSpec::Kind::Piecewise:
            return "piecewise";
        case RoutineSpec::Kind::Random:
            return "random";
        case RoutineSpec::Kind::Rectangle:
            return "rectangle";
    }
    return "square";
}

std::vector<Setting> make_settings() {
    std::vector<Setting> s;

    Setting seed{"seed",
                 "seed",
                 "seed of every random stream of the run (0 … 2^63−1)",
                 SettingType::Integer,
                 {},
                 {},
                 {},
                 {},
                 {}};
    seed.get = [](const RunConfig& c) -> SettingValue { return static_cast<std::int64_t>(c.seed); };
    seed.set = [](RunConfig& c, const SettingValue& v) {
        c.seed = static_cast<std::uint64_t>(std::get<std::int64_t>(v));
    };
    s.push_back(seed);
    Setting laps{
        "laps", "laps", "laps of the square path (1 … 1000)", SettingType::Integer, {}, {}, {},
        {},     {}};
    laps.get = [](const RunConfig& c) -> SettingValue { return std::int64_t{c.laps}; };
    laps.set = [](RunConfig& c, const SettingValue& v) {
        c.laps = static_cast<int>(std::get<std::int64_t>(v));
    };
    s.push_back(laps);
    s.push_back(real(
        "duration", "duration",
        "simulated seconds to run (a square or rectangle stops at its laps or here, whichever "
        "comes first); 0: 200 s per lap",
        [](auto& c) -> auto& { return c.duration; }));
    s.push_back(file("world", "world",
                     "world: a built-in world (standard_arena, office) or a world file "
                     "(relative to this file); empty: the standard arena",
                     &RunConfig::world_file, built_in_world_names));

    // [filter] — the EKF's noise model (paper: Q over [ε_d, ε_Δθ], R over [ε_ds1, ε_ds2]).
    s.push_back(real(
        "filter.q11", "filter.q11", "Q11: variance of ε_d per 50 ms period, m²",
        [](auto& c) -> auto& { return c.filter.q11; }));
    s.push_back(real(
        "filter.q22", "filter.q22", "Q22: variance of ε_Δθ per period, rad²",
        [](auto& c) -> auto& { return c.filter.q22; }));
    s.push_back(real(
        "filter.r11", "filter.r11", "R11: variance of the front IR distance, m²",
        [](auto& c) -> auto& { return c.filter.r11; }));
    s.push_back(real(
        "filter.r22", "filter.r22", "R22: variance of the rear IR distance, m²",
        [](auto& c) -> auto& { return c.filter.r22; }));
    s.push_back(boolean(
        "filter.wall_updates", "filter.wall_updates",
        "false: odometry only (walls are associated but never used)",
        [](auto& c) -> auto& { return c.filter.wall_updates; }));
    s.push_back(boolean(
        "filter.gate", "filter.gate_enabled", "reject updates whose NIS exceeds the χ²(2) gate",
        [](auto& c) -> auto& { return c.filter.gate_enabled; }));
    s.push_back(real(
        "filter.gate_probability", "filter.gate_probability",
        "probability of the Mahalanobis gate, in (0, 1)",
        [](auto& c) -> auto& { return c.filter.gate_probability; }));
    s.push_back(real(
        "filter.min_variance", "filter.min_variance", "floor on every variance of P",
        [](auto& c) -> auto& { return c.filter.limits.min_variance; }));
    s.push_back(real(
        "filter.max_variance", "filter.max_variance", "ceiling on every variance of P",
        [](auto& c) -> auto& { return c.filter.limits.max_variance; }));

    add_lesson_filter_settings(s);
    add_laser_settings(s);
    add_simulated_sensor_settings(s);
    add_laser_simulation_settings(s);

    // [initial] — the belief the filter starts from.
    s.push_back(pose_part("initial.x", "initial.x", "believed start x, m (default: world start)",
                          &RunConfig::initial_pose, &PoseOverride::x));
    s.push_back(pose_part("initial.y", "initial.y", "believed start y, m (default: world start)",
                          &RunConfig::initial_pose, &PoseOverride::y));
    s.push_back(pose_part("initial.heading_deg", "initial.theta",
                          "believed start heading, ° (default: world start)",
                          &RunConfig::initial_pose, &PoseOverride::theta, kPi / 180.0));
    s.push_back(real(
        "initial.var_x", "initial.var_x", "P0: variance of x, m²",
        [](auto& c) -> auto& { return c.initial.var_x; }));
    s.push_back(real(
        "initial.var_y", "initial.var_y", "P0: variance of y, m²",
        [](auto& c) -> auto& { return c.initial.var_y; }));
    s.push_back(real(
        "initial.var_theta", "initial.var_theta", "P0: variance of θ, rad²",
        [](auto& c) -> auto& { return c.initial.var_theta; }));

    // [control] — the path-control routine.
    Setting routine{"control.routine",
                    "control.routine",
                    "square, line, circle, goto, manual, shuttle (line back and forth), "
                    "piecewise (corners with stops), random (random places) or rectangle (laps of "
                    "rectangle_size from rectangle_corner)",
                    SettingType::Choice,
                    {"square", "line", "circle", "goto", "manual", "shuttle", "piecewise", "random",
                     "rectangle"},
                    {},
                    {},
                    {},
                    {}};
    routine.get = [](const RunConfig& c) -> SettingValue {
        return std::string(routine_name(c.routine.kind));
    };
    routine.set = [](RunConfig& c, const SettingValue& v) {
        const std::string& name = std::get<std::string>(v);
        for (auto kind :
             {RoutineSpec::Kind::Square, RoutineSpec::Kind::Line, RoutineSpec::Kind::Circle,
              RoutineSpec::Kind::Goto, RoutineSpec::Kind::Manual, RoutineSpec::Kind::Shuttle,
              RoutineSpec::Kind::Piecewise, RoutineSpec::Kind::Random,
              RoutineSpec::Kind::Rectangle}) {
            if (name == routine_name(kind)) {
                c.routine.kind = kind;
            }
        }
    };
    s.push_back(routine);
    s.push_back(real(
        "control.pause", "controller.pause",
        "shuttle/piecewise/random: seconds stopped at each waypoint",
        [](auto& c) -> auto& { return c.routine.pause; }));
    Setting random_points{"control.random_points",
                          "control.random_points",
                          "random: how many random places to visit (1 … 100)",
                          SettingType::Integer,
                          {},
                          {},
                          {},
                          {},
                          {}};
    random_points.get = [](const RunConfig& c) -> SettingValue {
        return std::int64_t{c.routine.random_points};
    };
    random_points.set = [](RunConfig& c, const SettingValue& v) {
        c.routine.random_points = static_cast<int>(std::get<std::int64_t>(v));
    };
    s.push_back(random_points);
    s.push_back(real(
        "control.v_ref", "motion.v_ref", "V_ref: reference speed, m/s",
        [](auto& c) -> auto& { return c.motion.v_ref; }));
    s.push_back(real(
        "control.w_ref", "motion.w_ref", "W_ref: largest turn rate, rad/s",
        [](auto& c) -> auto& { return c.motion.w_ref; }));
    s.push_back(real(
        "control.heading_gain", "gains.heading_gain", "k_θ: W = k_θ·heading error, 1/s",
        [](auto& c) -> auto& { return c.gains.heading_gain; }));
    s.push_back(real(
        "control.cross_track_gain", "gains.cross_track_gain",
        "k_e: approach angle atan(k_e·offset), 1/m",
        [](auto& c) -> auto& { return c.gains.cross_track_gain; }));
    s.push_back(real(
        "control.distance_gain", "gains.distance_gain", "k_ρ: GoXYTheta slows to k_ρ·distance, 1/s",
        [](auto& c) -> auto& { return c.gains.distance_gain; }));
    s.push_back(real(
        "control.position_tolerance", "gains.position_tolerance", "GoXYTheta arrival distance, m",
        [](auto& c) -> auto& { return c.gains.position_tolerance; }));
    s.push_back(degrees(
        "control.heading_tolerance_deg", "gains.heading_tolerance",
        "GoXYTheta final heading tolerance, °",
        [](auto& c) -> auto& { return c.gains.heading_tolerance; }));
    s.push_back(real(
        "control.max_wheel_speed", "max_wheel_speed", "wheel speed limit, m/s",
        [](auto& c) -> auto& { return c.max_wheel_speed; }));
    s.push_back(point(
        "control.line_from", "controller.from", "line: first point [x, y], m",
        [](auto& c) -> auto& { return c.routine.line_from; }));
    s.push_back(point(
        "control.line_to", "controller.to", "line: second point [x, y], m",
        [](auto& c) -> auto& { return c.routine.line_to; }));
    s.push_back(point(
        "control.circle_centre", "controller.centre", "circle: centre [x, y], m",
        [](auto& c) -> auto& { return c.routine.circle_centre; }));
    s.push_back(real(
        "control.circle_radius", "controller.radius", "circle: radius, m",
        [](auto& c) -> auto& { return c.routine.circle_radius; }));
    s.push_back(boolean(
        "control.circle_clockwise", "controller.clockwise", "circle: true for clockwise",
        [](auto& c) -> auto& { return c.routine.circle_clockwise; }));
    s.push_back(point(
        "control.rectangle_corner", "controller.rectangle_corner",
        "rectangle: lower-left corner [x, y] where each lap starts, heading +x, m",
        [](auto& c) -> auto& { return c.routine.rectangle_corner; }));
    s.push_back(point(
        "control.rectangle_size", "controller.rectangle_size",
        "rectangle: [width along x, height along y], m (driven counter-clockwise)",
        [](auto& c) -> auto& { return c.routine.rectangle_size; }));
    s.push_back(real(
        "control.goto_x", "controller.target.x", "goto: target x, m",
        [](auto& c) -> auto& { return c.routine.goto_target.x; }));
    s.push_back(real(
        "control.goto_y", "controller.target.y", "goto: target y, m",
        [](auto& c) -> auto& { return c.routine.goto_target.y; }));
    s.push_back(degrees(
        "control.goto_heading_deg", "controller.target.theta", "goto: final heading, °",
        [](auto& c) -> auto& { return c.routine.goto_target.theta; }));

    // [robot] — the robot as the filter assumes it is built.
    s.push_back(real(
        "robot.wheel_diameter", "robot.wheel_diameter", "wheel diameter, m",
        [](auto& c) -> auto& { return c.robot.wheel_diameter; }));
    s.push_back(real(
        "robot.wheel_base", "odometry.wheel_base", "b: distance between the wheels, m",
        [](auto& c) -> auto& { return c.robot.wheel_base; }));
    s.push_back(real(
        "robot.counts_per_turn", "robot.counts_per_turn", "encoder counts per wheel turn",
        [](auto& c) -> auto& { return c.robot.counts_per_turn; }));
    s.push_back(real(
        "robot.codo_right", "odometry.codo_right",
        "Codo1: right wheel counts per metre; 0: from the diameter",
        [](auto& c) -> auto& { return c.robot.codo_right; }));
    s.push_back(real(
        "robot.codo_left", "odometry.codo_left",
        "Codo2: left wheel counts per metre; 0: from the diameter",
        [](auto& c) -> auto& { return c.robot.codo_left; }));
    s.push_back(real(
        "robot.ir_front", "ir_mount.front_longitudinal", "front IR sensor ahead of the axle, m",
        [](auto& c) -> auto& { return c.robot.ir_mount.front_longitudinal; }));
    s.push_back(real(
        "robot.ir_rear", "ir_mount.rear_longitudinal",
        "rear IR sensor ahead of the axle (negative: behind), m",
        [](auto& c) -> auto& { return c.robot.ir_mount.rear_longitudinal; }));
    s.push_back(real(
        "robot.ir_lateral", "ir_mount.lateral_offset",
        "IR sensors' distance from the centre line (right side), m",
        [](auto& c) -> auto& { return c.robot.ir_mount.lateral_offset; }));

    // [ir_curve] — eq. 2, D = a·(C_M/(A + C_R) − b), and its trusted range.
    s.push_back(real(
        "ir_curve.a", "ir_curve.a", "a: scale of the fit, m per fit unit",
        [](auto& c) -> auto& { return c.ir_curve.a; }));
    s.push_back(real(
        "ir_curve.c_m", "ir_curve.c_m", "C_M: constant of multiplication",
        [](auto& c) -> auto& { return c.ir_curve.c_m; }));
    s.push_back(real(
        "ir_curve.c_r", "ir_curve.c_r", "C_R: constant of linearisation",
        [](auto& c) -> auto& { return c.ir_curve.c_r; }));
    s.push_back(real(
        "ir_curve.b", "ir_curve.b", "b: offset of the fit, fit units",
        [](auto& c) -> auto& { return c.ir_curve.b; }));
    s.push_back(real(
        "ir_curve.min_range", "ir_curve.min_range", "closest trusted reading, m",
        [](auto& c) -> auto& { return c.ir_curve.min_range; }));
    s.push_back(real(
        "ir_curve.max_range", "ir_curve.max_range", "farthest trusted reading, m",
        [](auto& c) -> auto& { return c.ir_curve.max_range; }));
    s.push_back(real(
        "ir_curve.peak_distance", "ir_curve.peak_distance",
        "the sensor's output peaks here and folds back below, m",
        [](auto& c) -> auto& { return c.ir_curve.peak_distance; }));
    s.push_back(real(
        "ir_curve.contact_adc", "ir_curve.contact_adc",
        "A/D value with the target touching the sensor",
        [](auto& c) -> auto& { return c.ir_curve.contact_adc; }));
    // Each sensor's own curve (calibrated per unit); unset parameters are the shared ones.
    add_sensor_curve_settings(s, kFrontSensor);
    add_sensor_curve_settings(s, kRearSensor);

    // [association] — Fig. 4.
    s.push_back(real(
        "association.segment_margin", "association.segment_margin",
        "predicted beams may miss a wall's end by this much, m",
        [](auto& c) -> auto& { return c.association.segment_margin; }));
    s.push_back(real(
        "association.range_margin", "association.range_margin",
        "predicted beams may exceed the IR range by this much, m",
        [](auto& c) -> auto& { return c.association.range_margin; }));
    s.push_back(degrees(
        "association.max_incidence_deg", "association.max_incidence",
        "walls seen more obliquely are not used, °",
        [](auto& c) -> auto& { return c.association.max_incidence; }));
    s.push_back(degrees(
        "association.max_angle_error_deg", "association.max_angle_error",
        "largest accepted ObsAng error, °",
        [](auto& c) -> auto& { return c.association.max_angle_error; }));
    s.push_back(real(
        "association.max_distance_error", "association.max_distance_error",
        "largest accepted wall distance error, m",
        [](auto& c) -> auto& { return c.association.max_distance_error; }));
    s.push_back(choice(
        "association.gate", "association.gate",
        "which test takes a wall: fixed (the paper's: the angle and distance errors under the "
        "limits above) or mahalanobis (νᵀS⁻¹ν with S = HPHᵀ + R under the χ²(2) quantile)",
        {AssociationGate::Fixed, AssociationGate::Mahalanobis}, association_gate_from_string,
        [](auto& c) -> auto& { return c.association.gate; }));
    s.push_back(real(
        "association.gate_probability", "association.gate_probability",
        "probability of the Mahalanobis association gate, in (0, 1)",
        [](auto& c) -> auto& { return c.association.gate_probability; }));

    // [simulator] — the simulated robot's errors, noise, body and motors.
    const auto physical = [&s](std::string name, std::string help, auto access) {
        s.push_back(
            real("simulator." + name, "simulator." + name, std::move(help), std::move(access)));
    };
    physical(
        "wheel_diameter_ratio", "E_d = D_right/D_left of the real wheels",
        [](auto& c) -> auto& { return c.physical.wheel_diameter_ratio; });
    physical(
        "wheel_base_ratio", "E_b = real / nominal wheel base",
        [](auto& c) -> auto& { return c.physical.wheel_base_ratio; });
    physical(
        "slip_noise", "random wheel slip, σ² = slip_noise²·distance, m^½",
        [](auto& c) -> auto& { return c.physical.slip_noise; });
    physical(
        "ir_noise", "σ of Gaussian noise on each IR distance, m",
        [](auto& c) -> auto& { return c.physical.ir_noise; });
    s.push_back(choice(
        "simulator.ir_model", "simulator.ir_model",
        "the IR sensors: ideal (the filter's curve, noise constant in metres) or realistic "
        "(each sensor its own curve from the seed, noise on the output)",
        {sim::IrSensorModel::Ideal, sim::IrSensorModel::Realistic},
        sim::ir_sensor_model_from_string, [](auto& c) -> auto& { return c.physical.ir_model; }));
    physical(
        "ir_noise_distance", "realistic IR: the distance at which the noise is ir_noise, m",
        [](auto& c) -> auto& { return c.physical.ir_noise_distance; });
    physical(
        "ir_gain_spread", "realistic IR: σ of each sensor's output gain (data sheet: 0.044)",
        [](auto& c) -> auto& { return c.physical.ir_gain_spread; });
    physical(
        "ir_offset_spread", "realistic IR: σ of each sensor's output offset, A/D counts",
        [](auto& c) -> auto& { return c.physical.ir_offset_spread; });
    physical(
        "ir_period", "IR update period (value held in between), s",
        [](auto& c) -> auto& { return c.physical.ir_period; });
    physical(
        "ir_ray_length", "the IR sensors see nothing beyond this, m",
        [](auto& c) -> auto& { return c.physical.ir_ray_length; });
    physical(
        "motor_time_constant", "first-order motor response, s",
        [](auto& c) -> auto& { return c.physical.motor_time_constant; });
    physical(
        "max_motor_rpm", "motor no-load speed, rpm",
        [](auto& c) -> auto& { return c.physical.max_motor_rpm; });
    physical(
        "mass", "robot mass, kg", [](auto& c) -> auto& { return c.physical.mass; });
    physical(
        "traction", "tyre friction coefficient μ",
        [](auto& c) -> auto& { return c.physical.traction; });
    physical(
        "wheel_load", "share of the weight on the driven wheels",
        [](auto& c) -> auto& { return c.physical.wheel_load; });
    physical(
        "chassis_front", "chassis extent ahead of the axle, m",
        [](auto& c) -> auto& { return c.physical.chassis_front; });
    physical(
        "chassis_rear", "chassis extent behind the axle, m",
        [](auto& c) -> auto& { return c.physical.chassis_rear; });
    physical(
        "chassis_half_width", "half the chassis width with wheels, m",
        [](auto& c) -> auto& { return c.physical.chassis_half_width; });
    physical(
        "physics_rate", "physics steps per second, Hz",
        [](auto& c) -> auto& { return c.simulator.physics_rate; });
    physical(
        "control_period", "control period of the loop, s",
        [](auto& c) -> auto& { return c.simulator.control_period; });
    s.push_back(pose_part("simulator.start_x", "simulator.start_x",
                          "where the robot really starts, m (default: world start)",
                          &RunConfig::true_start, &PoseOverride::x));
    s.push_back(pose_part("simulator.start_y", "simulator.start_y",
                          "real start y, m (default: world start)", &RunConfig::true_start,
                          &PoseOverride::y));
    s.push_back(pose_part("simulator.start_heading_deg", "simulator.start_heading",
                          "real start heading, ° (default: world start)", &RunConfig::true_start,
                          &PoseOverride::theta, kPi / 180.0));
    return s;
}

}  // namespace

std::string Setting::section() const {
    const auto dot = key.find('.');
    return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

std::string Setting::name() const {
    const auto dot = key.find('.');
    return dot == std::string::npos ? key : key.substr(dot + 1);
}

const std::vector<Setting>& run_settings() {
    static const std::vector<Setting> settings = make_settings();
    return settings;
}

const Setting* find_setting_by_key(const std::string& key) {
    for (const Setting& setting : run_settings()) {
        if (setting.key == key) {
            return &setting;
        }
    }
    return nullptr;
}

const Setting* find_setting_by_field(const std::string& field) {
    for (const Setting& setting : run_settings()) {
        if (setting.field == field) {
            return &setting;
        }
    }
    return nullptr;
}

std::string format_setting_value(const SettingValue& value) {
    const auto number = [](double x) {
        if (!std::isfinite(x)) {
            return std::string(std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"));
        }
        char buffer[32];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
        std::string text(buffer, result.ptr);
        // TOML needs a decimal point or an exponent to read a float back as a float.
        if (text.find_first_of(".eE") == std::string::npos) {
            text += ".0";
        }
        return text;
    };
    struct Formatter {
        decltype(number)& format;
        std::string operator()(double x) const { return format(x); }
        std::string operator()(std::int64_t x) const { return std::to_string(x); }
        std::string operator()(bool x) const { return x ? "true" : "false"; }
        std::string operator()(const std::string& x) const {
            std::string quoted = "\"";
            for (char ch : x) {
                if (ch == '"' || ch == '\\') {
                    quoted += '\\';
                }
                quoted += ch;
            }
            return quoted + "\"";
        }
        std::string operator()(const Vector2& x) const {
            return "[" + format(x.x()) + ", " + format(x.y()) + "]";
        }
    };
    return std::visit(Formatter{number}, value);
}

}  // namespace legofeup::lessons
