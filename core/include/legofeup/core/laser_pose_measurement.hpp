#pragma once
// The observation of the laser lesson (paper 001 eq. 2–3, 14–18): scan matching yields the
// robot pose Z = [x_obs, y_obs, θ_obs] directly, so
//   h(X) = X,   H = ∂h/∂X = I (eq. 14),   R = diag(r_x, r_y, r_θ) (eq. 16),
//   V = Z − Ẑ with the heading difference wrapped (eq. 3).
// With H = I the EKF's general update is the paper's eq. 15, 17, 18:
//   K = P·(P + R)⁻¹,   X̂ ← X̂ + K·V,   P ← (I − K)·P,
// which the filter computes with an LDLT solve and the Joseph form (equal for this K).
// The model is linear, so the UKF's update gives the same result (up to the heading's
// wrapped sigma-point mean); both filter kinds accept it.

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

class LaserPoseMeasurement {
  public:
    static constexpr int kSize = kStateSize;
    using Vector = StateVector;
    using Matrix = StateCovariance;

    /// `observed` is Z (world frame); `r` the variances of eq. 16 (m², m², rad²).
    LaserPoseMeasurement(const Pose2& observed, const StateVector& r)
        : z_(to_state(observed)), r_(r.asDiagonal()) {
        PoseStateSpace::normalize(z_);
    }

    const Vector& measurement() const { return z_; }
    Vector predict_measurement(const StateVector& x) const { return x; }
    Matrix jacobian(const StateVector& /*x*/) const { return Matrix::Identity(); }
    const Matrix& noise_covariance() const { return r_; }
    /// a − b with the heading wrapped (eq. 3).
    Vector residual(const Vector& a, const Vector& b) const {
        return PoseStateSpace::difference(a, b);
    }
    /// Sigma-point mean for the UKF: the heading by its wrapped-difference mean.
    template <std::size_t K>
    Vector weighted_mean(const std::array<Vector, K>& points,
                         const std::array<double, K>& weights) const {
        return PoseStateSpace::weighted_mean(points, weights);
    }

  private:
    Vector z_;
    Matrix r_;
};

}  // namespace legofeup
