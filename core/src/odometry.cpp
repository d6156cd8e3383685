#include "legofeup/core/odometry.hpp"

#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {

double nominal_counts_per_metre(double wheel_diameter, double counts_per_turn) {
    return counts_per_turn / (kPi * wheel_diameter);
}

std::int32_t encoder_delta(std::int32_t now, std::int32_t before) {
    // Unsigned subtraction wraps modulo 2³²; converting back to int32 is well defined
    // (modular) since C++20.
    const auto difference = static_cast<std::uint32_t>(now) - static_cast<std::uint32_t>(before);
    return static_cast<std::int32_t>(difference);
}

OdometryIncrement odometry_increment(std::int32_t pulses_right, std::int32_t pulses_left,
                                     const OdometryParams& params) {
    OdometryIncrement inc;
    inc.d_right = static_cast<double>(pulses_right) / params.codo_right;  // d1 = Odo1/Codo1
    inc.d_left = static_cast<double>(pulses_left) / params.codo_left;     // d2 = Odo2/Codo2
    inc.distance = 0.5 * (inc.d_right + inc.d_left);                      // d
    inc.rotation = (inc.d_right - inc.d_left) / params.wheel_base;        // Δθ
    return inc;
}

OdometryIncrement increment_from_motion(double distance, double rotation, double wheel_base) {
    OdometryIncrement inc;
    inc.distance = distance;
    inc.rotation = rotation;
    inc.d_right = distance + 0.5 * wheel_base * rotation;
    inc.d_left = distance - 0.5 * wheel_base * rotation;
    return inc;
}

Pose2 advance_pose(const Pose2& pose, double distance, double rotation) {
    const double mid_heading = pose.theta + 0.5 * rotation;  // θ + Δθ/2
    return {pose.x + distance * std::cos(mid_heading), pose.y + distance * std::sin(mid_heading),
            wrap_angle(pose.theta + rotation)};
}

}  // namespace legofeup
