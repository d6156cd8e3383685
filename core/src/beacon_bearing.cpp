#include "legofeup/core/beacon_bearing.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {

BeaconBearingMeasurement::BeaconBearingMeasurement(const Vector2& beacon, double bearing,
                                                   double variance)
    : beacon_(beacon), z_(Vector(wrap_angle(bearing))), r_(Matrix(variance)) {}

bool BeaconBearingMeasurement::usable(const StateVector& x) const {
    return (beacon_ - x.head<2>()).norm() >= kMinimumRange;
}

BeaconBearingMeasurement::Vector BeaconBearingMeasurement::predict_measurement(
    const StateVector& x) const {
    const double dx = beacon_.x() - x(kX);  // Δx
    const double dy = beacon_.y() - x(kY);  // Δy
    return Vector(wrap_angle(std::atan2(dy, dx) - x(kTheta)));
}

BeaconBearingMeasurement::Jacobian BeaconBearingMeasurement::jacobian(const StateVector& x) const {
    const double dx = beacon_.x() - x(kX);
    const double dy = beacon_.y() - x(kY);
    const double range_squared = std::max(dx * dx + dy * dy, kMinimumRange * kMinimumRange);  // ρ²
    Jacobian H;
    H(0, kX) = dy / range_squared;   // ∂h/∂x
    H(0, kY) = -dx / range_squared;  // ∂h/∂y
    H(0, kTheta) = -1.0;             // ∂h/∂θ
    return H;
}

BeaconBearingMeasurement::Vector BeaconBearingMeasurement::residual(const Vector& a,
                                                                    const Vector& b) const {
    return Vector(wrap_angle(a(0) - b(0)));
}

}  // namespace legofeup
