#include "legofeup/core/odometry_process_model.hpp"

#include <bit>
#include <cmath>
#include <cstdint>

#include "legofeup/core/angles.hpp"

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

OdometryProcessModel::Linearisation OdometryProcessModel::linearise(const StateVector& x) const {
    // predict_state is propagate(x, 0), whose d + 0 and Δθ + 0 turn a −0 into +0; the
    // Jacobians use d and Δθ as they are. So the state's mid heading is the Jacobians' φ
    // but for a zero of the other sign, whose sine differs in sign: reuse only the same bits.
    const double distance = distance_ + 0.0;
    const double rotation = rotation_ + 0.0;
    const double phi = x(kTheta) + 0.5 * rotation_;  // φ = θ + Δθ/2
    const double mid_heading = x(kTheta) + 0.5 * rotation;
    const double cos_phi = std::cos(phi);
    const double sin_phi = std::sin(phi);
    const bool same =
        std::bit_cast<std::uint64_t>(mid_heading) == std::bit_cast<std::uint64_t>(phi);
    const double cos_mid = same ? cos_phi : std::cos(mid_heading);
    const double sin_mid = same ? sin_phi : std::sin(mid_heading);

    Linearisation linearised;
    // advance_pose (eq. 7) with these cos and sin.
    linearised.state << x(kX) + distance * cos_mid, x(kY) + distance * sin_mid,
        wrap_angle(x(kTheta) + rotation);
    linearised.state_jacobian << 1.0, 0.0, -distance_ * sin_phi,  //
        0.0, 1.0, distance_ * cos_phi,                            //
        0.0, 0.0, 1.0;
    linearised.noise_jacobian << cos_phi, -0.5 * distance_ * sin_phi,  //
        sin_phi, 0.5 * distance_ * cos_phi,                            //
        0.0, 1.0;
    return linearised;
}

}  // namespace legofeup
