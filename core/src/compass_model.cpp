#include "legofeup/core/compass_model.hpp"

#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {

CompassOdometryProcessModel::CompassOdometryProcessModel(const OdometryIncrement& increment,
                                                         const CompassTuning& tuning)
    : odometry_(increment, Eigen::Matrix2d::Zero()), q_(NoiseCovariance::Zero()) {
    const double distance = std::abs(increment.distance);  // |ΔD|
    const double rotation = std::abs(increment.rotation);  // |Δθ|
    q_(kX, kX) = tuning.k_d * distance;
    q_(kY, kY) = tuning.k_d * distance;
    q_(kTheta, kTheta) = tuning.k_dtheta * distance + tuning.k_theta * rotation;
    q_.diagonal().array() += kCompassProcessNoiseFloor;
}

StateCovariance CompassOdometryProcessModel::noise_jacobian(const StateVector& x) const {
    StateCovariance G = StateCovariance::Zero();
    G(kX, kX) = std::sqrt(std::abs(std::cos(x(kTheta))));  // √|cos θ|
    G(kY, kY) = std::sqrt(std::abs(std::sin(x(kTheta))));  // √|sin θ|
    G(kTheta, kTheta) = 1.0;
    return G;
}

StateVector CompassOdometryProcessModel::propagate(const StateVector& x,
                                                   const NoiseVector& noise) const {
    StateVector next = odometry_.predict_state(x) + noise_jacobian(x) * noise;
    next(kTheta) = wrap_angle(next(kTheta));
    return next;
}

StateCovariance CompassOdometryProcessModel::pose_noise(const StateVector& x) const {
    const StateCovariance G = noise_jacobian(x);
    return G * q_ * G.transpose();
}

CompassMeasurement::CompassMeasurement(double heading_rad, double variance)
    : z_(Vector(wrap_angle(heading_rad))), r_(Matrix(variance)), h_(Jacobian::Zero()) {
    h_(0, kTheta) = 1.0;
}

CompassMeasurement::Vector CompassMeasurement::residual(const Vector& a, const Vector& b) const {
    return Vector(wrap_angle(a(0) - b(0)));
}

}  // namespace legofeup
