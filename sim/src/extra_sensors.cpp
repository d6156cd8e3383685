#include "extra_sensors.hpp"

#include <algorithm>
#include <cmath>

#include "box2d_convert.hpp"
#include "sensor_models.hpp"

namespace legofeup::sim {

ExtraSensors::ExtraSensors(std::uint64_t seed, const RobotSpec& robot)
    : scanner_(seed),
      laser_(seed),
      gyro_noise_(seed, NoiseStream::GyroNoise),
      gyro_bias_stream_(seed, NoiseStream::GyroBias),
      accel_noise_(seed, NoiseStream::AccelNoise),
      compass_noise_(seed, NoiseStream::CompassNoise) {
    // Biases drawn once at reset: b ~ N(0, σ_b²), whether or not the sensor is enabled.
    gyro_bias_ = robot.gyro.bias_sigma * gyro_bias_stream_.next();
    GaussianStream accel_bias(seed, NoiseStream::AccelBias);
    for (auto& unit : accel_bias_) {
        for (double& axis : unit) {
            axis = robot.accelerometers.bias_sigma * accel_bias.next();
        }
    }
}

MountMotion ExtraSensors::mount_motion(const b2Body& chassis, const RobotSpec& robot) {
    const double half_base = 0.5 * robot.wheel_base * robot.wheel_base_ratio;
    MountMotion motion;
    motion.velocity[kAccelRightWheel] =
        from_b2(chassis.GetLinearVelocityFromLocalPoint(to_b2(0.0, -half_base)));
    motion.velocity[kAccelLeftWheel] =
        from_b2(chassis.GetLinearVelocityFromLocalPoint(to_b2(0.0, half_base)));
    motion.heading = static_cast<double>(chassis.GetAngle());
    return motion;
}

void ExtraSensors::accumulate(const MountMotion& before, const MountMotion& after, double dt) {
    for (int unit : {kAccelRightWheel, kAccelLeftWheel}) {
        const auto u = static_cast<std::size_t>(unit);
        force_sum_[u] += mount_specific_force(before.velocity[u], after.velocity[u], before.heading,
                                              after.heading, dt);
    }
    ++force_steps_;
}

void ExtraSensors::sample_motion_sensors(const RobotSpec& robot, const WorldSpec& world,
                                         const b2Body& chassis, double time) {
    if (robot.gyro.enabled) {
        // Bias random walk since the last reading: b += σ_rw·√Δt·n.
        const double elapsed = std::max(0.0, time - last_gyro_time_);
        gyro_bias_ += robot.gyro.bias_drift * std::sqrt(elapsed) * gyro_bias_stream_.next();
        last_gyro_time_ = time;
        const double rate = static_cast<double>(chassis.GetAngularVelocity());
        gyro_raw_ = gyro_raw(robot.gyro, rate, gyro_bias_, robot.gyro.noise * gyro_noise_.next());
    }
    if (robot.accelerometers.enabled) {
        for (int unit : {kAccelRightWheel, kAccelLeftWheel}) {
            const auto u = static_cast<std::size_t>(unit);
            const Vector2 mean =
                force_steps_ > 0 ? Vector2(force_sum_[u] / force_steps_) : Vector2::Zero();
            for (int axis : {kAccelForward, kAccelLeft}) {
                const auto a = static_cast<std::size_t>(axis);
                accel_raw_[u][a] =
                    accelerometer_raw(robot.accelerometers, mean(axis), accel_bias_[u][a],
                                      robot.accelerometers.noise * accel_noise_.next());
            }
        }
    }
    force_sum_ = {Vector2::Zero(), Vector2::Zero()};
    force_steps_ = 0;
    if (robot.compass.enabled) {
        const double disturbance =
            magnetic_disturbance_deg(world.magnetic, from_b2(chassis.GetPosition()));
        compass_raw_ = compass_raw(static_cast<double>(chassis.GetAngle()), disturbance,
                                   robot.compass.noise_deg * compass_noise_.next());
    }
}

void ExtraSensors::scan_beacons(const RobotSpec& robot, const BeaconMap& beacons_by_id,
                                const b2World& world, const b2Body& chassis, double time) {
    if (robot.beacon_scanner.enabled) {
        scan_ = scanner_.scan(robot.beacon_scanner, beacons_by_id, world, chassis);
        last_scan_time_ = time;
    }
}

void ExtraSensors::scan_laser(const RobotSpec& robot, const b2World& world, const b2Body& chassis,
                              double time) {
    if (robot.laser_scanner.enabled) {
        laser_.scan(robot.laser_scanner, world, chassis, laser_scan_);
        last_laser_time_ = time;
    }
}

void ExtraSensors::fill(SensorFrame& frame, const RobotSpec& robot, double control_period) const {
    constexpr double kTimeTolerance = 1e-9;  // s
    frame.has_beacon_scan = robot.beacon_scanner.enabled
                            && last_scan_time_ > frame.time - control_period + kTimeTolerance;
    if (frame.has_beacon_scan) {
        frame.beacons = scan_;
    }
    frame.has_laser_scan = robot.laser_scanner.enabled
                           && last_laser_time_ > frame.time - control_period + kTimeTolerance;
    if (frame.has_laser_scan) {
        frame.laser = laser_scan_;
    }
    frame.has_gyro = robot.gyro.enabled;
    frame.gyro_raw = robot.gyro.enabled ? gyro_raw_ : std::int16_t{0};
    frame.has_accelerometers = robot.accelerometers.enabled;
    if (robot.accelerometers.enabled) {
        frame.accel_raw = accel_raw_;
    }
    frame.has_compass = robot.compass.enabled;
    frame.compass_deg = robot.compass.enabled ? compass_raw_ : std::int16_t{0};
}

}  // namespace legofeup::sim
