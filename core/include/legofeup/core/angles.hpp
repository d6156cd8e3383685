#pragma once
// The one angle-wrapping function, used for the state's heading and for innovations.

#include <numbers>

namespace legofeup {

inline constexpr double kPi = std::numbers::pi;

/// wrap_angle's slow path for angles outside (−π, π]: std::remainder computes a − n·2π with
/// no rounding error (for the double nearest 2π), so repeated wrapping never drifts.
double wrap_angle_slow(double angle);

/// Wraps an angle to the half-open interval (−π, π]. Angles already inside are returned
/// unchanged (the common case, kept inline because it runs several times per loop step).
inline double wrap_angle(double angle) {
    return angle > -kPi && angle <= kPi ? angle : wrap_angle_slow(angle);
}

inline constexpr double degrees_to_radians(double deg) {
    return deg * kPi / 180.0;
}
inline constexpr double radians_to_degrees(double rad) {
    return rad * 180.0 / kPi;
}

}  // namespace legofeup
