#pragma once
// Odometry with state-dependent noise, corrected by a magnetic compass (paper 004).
//
// Process (eq. 3, 6): the odometry motion of OdometryProcessModel plus pose noise,
//   X ← f(X, U) + G(θ)·q,   f = [x + ΔD·cos(θ + Δθ/2), y + ΔD·sin(θ + Δθ/2), θ + Δθ].
// (The printed eq. 6 reads θ + θ/2 in the cosine and sine and θ + θ/2 in the third row;
// both θ/2 must be Δθ/2 and the third row θ + Δθ, otherwise the robot would turn without
// moving its wheels.)
// Eq. 5 makes the noise covariance depend on the heading:
//   Q(θ) = diag(k_D·|ΔD·cos θ|, k_D·|ΔD·sin θ|, k_Dθ·|ΔD| + k_θ·|Δθ|)
// (absolute values: the printed expression goes negative when driving backwards or facing
// −x). The filters' hook noise_covariance() takes no state, so the heading enters through
// the noise Jacobian instead: q ~ N(0, Q̃) with
//   Q̃ = diag(k_D·|ΔD|, k_D·|ΔD|, k_Dθ·|ΔD| + k_θ·|Δθ|) + 10⁻¹²·I,
//   G(θ) = ∂f/∂q = diag(√|cos θ|, √|sin θ|, 1),   so G·Q̃·Gᵀ = Q(θ) (+ the floor).
// The EKF evaluates G at the prior estimate (exactly eq. 5 at the prior θ); the UKF
// propagates its noise sigma points through G at the prior θ too. The tiny floor keeps Q̃
// regular (the UKF factorises it) when the robot stands still.
//
// Measurement (eq. 11 restricted to the sensor we have): the compass measures θ directly,
// h(X) = θ, ∇h_X = [0 0 1], residual and sigma-point mean wrapped.

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "legofeup/core/angle_mean.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

/// Added to every variance of the compass lesson's Q so it is never singular.
inline constexpr double kCompassProcessNoiseFloor = 1e-12;

class CompassOdometryProcessModel {
  public:
    static constexpr int kNoiseSize = kStateSize;
    using NoiseVector = StateVector;
    using NoiseCovariance = StateCovariance;

    /// `increment` gives ΔD and Δθ (U, eq. 4).
    CompassOdometryProcessModel(const OdometryIncrement& increment, const CompassTuning& tuning);

    /// f(X, U) + G(θ)·q.
    StateVector propagate(const StateVector& x, const NoiseVector& noise) const;

    // Filter hooks.
    StateVector predict_state(const StateVector& x) const {
        return propagate(x, NoiseVector::Zero());
    }
    StateCovariance state_jacobian(const StateVector& x) const {
        return odometry_.state_jacobian(x);
    }
    /// G(θ) = diag(√|cos θ|, √|sin θ|, 1).
    StateCovariance noise_jacobian(const StateVector& x) const;
    /// Q̃ (the heading-free factor of eq. 5, plus the floor).
    const NoiseCovariance& noise_covariance() const { return q_; }

    /// Q(θ) = G·Q̃·Gᵀ: the pose noise of eq. 5 at the heading of `x` (for tests and plots).
    StateCovariance pose_noise(const StateVector& x) const;

  private:
    OdometryProcessModel odometry_;  // the same f and ∇f_X, its own noise unused
    NoiseCovariance q_;
};

class CompassMeasurement {
  public:
    static constexpr int kSize = 1;
    using Vector = Eigen::Matrix<double, 1, 1>;
    using Matrix = Eigen::Matrix<double, 1, 1>;
    using Jacobian = Eigen::Matrix<double, 1, kStateSize>;

    /// `heading_rad` the compass heading (rad, CCW from the world x axis); variance in rad².
    CompassMeasurement(double heading_rad, double variance);

    const Vector& measurement() const { return z_; }
    Vector predict_measurement(const StateVector& x) const { return Vector(x(kTheta)); }
    const Jacobian& jacobian(const StateVector& /*x*/) const { return h_; }
    const Matrix& noise_covariance() const { return r_; }
    /// a − b wrapped to (−π, π].
    Vector residual(const Vector& a, const Vector& b) const;
    template <std::size_t K>
    Vector weighted_mean(const std::array<Vector, K>& points,
                         const std::array<double, K>& weights) const {
        return Vector(weighted_angle_mean(points, weights, 0));
    }

  private:
    Vector z_;
    Matrix r_;
    Jacobian h_;
};

}  // namespace legofeup
