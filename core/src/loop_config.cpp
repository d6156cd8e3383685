#include "legofeup/core/loop_config.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <type_traits>
#include <utility>
#include <variant>

#include "legofeup/core/free_space.hpp"

namespace legofeup {
namespace {

void check_ir_curve(ConfigChecker& check, const SharpIrCurve& curve, const std::string& prefix) {
    const std::string p = prefix + ".";
    check.positive(p + "a", curve.a, 1.0);
    check.positive(p + "c_m", curve.c_m, 1e7);
    check.finite(p + "c_r", curve.c_r);
    check.finite(p + "b", curve.b);
    check.positive(p + "min_range", curve.min_range, 10.0);
    check.require(curve.max_range > curve.min_range && curve.max_range <= 10.0, p + "max_range",
                  curve.max_range, "must be greater than " + p + "min_range and at most 10 m");
    check.require(curve.peak_distance > 0.0 && curve.peak_distance <= curve.min_range,
                  p + "peak_distance", curve.peak_distance,
                  "must be greater than 0 and at most " + p + "min_range");
    check.in_range(p + "adc_max", curve.adc_max, 1.0, 65535.0);
    check.in_range(p + "contact_adc", curve.contact_adc, 0.0, curve.adc_max);
    // The fit must give positive, decreasing distances that the A/D can represent over the
    // trusted range: its denominator D/a + b stays positive down to the peak distance.
    check.require(curve.peak_distance / curve.a + curve.b > 0.0, p + "b", curve.b,
                  "makes the fitted curve D = a·(C_M/(A + C_R) − b) non-monotonic in range");
    const double near_adc = adc_from_distance(curve.min_range, curve);
    const double far_adc = adc_from_distance(curve.max_range, curve);
    check.require(near_adc <= curve.adc_max && far_adc >= 0.0, p + "c_m", curve.c_m,
                  "puts the trusted range outside the A/D scale 0…adc_max");
}

void check_ir_mount(ConfigChecker& check, const IrMount& mount, const std::string& prefix) {
    const std::string p = prefix + ".";
    check.in_range(p + "front_longitudinal", mount.front_longitudinal, -1.0, 1.0);
    check.in_range(p + "rear_longitudinal", mount.rear_longitudinal, -1.0, 1.0);
    check.require(mount.separation() > 1e-3, p + "front_longitudinal", mount.front_longitudinal,
                  "the front sensor must be at least 1 mm ahead of the rear one");
    check.in_range(p + "lateral_offset", mount.lateral_offset, -1.0, 1.0);
}

void check_controller(ConfigChecker& check, const Controller& controller) {
    std::visit(
        [&](const auto& routine) {
            using Routine = std::decay_t<decltype(routine)>;
            if constexpr (std::is_same_v<Routine, GoXYTheta>) {
                check.finite("controller.target.x", routine.target().x);
                check.finite("controller.target.y", routine.target().y);
                check.finite("controller.target.theta", routine.target().theta);
            } else if constexpr (std::is_same_v<Routine, FollowLine>) {
                check.require((routine.to() - routine.from()).norm() > 1e-6, "controller.to",
                              routine.to().x(), "must differ from controller.from");
            } else if constexpr (std::is_same_v<Routine, FollowCircle>) {
                check.positive("controller.radius", routine.radius(), 1e3);
            } else if constexpr (std::is_same_v<Routine, FollowPath>) {
                for (std::size_t i = 0; i < routine.segments().size(); ++i) {
                    const std::string field = "controller.path[" + std::to_string(i) + "]";
                    if (const auto* line = std::get_if<LineSegment>(&routine.segments()[i])) {
                        check.require((line->to - line->from).norm() > 1e-6, field + ".to",
                                      line->to.x(), "a line segment must have a length");
                    } else {
                        const auto& arc = std::get<ArcSegment>(routine.segments()[i]);
                        check.positive(field + ".radius", arc.radius, 1e3);
                        check.positive(field + ".sweep", arc.sweep, 1e3);
                    }
                }
            } else if constexpr (std::is_same_v<Routine, VisitWaypoints>) {
                check.require(!routine.waypoints().empty(), "controller.waypoints", 0.0,
                              "needs at least one waypoint");
                for (std::size_t i = 0; i < routine.waypoints().size(); ++i) {
                    const Vector2& point = routine.waypoints()[i];
                    check.require(point.allFinite(),
                                  "controller.waypoints[" + std::to_string(i) + "]",
                                  std::isfinite(point.x()) ? point.y() : point.x(),
                                  "a waypoint must be finite");
                }
                check.in_range("controller.pause", routine.pause(), 0.0, 600.0);
            }
        },
        controller);
}

void check_variance(ConfigChecker& check, const std::string& field, double value) {
    check.in_range(field, value, kMinUserVariance, kMaxUserVariance);
}

// The further lessons' filters (field names are the configuration file's keys).
void check_lesson_filters(ConfigChecker& check, const LessonFilters& lesson) {
    // The smallest sigma-point dimension is the pose's 3 (updates); n + κ must stay positive.
    check.in_range("filter.ukf_kappa", lesson.ukf.kappa, -2.9, 100.0);
    const ParticleFilterTuning& particles = lesson.particles;
    check.require(particles.particle_count >= 1 && particles.particle_count <= kMaxParticleCount,
                  "pf.particles", particles.particle_count,
                  "must be between 1 and " + std::to_string(kMaxParticleCount));
    check.in_range("pf.resample_threshold", particles.resample_threshold, 0.0, 1.0);
    check.require(particles.alpha_slow > 0.0 && particles.alpha_slow < 1.0, "pf.alpha_slow",
                  particles.alpha_slow, "must be strictly between 0 and 1");
    check.require(particles.alpha_fast > particles.alpha_slow && particles.alpha_fast <= 1.0,
                  "pf.alpha_fast", particles.alpha_fast,
                  "must be above pf.alpha_slow and at most 1 (the short-term average "
                  "follows the likelihood faster than the long-term one)");
    const OdometryAlphas& alphas = particles.motion_alphas;
    check.in_range("pf.alpha1", alphas.rotation_from_rotation, 0.0, 1.0);
    check.in_range("pf.alpha2", alphas.rotation_from_translation, 0.0, 1.0);
    check.in_range("pf.alpha3", alphas.translation_from_translation, 0.0, 1.0);
    check.in_range("pf.alpha4", alphas.translation_from_rotation, 0.0, 1.0);
    check.in_range("beacons.r_bearing", lesson.beacons.r_bearing, kMinUserVariance, 100.0);
    check.require(lesson.beacons.gate_probability > 0.0 && lesson.beacons.gate_probability < 1.0,
                  "beacons.gate_probability", lesson.beacons.gate_probability,
                  "must be strictly between 0 and 1");
    const WheelSpeedKfTuning& wheel = lesson.wheel_speed;
    check_variance(check, "wheel_speed_kf.q_angle", wheel.q_angle);
    check_variance(check, "wheel_speed_kf.q_rate", wheel.q_rate);
    check_variance(check, "wheel_speed_kf.r_right", wheel.r_right);
    check_variance(check, "wheel_speed_kf.r_left", wheel.r_left);
    check_variance(check, "wheel_speed_kf.p0", wheel.p0);
    const VelocityKfTuning& velocity = lesson.velocity;
    check_variance(check, "velocity_kf.q_v", velocity.q_v);
    check_variance(check, "velocity_kf.q_w", velocity.q_w);
    check_variance(check, "velocity_kf.r_v", velocity.r_v);
    check_variance(check, "velocity_kf.r_w", velocity.r_w);
    check_variance(check, "velocity_kf.p0", velocity.p0);
    const GyroFusionTuning& fusion = lesson.gyro_fusion;
    check_variance(check, "gyro_fusion.q_position", fusion.q_position);
    check_variance(check, "gyro_fusion.q_heading", fusion.q_heading);
    check_variance(check, "gyro_fusion.q_v", fusion.q_v);
    check_variance(check, "gyro_fusion.q_w", fusion.q_w);
    check_variance(check, "gyro_fusion.r_v_encoders", fusion.r_v_encoders);
    check_variance(check, "gyro_fusion.r_w_encoders", fusion.r_w_encoders);
    check_variance(check, "gyro_fusion.r_w_gyro", fusion.r_w_gyro);
    check.require(fusion.encoder_gate_probability >= 0.0 && fusion.encoder_gate_probability < 1.0,
                  "gyro_fusion.encoder_gate_probability", fusion.encoder_gate_probability,
                  "must be in [0, 1) (0 switches the slip gate off)");
    const CompassTuning& compass = lesson.compass;
    check.in_range("compass.k_d", compass.k_d, 0.0, 100.0);
    check.in_range("compass.k_dtheta", compass.k_dtheta, 0.0, 100.0);
    check.in_range("compass.k_theta", compass.k_theta, 0.0, 100.0);
    check_variance(check, "compass.r_compass", compass.r_compass);
    const ExtraSensorCalibration& calibration = lesson.calibration;
    check.in_range("calibration.gyro_offset", calibration.gyro_offset, 0.0, 1023.0);
    check.positive("calibration.gyro_counts_per_dps", calibration.gyro_counts_per_dps, 1000.0);
    check.positive("calibration.accel_counts_per_g", calibration.accel_counts_per_g, 1e5);
    check.in_range("calibration.gravity", calibration.gravity, 1.0, 100.0);
}

// Laser scan matching (paper 001), fields "lesson.laser.<name>". The static and dynamic
// parts of eq. 13's Q may each be 0 (no slip at rest, or no motion-dependent error): the
// filter's variance floor keeps P regular even when a whole row of Q is 0. The ICP and
// scanner geometry are checked by their own validate() (appended by the caller).
void check_laser(ConfigChecker& check, const LaserTuning& laser,
                 const std::shared_ptr<const OccupancyGrid>& map, bool in_use) {
    const std::string p = "lesson.laser.";
    for (const auto& [name, value] :
         {std::pair{"q_x_static", laser.q_x_static}, std::pair{"q_y_static", laser.q_y_static},
          std::pair{"q_theta_static", laser.q_theta_static},
          std::pair{"q_x_dynamic", laser.q_x_dynamic}, std::pair{"q_y_dynamic", laser.q_y_dynamic},
          std::pair{"q_theta_dynamic", laser.q_theta_dynamic}}) {
        check.in_range(p + name, value, 0.0, kMaxUserVariance);
    }
    check_variance(check, p + "r_x", laser.r_x);
    check_variance(check, p + "r_y", laser.r_y);
    check_variance(check, p + "r_theta", laser.r_theta);
    check.in_range(p + "min_matched_points", laser.min_matched_points, 0.0, kMaxScanBeams);
    check.in_range(p + "recovery_after_mismatches", laser.recovery_after_mismatches, 1.0, 1e6);
    check.positive(p + "recovery_covariance_factor", laser.recovery_covariance_factor, 1e6);
    check.positive(p + "recovery_correspondence_factor", laser.recovery_correspondence_factor, 1.0);
    check.in_range(p + "mount.x", laser.mount.x, -10.0, 10.0);
    check.in_range(p + "mount.y", laser.mount.y, -10.0, 10.0);
    check.in_range(p + "mount.theta", laser.mount.theta, -2.0 * kPi, 2.0 * kPi);
    if (in_use) {
        check.require(map != nullptr && !map->empty(), "map", 0.0,
                      "the laser localisation needs the filter's occupancy-grid map");
    }
}

void append(std::vector<ConfigIssue>& issues, std::vector<ConfigIssue> more) {
    issues.insert(issues.end(), std::make_move_iterator(more.begin()),
                  std::make_move_iterator(more.end()));
}

void check_beacons(ConfigChecker& check, const BeaconMap& beacons) {
    for (std::size_t i = 0; i < beacons.size(); ++i) {
        const Beacon& beacon = beacons[i];
        const std::string field = "beacons[" + std::to_string(i) + "]";
        check.in_range(field + ".id", beacon.id, 0.0, 255.0);
        check.require(beacon.position.allFinite(), field + ".x", beacon.position.x(),
                      "a beacon's position must be finite");
        for (std::size_t j = 0; j < i; ++j) {
            check.require(beacons[j].id != beacon.id, field + ".id", beacon.id,
                          "another beacon has the same id");
        }
    }
}

}  // namespace

std::vector<ConfigIssue> validate(const SharpIrCurve& curve, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check_ir_curve(check, curve, prefix);
    return issues;
}

std::vector<ConfigIssue> validate(const IrMount& mount, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check_ir_mount(check, mount, prefix);
    return issues;
}

SharpIrCurve ir_sensor_curve(const LoopConfig& config, IrSensor sensor) {
    const auto& own = config.ir_sensor_parameters[static_cast<std::size_t>(sensor)];
    return own ? with_curve_parameters(config.ir_curve, *own) : config.ir_curve;
}

const char* to_string(SteeringPose pose) {
    return pose == SteeringPose::Odometry ? "odometry" : "estimate";
}

std::optional<SteeringPose> steering_pose_from_string(std::string_view text) {
    for (const SteeringPose pose : {SteeringPose::Estimate, SteeringPose::Odometry}) {
        if (text == to_string(pose)) {
            return pose;
        }
    }
    return std::nullopt;
}

std::string ir_sensor_curve_name(IrSensor sensor) {
    return sensor == kFrontSensor ? "ir_curve.front" : "ir_curve.rear";
}

std::vector<ConfigIssue> validate(const LoopConfig& config) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);

    check.positive("odometry.codo_right", config.odometry.codo_right, 1e6);
    check.positive("odometry.codo_left", config.odometry.codo_left, 1e6);
    check.positive("odometry.wheel_base", config.odometry.wheel_base, 10.0);

    check_ir_mount(check, config.ir_mount, "ir_mount");
    const std::size_t issues_before_curve = issues.size();
    check_ir_curve(check, config.ir_curve, "ir_curve");
    // A sensor's own curve is checked as a whole once the shared one passes (its range
    // problems are the shared curve's, reported once, under its name).
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        if (config.ir_sensor_parameters[static_cast<std::size_t>(sensor)]
            && issues.size() == issues_before_curve) {
            check_ir_curve(check, ir_sensor_curve(config, sensor), ir_sensor_curve_name(sensor));
        }
    }

    for (int i = 0; i < config.walls.size(); ++i) {
        const Wall& wall = config.walls.wall(i);
        const std::string field = "walls[" + std::to_string(i) + "] (" + wall.name + ")";
        check.require(wall.start.allFinite() && wall.end.allFinite(), field + ".start",
                      wall.start.x(), "wall end points must be finite");
        check.require(config.walls.line(i).length > 1e-6, field + ".end", wall.end.x(),
                      "a wall must have a length");
    }

    const AssociationParams& assoc = config.association;
    check.in_range("association.segment_margin", assoc.segment_margin, 0.0, 10.0);
    check.in_range("association.range_margin", assoc.range_margin, 0.0, 10.0);
    check.positive("association.max_incidence", assoc.max_incidence, 0.5 * kPi);
    check.positive("association.max_angle_error", assoc.max_angle_error, kPi);
    check.positive("association.max_distance_error", assoc.max_distance_error, 10.0);
    check.require(assoc.gate_probability > 0.0 && assoc.gate_probability < 1.0,
                  "association.gate_probability", assoc.gate_probability,
                  "must be strictly between 0 and 1");

    const FilterTuning& filter = config.filter;
    check_variance(check, "filter.q11", filter.q11);
    check_variance(check, "filter.q22", filter.q22);
    check_variance(check, "filter.r11", filter.r11);
    check_variance(check, "filter.r22", filter.r22);
    check.require(filter.gate_probability > 0.0 && filter.gate_probability < 1.0,
                  "filter.gate_probability", filter.gate_probability,
                  "must be strictly between 0 and 1");
    check.positive("filter.min_variance", filter.limits.min_variance, 1.0);
    check.require(filter.limits.max_variance > filter.limits.min_variance
                      && std::isfinite(filter.limits.max_variance),
                  "filter.max_variance", filter.limits.max_variance,
                  "must be finite and greater than filter.min_variance");

    check.in_range("initial.x", config.initial.pose.x, -1e4, 1e4);
    check.in_range("initial.y", config.initial.pose.y, -1e4, 1e4);
    check.in_range("initial.theta", config.initial.pose.theta, -2.0 * kPi, 2.0 * kPi);
    check_variance(check, "initial.var_x", config.initial.var_x);
    check_variance(check, "initial.var_y", config.initial.var_y);
    check_variance(check, "initial.var_theta", config.initial.var_theta);

    check.positive("motion.v_ref", config.motion.v_ref, 2.0);
    check.positive("motion.w_ref", config.motion.w_ref, 20.0);
    check.positive("gains.heading_gain", config.gains.heading_gain, 100.0);
    check.positive("gains.cross_track_gain", config.gains.cross_track_gain, 1000.0);
    check.positive("gains.distance_gain", config.gains.distance_gain, 100.0);
    check.positive("gains.position_tolerance", config.gains.position_tolerance, 10.0);
    check.positive("gains.heading_tolerance", config.gains.heading_tolerance, kPi);
    check_controller(check, config.controller);

    check_lesson_filters(check, config.lesson);
    check_laser(check, config.lesson.laser, config.map,
                config.lesson.localisation == Localisation::Laser);
    if (config.initial.unknown_pose) {
        // Global localisation spreads the belief over the free space (free_space.hpp).
        const bool laser = config.lesson.localisation == Localisation::Laser;
        const bool has_room =
            laser && config.map
                ? std::find(config.map->cells().begin(), config.map->cells().end(), CellState::Free)
                      != config.map->cells().end()
                : !FreeSpace::bounding(config.walls).empty();
        check.require(has_room, "initial.unknown_pose", 1.0,
                      laser ? "needs a map with free cells to spread the belief over"
                            : "needs walls that enclose an area to spread the belief over");
    }
    append(issues, validate(config.lesson.laser.icp, "lesson.laser.icp"));
    append(issues, validate(config.lesson.particles.scan_model, "pf"));
    append(issues, validate(config.lesson.laser.geometry, "lesson.laser.geometry"));
    check_beacons(check, config.beacons);
    check.positive("simulator.control_period", config.control_period, 10.0);

    check.positive("max_wheel_speed", config.max_wheel_speed, 10.0);
    check.positive("max_wheel_travel_per_step", config.max_wheel_travel_per_step, 10.0);
    return issues;
}

}  // namespace legofeup
