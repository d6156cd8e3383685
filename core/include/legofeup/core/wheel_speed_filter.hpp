#pragma once
// The per-wheel linear Kalman filter for wheel speed (paper 003 §3.2, eq. 15–19).
//
// State x = [θ, ω]ᵀ: the wheel's angle (°) and rate (°/s) (eq. 15). Between samples the
// rate is modelled constant, ẋ = A·x with A = [0 1; 0 0] (eq. 16), so over a period T
//   x_k = e^{A·T}·x_{k−1} + w_{k−1},   e^{A·T} = I + A·T = [1 T; 0 1]   (A² = 0; eq. 17)
//   z_k = H·x_k + v_k,                  H = [1 0]  (the encoder angle, °; eq. 18)
// with w ~ N(0, Q = diag(q_angle, q_rate)) and v ~ N(0, r) (eq. 19 gives Q = diag(0.1, 10),
// R = 2.5 / 1.5 for the right / left wheel and P₀ = 10·I).
//
// A linear KF, run by the ExtendedKalmanFilter with linear models (linear_models.hpp):
// predict x ← Φ·x, P ← Φ·P·Φᵀ + Q; update with ν = z − θ, S = P₁₁ + r, K = P·Hᵀ/S,
// x ← x + K·ν and the Joseph form. The encoder is read in degrees, so the filter stays in
// the paper's units and its numbers compare directly with eq. 19.

#include <Eigen/Core>

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/linear_models.hpp"

namespace legofeup {

class WheelSpeedFilter {
  public:
    /// q_angle = Q₁₁ (°²), q_rate = Q₂₂ ((°/s)²), r = R (°²), p0: P₀ = p0·I.
    WheelSpeedFilter(double q_angle, double q_rate, double r, double p0);

    /// Starts at the given angle with ω = 0 and P = p0·I.
    void reset(double angle_deg);

    /// One period: predict over `period_s` (s), then update with the encoder angle (°).
    /// A non-finite or non-positive period, or a non-finite angle, leaves the filter as it
    /// was; so does an update whose result would not be finite.
    void step(double measured_angle_deg, double period_s);

    double angle_deg() const { return filter_.state()(0); }
    double rate_dps() const { return filter_.state()(1); }
    Eigen::Matrix2d covariance() const { return filter_.covariance(); }
    /// K of the last update (zero before the first).
    Eigen::Vector2d last_gain() const { return gain_; }

  private:
    double q_angle_;
    double q_rate_;
    double r_;
    double p0_;
    ExtendedKalmanFilter<EuclideanStateSpace<2>> filter_;
    Eigen::Vector2d gain_ = Eigen::Vector2d::Zero();
};

}  // namespace legofeup
