#pragma once
// The robot state X = [x, y, θ]ᵀ of the LegoFeup loop (paper eq. 6) and its fixed-size
// Eigen types. Positions in metres, heading in radians, world frame.

#include <Eigen/Core>

namespace legofeup {

/// Named indices into the state vector (never index with bare 0, 1, 2).
enum StateIndex : int { kX = 0, kY = 1, kTheta = 2 };
inline constexpr int kStateSize = 3;

using StateVector = Eigen::Matrix<double, kStateSize, 1>;
using StateCovariance = Eigen::Matrix<double, kStateSize, kStateSize>;
using Vector2 = Eigen::Vector2d;

/// A planar pose; the value type shared with the simulator and the user interfaces.
struct Pose2 {
    double x = 0.0;
    double y = 0.0;
    double theta = 0.0;

    friend bool operator==(const Pose2&, const Pose2&) = default;
};

inline StateVector to_state(const Pose2& pose) {
    return {pose.x, pose.y, pose.theta};
}
inline Pose2 to_pose(const StateVector& x) {
    return {x(kX), x(kY), x(kTheta)};
}
inline Vector2 position_of(const Pose2& pose) {
    return {pose.x, pose.y};
}
/// z-component of the 2-D cross product a × b: positive when b is to the left of a.
inline double cross(const Vector2& a, const Vector2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

}  // namespace legofeup
