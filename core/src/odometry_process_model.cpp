#include "legofeup/core/odometry_process_model.hpp"

#include <cmath>

namespace legofeup {

StateVector OdometryProcessModel::propagate(const StateVector& x, const NoiseVector& noise) const {
    const Pose2 next = advance_pose(to_pose(x), distance_ + noise(0), rotation_ + noise(1));
    return to_state(next);
}

StateCovariance OdometryProcessModel::state_jacobian(const StateVector& x) const {
    const double phi = x(kTheta) + 0.5 * rotation_;  // φ = θ + Δθ/2
    StateCovariance F;
    F << 1.0, 0.0, -distance_ * std::sin(phi),  //
        0.0, 1.0, distance_ * std::cos(phi),    //
        0.0, 0.0, 1.0;
    return F;
}

OdometryProcessModel::NoiseJacobian OdometryProcessModel::noise_jacobian(
    const StateVector& x) const {
    const double phi = x(kTheta) + 0.5 * rotation_;
    NoiseJacobian G;
    G << std::cos(phi), -0.5 * distance_ * std::sin(phi),  //
        std::sin(phi), 0.5 * distance_ * std::cos(phi),    //
        0.0, 1.0;
    return G;
}

}  // namespace legofeup
