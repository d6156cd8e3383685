#pragma once
// The prediction of the laser lesson (paper 001 eq. 4–5, 11–13): the pose advances by the
// odometry increment expressed in the world frame, and the process noise is added directly
// to the pose with a static and a motion-dependent part.
//
// The loop's odometry gives the increment in the robot frame (d, Δθ, eq. 7–9 of the
// LegoFeup paper). Rotated into the world at the heading being predicted from, along the
// centred-difference heading φ = θ + Δθ/2:
//   Δx_odom = d·cos φ,   Δy_odom = d·sin φ,   Δθ_odom = Δθ
// Eq. 11:  f(X, U) = X + [Δx_odom, Δy_odom, Δθ_odom]ᵀ       (+ q, additive pose noise)
// Eq. 12:  F = ∂f/∂X = [1 0 −Δy_odom; 0 1 Δx_odom; 0 0 1]   (∂Δx/∂θ = −d·sin φ = −Δy)
// Eq. 13:  Q = diag(q_x,stat + q_x,dyn·|Δx_odom|,
//                   q_y,stat + q_y,dyn·|Δy_odom|,
//                   q_θ,stat + q_θ,dyn·|Δθ_odom|)
// Eq. 5:   P ← F·P·Fᵀ + Q   (the noise Jacobian is I: Q is already in state space)
//
// Q depends on the heading through |Δx_odom| and |Δy_odom|; the filters' noise hook takes
// no state, so the model is built for one step from the prior estimate's heading and Q is
// evaluated there (exactly the paper's Q(k) at X̂(k|k)). The UKF propagates its sigma
// points through f with that same Q added.

#include <Eigen/Core>

#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

class LaserProcessModel {
  public:
    static constexpr int kNoiseSize = kStateSize;
    using NoiseVector = StateVector;
    using NoiseCovariance = StateCovariance;

    /// `increment` is this period's odometry (d, Δθ); `prior_heading` the heading of the
    /// estimate the prediction starts from (where Q of eq. 13 is evaluated).
    LaserProcessModel(const OdometryIncrement& increment, double prior_heading,
                      const LaserTuning& tuning);

    /// [Δx_odom, Δy_odom, Δθ_odom] of this period when predicting from heading `theta`.
    StateVector world_increment(double theta) const;
    /// Eq. 13 evaluated at heading `theta`.
    StateCovariance process_noise(double theta) const;

    /// f(X, U) + q (eq. 11 with the noise added to the pose).
    StateVector propagate(const StateVector& x, const NoiseVector& noise) const;

    // Filter hooks.
    StateVector predict_state(const StateVector& x) const {
        return propagate(x, NoiseVector::Zero());
    }
    /// Eq. 12.
    StateCovariance state_jacobian(const StateVector& x) const;
    /// I: eq. 13's Q is added to the pose directly.
    StateCovariance noise_jacobian(const StateVector& /*x*/) const {
        return StateCovariance::Identity();
    }
    /// Eq. 13 at the prior heading.
    const NoiseCovariance& noise_covariance() const { return q_; }

  private:
    double distance_;  // d
    double rotation_;  // Δθ
    StateVector q_static_;
    StateVector q_dynamic_;
    NoiseCovariance q_;
};

}  // namespace legofeup
