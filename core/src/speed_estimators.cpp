#include "legofeup/core/speed_estimators.hpp"

#include "legofeup/core/angles.hpp"
#include "legofeup/core/extra_sensors.hpp"

namespace legofeup {
namespace {

// Indices of SensorFrame::encoder_counts and of the [right, left] arrays.
constexpr std::size_t kRight = 0;
constexpr std::size_t kLeft = 1;

WheelSpeedFilter make_wheel_filter(const WheelSpeedKfTuning& t, double r) {
    return WheelSpeedFilter(t.q_angle, t.q_rate, r, t.p0);
}

}  // namespace

SpeedEstimators::SpeedEstimators()
    : wheels_{make_wheel_filter(WheelSpeedKfTuning{}, WheelSpeedKfTuning{}.r_right),
              make_wheel_filter(WheelSpeedKfTuning{}, WheelSpeedKfTuning{}.r_left)},
      body_(VelocityKfTuning{}) {}

void SpeedEstimators::configure(const LessonFilters& filters, const OdometryParams& odometry) {
    const bool wheels_changed = filters.wheel_speed != filters_.wheel_speed;
    filters_ = filters;
    odometry_ = odometry;
    body_.set_tuning(filters.velocity);
    if (wheels_changed) {
        // The wheel filters hold their tuning from construction: rebuild them, keeping the
        // reference so the next frame continues (their state restarts at rest).
        wheels_ = {make_wheel_filter(filters.wheel_speed, filters.wheel_speed.r_right),
                   make_wheel_filter(filters.wheel_speed, filters.wheel_speed.r_left)};
        for (std::size_t i = 0; i < 2; ++i) {
            wheels_[i].reset(wheel_angles_[i]);
        }
    }
}

void SpeedEstimators::reset(const Pose2& initial) {
    have_counts_ = false;
    gyro_heading_ = wrap_angle(initial.theta);
    wheel_kf_pose_ = {initial.x, initial.y, gyro_heading_};
    body_kf_pose_ = wheel_kf_pose_;
    acceleration_ = {};
    raw_accel_forward_ = {};
    accel_bias_.reset();
    body_.reset();
}

void SpeedEstimators::convert_extra_sensors(const SensorFrame& frame, double period,
                                            ExtraReadings& readings) {
    const ExtraSensorCalibration& calibration = filters_.calibration;
    readings = ExtraReadings{};
    readings.gyro_heading = gyro_heading_;
    if (frame.has_gyro) {
        readings.has_gyro = true;
        readings.gyro_rate = gyro_rate_from_raw(frame.gyro_raw, calibration);
        // Rectangle rule over the period that just ended (the rate is sampled at its end).
        gyro_heading_ = wrap_angle(gyro_heading_ + readings.gyro_rate * period);
        readings.gyro_heading = gyro_heading_;
    }
    acceleration_ = {};
    if (frame.has_accelerometers) {
        readings.has_accelerometers = true;
        raw_accel_forward_[kRight] =
            accel_from_raw(frame.accel_raw[kAccelRightWheel][kAccelForward], calibration);
        raw_accel_forward_[kLeft] =
            accel_from_raw(frame.accel_raw[kAccelLeftWheel][kAccelForward], calibration);
        // The bias learned from the frames before this one (so far as it is known).
        if (calibration.remove_accel_bias) {
            readings.accel_bias = accel_bias_.bias();
        }
        for (std::size_t i = 0; i < 2; ++i) {
            readings.accel_forward[i] = raw_accel_forward_[i] - readings.accel_bias[i];
        }
        acceleration_ = body_acceleration(readings.accel_forward[kRight],
                                          readings.accel_forward[kLeft], odometry_.wheel_base);
    }
    if (frame.has_compass) {
        readings.has_compass = true;
        readings.compass_heading = compass_heading_from_raw(frame.compass_deg);
    }
}

void SpeedEstimators::step(const SensorFrame& frame, double period, SpeedEstimates& speeds,
                           ExtraReadings& readings) {
    convert_extra_sensors(frame, have_counts_ ? period : 0.0, readings);
    speeds = SpeedEstimates{};
    if (!have_counts_) {
        for (std::size_t i = 0; i < 2; ++i) {
            wheel_angles_[i] = static_cast<double>(frame.encoder_counts[i]);
            wheels_[i].reset(wheel_angles_[i]);
        }
        last_counts_ = frame.encoder_counts;
        have_counts_ = true;
        return;
    }
    // Counts per metre of each wheel (Codo of eq. 9) turn counts/s into surface speed, m/s.
    const std::array<double, 2> codo{odometry_.codo_right, odometry_.codo_left};
    WheelSpeeds differentiated;
    for (std::size_t i = 0; i < 2; ++i) {
        const double delta =
            static_cast<double>(encoder_delta(frame.encoder_counts[i], last_counts_[i]));
        speeds.wheel_differentiated[i] = delta / period / codo[i];
        // The KF measures the wheel angle in counts (1 count = 1° on the NXT), accumulated
        // from the deltas so a counter wrap-around cannot jump it.
        wheel_angles_[i] += delta;
        wheels_[i].step(wheel_angles_[i], period);
        speeds.wheel_kf[i] = wheels_[i].rate_dps() / codo[i];
    }
    differentiated.right = speeds.wheel_differentiated[kRight];
    differentiated.left = speeds.wheel_differentiated[kLeft];
    speeds.body_encoders = velocity_command(differentiated, odometry_.wheel_base);  // eq. 14
    if (frame.has_accelerometers) {
        // Eq. 21: v += T·a, ω += T·α; eq. 22: z = (v, ω) from the encoders.
        body_.predict(acceleration_.v, acceleration_.w, period);
        body_.update(speeds.body_encoders);
        speeds.body_kf = body_.estimate();
        speeds.body_kf_valid = true;
    }
    speeds.valid = true;
    last_counts_ = frame.encoder_counts;
    integrate_poses(frame, period, speeds);
    learn_accel_bias(readings, speeds, period);
}

void SpeedEstimators::integrate_poses(const SensorFrame& frame, double period,
                                      SpeedEstimates& speeds) {
    // Eq. 13 with each filter's (v, ω) over the period that just ended, as odometry does with
    // the counts of that period: d = v·T, Δθ = ω·T.
    const VelocityCommand wheel_kf = velocity_command(
        WheelSpeeds{speeds.wheel_kf[kRight], speeds.wheel_kf[kLeft]}, odometry_.wheel_base);
    wheel_kf_pose_ = advance_pose(wheel_kf_pose_, wheel_kf.v * period, wheel_kf.w * period);
    if (frame.has_accelerometers) {
        body_kf_pose_ =
            advance_pose(body_kf_pose_, speeds.body_kf.v * period, speeds.body_kf.w * period);
    }
    speeds.wheel_kf_pose = wheel_kf_pose_;
    speeds.body_kf_pose = body_kf_pose_;
}

void SpeedEstimators::learn_accel_bias(const ExtraReadings& readings, const SpeedEstimates& speeds,
                                       double period) {
    // This frame's readings against the wheels' speed change (accelerometer_bias.hpp); the
    // wheel KF's speeds, whose error at the end points is smaller than the differenced ones'.
    if (readings.has_accelerometers && filters_.calibration.remove_accel_bias) {
        accel_bias_.add(raw_accel_forward_, speeds.wheel_kf, period);
    }
}

}  // namespace legofeup
