#pragma once
// The speed estimates of paper 003 that run beside the pose filter, for every localisation:
// a linear KF per wheel on the encoder angle (§3.2), the wheel speeds by differencing the
// encoders, the body (v, ω) from the encoders (eq. 14) and, when the frame has the
// accelerometers, the KF on (v, ω) with accelerations as inputs (§3.3), each filter's speeds
// integrated into a pose (eq. 13). It also converts the optional gyro, accelerometer
// (removing the accelerometers' estimated bias, accelerometer_bias.hpp) and compass readings
// and integrates the gyro into a heading.

#include <array>
#include <cstdint>

#include "legofeup/core/accelerometer_bias.hpp"
#include "legofeup/core/body_velocity_filter.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/wheel_speed_filter.hpp"

namespace legofeup {

class SpeedEstimators {
  public:
    SpeedEstimators();

    /// Starts again: the next encoder counts only set the reference; the gyro heading and
    /// the integrated poses start at `initial`, the accelerometer bias estimate at 0.
    void reset(const Pose2& initial);

    /// Applies new tuning (takes effect at the next step).
    void configure(const LessonFilters& filters, const OdometryParams& odometry);

    /// One frame: `counts` are the cumulative encoder counts, `period` the seconds since the
    /// previous frame. Fills the speeds and readings of the snapshot.
    void step(const SensorFrame& frame, double period, SpeedEstimates& speeds,
              ExtraReadings& readings);

    /// The body acceleration (a, α) from the accelerometers of the last frame, bias removed
    /// (zero without).
    const VelocityCommand& measured_acceleration() const { return acceleration_; }

  private:
    void convert_extra_sensors(const SensorFrame& frame, double period, ExtraReadings& readings);
    void integrate_poses(const SensorFrame& frame, double period, SpeedEstimates& speeds);
    void learn_accel_bias(const ExtraReadings& readings, const SpeedEstimates& speeds,
                          double period);

    LessonFilters filters_;
    OdometryParams odometry_;
    std::array<WheelSpeedFilter, 2> wheels_;
    BodyVelocityFilter body_;
    AccelerometerBiasEstimator accel_bias_;
    std::array<double, 2> raw_accel_forward_{};  ///< m/s², the last readings with their bias
    Pose2 wheel_kf_pose_;
    Pose2 body_kf_pose_;
    std::array<std::int32_t, 2> last_counts_{};
    std::array<double, 2> wheel_angles_{};  ///< unwrapped encoder angles, counts
    bool have_counts_ = false;
    double gyro_heading_ = 0.0;
    VelocityCommand acceleration_;
};

}  // namespace legofeup
