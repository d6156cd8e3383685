#pragma once
// One bearing to a beacon at a known place, as the pose filters see it (paper 002 eq. 6–7, 10).
//
//   h(X) = wrap(atan2(b_y − y, b_x − x) − θ)          X = [x, y, θ], beacon at (b_x, b_y)
//
// With Δx = b_x − x, Δy = b_y − y and ρ² = Δx² + Δy² the Jacobian is
//   ∂h/∂x = Δy/ρ²,   ∂h/∂y = −Δx/ρ²,   ∂h/∂θ = −1
// (eq. 10 of the paper, written without the ratio so it holds for Δx = 0 too).
//
// Degenerate case: with the robot on the beacon (ρ → 0) the bearing is undefined and the
// Jacobian blows up as 1/ρ. Below kMinimumRange the model reports usable() == false and the
// caller must skip the sighting; h stays finite (atan2(0, 0) = 0) and the Jacobian is
// evaluated with ρ clamped to kMinimumRange, so even a careless caller gets finite numbers.

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "legofeup/core/angle_mean.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

class BeaconBearingMeasurement {
  public:
    static constexpr int kSize = 1;
    static constexpr double kMinimumRange = 1e-3;  ///< m
    using Vector = Eigen::Matrix<double, 1, 1>;
    using Matrix = Eigen::Matrix<double, 1, 1>;
    using Jacobian = Eigen::Matrix<double, 1, kStateSize>;

    /// `beacon`: its world position (m); `bearing`: the measured bearing relative to the
    /// heading (rad, CCW); `variance`: R (rad²).
    BeaconBearingMeasurement(const Vector2& beacon, double bearing, double variance);

    /// False when the estimate is within kMinimumRange of the beacon (bearing undefined).
    bool usable(const StateVector& x) const;

    // Filter hooks (EKF and UKF).
    const Vector& measurement() const { return z_; }
    Vector predict_measurement(const StateVector& x) const;
    Jacobian jacobian(const StateVector& x) const;
    const Matrix& noise_covariance() const { return r_; }
    /// a − b wrapped to (−π, π].
    Vector residual(const Vector& a, const Vector& b) const;
    /// The circular weighted mean of predicted bearings (UKF).
    template <std::size_t K>
    Vector weighted_mean(const std::array<Vector, K>& points,
                         const std::array<double, K>& weights) const {
        return Vector(weighted_angle_mean(points, weights, 0));
    }

  private:
    Vector2 beacon_;
    Vector z_;
    Matrix r_;
};

}  // namespace legofeup
