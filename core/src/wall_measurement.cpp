#include "legofeup/core/wall_measurement.hpp"

#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup {

double facing_heading(const WallLine& wall, int side) {
    return side >= 0 ? wall.facing_from_positive_side : wall.facing_from_negative_side;
}

WallMeasurement::WallMeasurement(const WallLine& wall, int side, const WallObservation& observation,
                                 const Eigen::Matrix2d& ir_covariance) {
    const double sign = side >= 0 ? 1.0 : -1.0;  // σ, the paper's "signal"
    z_ << wall.offset + sign * observation.centre_distance,
        wrap_angle(facing_heading(wall, side) + observation.angle);
    jacobian_ << wall.normal.x(), wall.normal.y(), 0.0,  // ∇h_X (eq. 17): C₁, C₂, 0
        0.0, 0.0, 1.0;
    noise_jacobian_ = observation.jacobian;  // ∂(D_c, ObsAng)/∂(d_s1, d_s2)
    noise_jacobian_.row(0) *= sign;          // z₁ = c + σ·D_c
    noise_covariance_ = noise_jacobian_ * ir_covariance * noise_jacobian_.transpose();
}

WallMeasurement::Vector WallMeasurement::residual(const Vector& z, const Vector& predicted) const {
    return {z(0) - predicted(0), wrap_angle(z(1) - predicted(1))};
}

}  // namespace legofeup
