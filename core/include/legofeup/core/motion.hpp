#pragma once
// Robot velocities, wheel speeds (paper eq. 1) and the controllers' shared settings.

#include "legofeup/core/angles.hpp"

namespace legofeup {

/// Linear and angular velocity of the robot: V (m/s, forward) and W (rad/s, CCW).
struct VelocityCommand {
    double v = 0.0;
    double w = 0.0;
};

/// Wheel speeds: V1 of the right wheel and V2 of the left wheel, m/s.
struct WheelSpeeds {
    double right = 0.0;  ///< V1
    double left = 0.0;   ///< V2
};

/// Eq. 1: V1 = V + b·W/2, V2 = V − b·W/2.
inline WheelSpeeds wheel_speeds(const VelocityCommand& command, double wheel_base) {
    const double half_turn = 0.5 * wheel_base * command.w;
    return {command.v + half_turn, command.v - half_turn};
}

/// The inverse of eq. 1: V = (V1 + V2)/2, W = (V1 − V2)/b.
inline VelocityCommand velocity_command(const WheelSpeeds& wheels, double wheel_base) {
    return {0.5 * (wheels.right + wheels.left), (wheels.right - wheels.left) / wheel_base};
}

/// Scales both wheel speeds by the same factor so neither exceeds `max_speed` (keeps the
/// curvature of the path; clipping one wheel alone would turn the robot).
WheelSpeeds limit_wheel_speeds(const WheelSpeeds& wheels, double max_speed);

/// V_ref and W_ref of the paper: the largest speeds the routines command.
struct MotionLimits {
    double v_ref = 0.1;  ///< m/s
    double w_ref = 0.8;  ///< rad/s
};

/// The tuning of the path-control routines.
struct ControllerGains {
    double heading_gain = 2.0;         ///< k_θ, 1/s: W = k_θ · heading error
    double cross_track_gain = 5.0;     ///< k_e, 1/m: approach heading = −atan(k_e · offset)
    double distance_gain = 1.0;        ///< k_ρ, 1/s: GoXYTheta slows to V = k_ρ · distance
    double position_tolerance = 0.02;  ///< GoXYTheta arrival, m
    double heading_tolerance = degrees_to_radians(2.0);  ///< GoXYTheta final heading, rad
};

}  // namespace legofeup
