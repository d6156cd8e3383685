#pragma once
// The further lessons' sensors on the simulated robot: beacon scanner, gyroscope, two
// accelerometers, compass and laser scanner, each with its own noise streams (docs/sensors.md). The
// simulator calls it around every physics step and when a sample is due; it keeps the last
// readings for the frame. Private to sim/.

#include <box2d/box2d.h>

#include <array>
#include <cstdint>

#include "beacon_scanner.hpp"
#include "laser_scanner.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/world.hpp"
#include "noise_streams.hpp"

namespace legofeup::sim {

/// World velocities of the two accelerometer mounts ([kAccelRightWheel], [kAccelLeftWheel])
/// and the heading at one instant.
struct MountMotion {
    std::array<Vector2, 2> velocity{Vector2::Zero(), Vector2::Zero()};
    double heading = 0.0;
};

class ExtraSensors {
  public:
    /// Reseeds every stream and draws the gyroscope's and accelerometers' biases.
    ExtraSensors(std::uint64_t seed, const RobotSpec& robot);

    /// The accelerometer mounts sit over the wheels, at ∓b/2 (actual wheel base) on the axle.
    static MountMotion mount_motion(const b2Body& chassis, const RobotSpec& robot);
    /// Adds one physics step's specific force at each mount to the running mean.
    void accumulate(const MountMotion& before, const MountMotion& after, double dt);

    /// Samples the enabled gyroscope, accelerometers (mean since the last sample) and compass.
    void sample_motion_sensors(const RobotSpec& robot, const WorldSpec& world,
                               const b2Body& chassis, double time);
    void scan_beacons(const RobotSpec& robot, const BeaconMap& beacons_by_id, const b2World& world,
                      const b2Body& chassis, double time);
    /// A laser scan at this instant, if the scanner is enabled.
    void scan_laser(const RobotSpec& robot, const b2World& world, const b2Body& chassis,
                    double time);

    /// Sets the enabled sensors' readings and has_ flags; a beacon scan and a laser scan
    /// only when one completed within the last control period.
    void fill(SensorFrame& frame, const RobotSpec& robot, double control_period) const;

    /// The gyroscope's current bias, counts.
    double gyro_bias() const { return gyro_bias_; }

  private:
    BeaconScanner scanner_;
    LaserScanner laser_;
    GaussianStream gyro_noise_;
    GaussianStream gyro_bias_stream_;
    GaussianStream accel_noise_;
    GaussianStream compass_noise_;

    double gyro_bias_ = 0.0;                             // counts
    double last_gyro_time_ = 0.0;                        // s
    std::array<std::array<double, 2>, 2> accel_bias_{};  // counts, [unit][axis]
    std::array<Vector2, 2> force_sum_{Vector2::Zero(), Vector2::Zero()};
    int force_steps_ = 0;

    BeaconScan scan_;
    double last_scan_time_ = -1e300;
    LaserScan laser_scan_;
    double last_laser_time_ = -1e300;
    std::int16_t gyro_raw_ = 0;
    std::array<std::array<std::int16_t, 2>, 2> accel_raw_{};
    std::int16_t compass_raw_ = 0;
};

}  // namespace legofeup::sim
