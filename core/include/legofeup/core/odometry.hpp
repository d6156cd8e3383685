#pragma once
// Odometry of the differential drive (paper eq. 7–9).
//
// Wheel 1 is the right wheel and wheel 2 the left one (eq. 1: V1 = V + b·W/2 turns the
// robot counter-clockwise when V1 > V2). Encoders count 1° ticks; Codo is counts per metre.

#include <cstdint>

#include "legofeup/core/state.hpp"

namespace legofeup {

/// Nominal counts per metre for a wheel: counts_per_turn / (π · diameter).
double nominal_counts_per_metre(double wheel_diameter, double counts_per_turn);

struct OdometryParams {
    /// Codo1, Codo2: encoder counts per metre of the right and left wheel (eq. 9). The
    /// defaults are the nominal NXT 2.0 values: 360 counts per turn of a 43.2 mm wheel.
    double codo_right = nominal_counts_per_metre(0.0432, 360.0);
    double codo_left = nominal_counts_per_metre(0.0432, 360.0);
    /// b: distance between the wheels' contact points (eq. 1, 8), metres.
    double wheel_base = 0.12;
};

/// The displacement of one control period, from the encoder pulses Odo1, Odo2.
struct OdometryIncrement {
    double d_right = 0.0;   ///< d1 = Odo1 / Codo1 (eq. 9), metres
    double d_left = 0.0;    ///< d2 = Odo2 / Codo2 (eq. 9), metres
    double distance = 0.0;  ///< d = (d1 + d2) / 2 (eq. 8), metres
    double rotation = 0.0;  ///< Δθ = (d1 − d2) / b (eq. 8), radians
};

/// Counts between two cumulative 32-bit encoder readings. The NXT's RotationCount is a
/// signed 32-bit counter; the difference is taken modulo 2³² so a wrap-around is harmless.
std::int32_t encoder_delta(std::int32_t now, std::int32_t before);

/// Eq. 8–9: pulses of each wheel in one period → wheel distances, d and Δθ.
OdometryIncrement odometry_increment(std::int32_t pulses_right, std::int32_t pulses_left,
                                     const OdometryParams& params);

/// The increment of a robot that moved `distance` while turning `rotation` (the inverse of
/// eq. 8: d1 = d + b·Δθ/2, d2 = d − b·Δθ/2).
OdometryIncrement increment_from_motion(double distance, double rotation, double wheel_base);

/// Eq. 7 with the noise of eq. 10: advances a pose by (d + ε_d, Δθ + ε_Δθ) along the
/// centred-difference heading θ + (Δθ + ε_Δθ)/2. The heading is wrapped to (−π, π].
Pose2 advance_pose(const Pose2& pose, double distance, double rotation);

inline Pose2 advance_pose(const Pose2& pose, const OdometryIncrement& increment) {
    return advance_pose(pose, increment.distance, increment.rotation);
}

}  // namespace legofeup
