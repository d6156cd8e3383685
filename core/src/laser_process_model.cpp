#include "legofeup/core/laser_process_model.hpp"

#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {

LaserProcessModel::LaserProcessModel(const OdometryIncrement& increment, double prior_heading,
                                     const LaserTuning& tuning)
    : distance_(increment.distance),
      rotation_(increment.rotation),
      q_static_(tuning.q_x_static, tuning.q_y_static, tuning.q_theta_static),
      q_dynamic_(tuning.q_x_dynamic, tuning.q_y_dynamic, tuning.q_theta_dynamic),
      q_(process_noise(prior_heading)) {}

StateVector LaserProcessModel::world_increment(double theta) const {
    const double phi = theta + 0.5 * rotation_;  // φ = θ + Δθ/2
    return {distance_ * std::cos(phi), distance_ * std::sin(phi), rotation_};
}

StateCovariance LaserProcessModel::process_noise(double theta) const {
    // Eq. 13: q_stat + q_dyn·|Δ_odom|, one diagonal entry per state component.
    const StateVector magnitude = world_increment(theta).cwiseAbs();
    return (q_static_ + q_dynamic_.cwiseProduct(magnitude)).asDiagonal();
}

StateVector LaserProcessModel::propagate(const StateVector& x, const NoiseVector& noise) const {
    StateVector next = x + world_increment(x(kTheta)) + noise;  // eq. 11
    next(kTheta) = wrap_angle(next(kTheta));
    return next;
}

StateCovariance LaserProcessModel::state_jacobian(const StateVector& x) const {
    const StateVector delta = world_increment(x(kTheta));
    StateCovariance F;          // eq. 12
    F << 1.0, 0.0, -delta(kY),  //
        0.0, 1.0, delta(kX),    //
        0.0, 0.0, 1.0;
    return F;
}

}  // namespace legofeup
