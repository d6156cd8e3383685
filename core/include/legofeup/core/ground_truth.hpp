#pragma once
// What really happened, reported on its own channel for displays and metrics. The filter
// never sees it: links carry SensorFrames only. The simulator fills it in; over UDP it
// travels on its own stream (docs/protocol.md).

#include <array>
#include <cstdint>

#include "legofeup/core/motion.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct GroundTruth {
    double time = 0.0;         ///< simulated time, s
    Pose2 pose;                ///< the axle midpoint and heading
    VelocityCommand velocity;  ///< actual forward speed (m/s) and turn rate (rad/s)
    WheelSpeeds
        wheel_surface_speeds;  ///< ω·r of each wheel, m/s (differs from ground speed when slipping)
    bool touching_wall = false;  ///< the chassis is in contact with a wall
    /// Distances the IR beams really measured at their last sample (before noise and A/D),
    /// m; the ray length when they saw nothing.
    std::array<double, 2> ir_distances{};
    /// The gyroscope's true bias at this time, converted to rad/s (0 without a gyroscope).
    double gyro_bias_rate = 0.0;
    /// The compass disturbance field at the robot's position, rad (0 without one).
    double magnetic_disturbance = 0.0;
    /// How many times the robot was moved instantly since the last reset: teleports
    /// (GUI, control requests) and the simulator's displacement and kidnap events. A change
    /// between two truths says a kidnapping happened in between.
    std::uint32_t teleports = 0;
};

}  // namespace legofeup
