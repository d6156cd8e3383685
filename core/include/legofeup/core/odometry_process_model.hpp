#pragma once
// The odometry motion model of the EKF prediction (paper eq. 10–13).
//
//   f(X, U, q) = X + [ (d + ε_d)·cos(θ + (Δθ + ε_Δθ)/2) ]
//                    [ (d + ε_d)·sin(θ + (Δθ + ε_Δθ)/2) ]
//                    [  Δθ + ε_Δθ                       ]      q = [ε_d, ε_Δθ] ~ N(0, Q)
//
// With φ = θ + Δθ/2 the Jacobians at q = 0 are
//   ∇f_X = [1 0 −d·sin φ; 0 1 d·cos φ; 0 0 1]
//   ∇f_q = [cos φ −½d·sin φ; sin φ ½d·cos φ; 0 1]
// (the printed eq. 13 omits both third rows; eq. 10's third row reads θ + Δθ + ε_Δθ).

#include <Eigen/Core>

#include "legofeup/core/odometry.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

class OdometryProcessModel {
  public:
    static constexpr int kNoiseSize = 2;
    using NoiseVector = Eigen::Vector2d;
    using NoiseCovariance = Eigen::Matrix2d;
    using NoiseJacobian = Eigen::Matrix<double, kStateSize, kNoiseSize>;

    /// `increment` is U (through d and Δθ); `q` is Q, the covariance of [ε_d, ε_Δθ] for
    /// this control period (m², rad²).
    OdometryProcessModel(const OdometryIncrement& increment, const NoiseCovariance& q)
        : distance_(increment.distance), rotation_(increment.rotation), q_(q) {}

    /// f(X, U, q) for any noise value (used to check the Jacobians).
    StateVector propagate(const StateVector& x, const NoiseVector& noise) const;

    // Filter hooks.
    StateVector predict_state(const StateVector& x) const {
        return propagate(x, NoiseVector::Zero());
    }
    StateCovariance state_jacobian(const StateVector& x) const;
    NoiseJacobian noise_jacobian(const StateVector& x) const;

    /// The three hooks above at once, with one cos φ and one sin φ instead of three of each
    /// (they were half of the EKF's prediction); bit for bit the same values.
    struct Linearisation {
        StateVector state;               ///< f(X, U, 0)
        StateCovariance state_jacobian;  ///< ∇f_X
        NoiseJacobian noise_jacobian;    ///< ∇f_q
    };
    Linearisation linearise(const StateVector& x) const;
    const NoiseCovariance& noise_covariance() const { return q_; }

  private:
    double distance_;  // d
    double rotation_;  // Δθ
    NoiseCovariance q_;
};

}  // namespace legofeup
