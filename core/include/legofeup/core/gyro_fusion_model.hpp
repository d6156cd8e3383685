#pragma once
// The models of the 5-state EKF that fuses encoders, accelerometers and a gyroscope
// (paper 003 §3.4, eq. 24–26), state X = [x, y, θ, v, ω] (motion_state_space.hpp).
//
// Process (eq. 24), over one period T with accelerations a, α as inputs (0 without
// accelerometers: then v and ω are modelled constant) and φ = θ + ω·T/2:
//   x ← x + v·T·cos φ,  y ← y + v·T·sin φ,  θ ← θ + ω·T,  v ← v + T·a,  ω ← ω + T·α,
// plus additive noise q ~ N(0, Q = diag(q_position, q_position, q_heading, q_v, q_w)).
// Jacobian ∇f_X = I except
//   ∂x/∂θ = −v·T·sin φ   ∂x/∂v = T·cos φ   ∂x/∂ω = −v·T·sin φ·T/2
//   ∂y/∂θ =  v·T·cos φ   ∂y/∂v = T·sin φ   ∂y/∂ω =  v·T·cos φ·T/2
//   ∂θ/∂ω = T;                              ∇f_q = I.
//
// Measurements, applied one after the other in the same period:
//   EncoderVelocityMeasurement  z = [v, ω] from the differentiated encoders (eq. 14)
//   GyroRateMeasurement         z = ω from the gyroscope
// The paper instead integrates the encoder and gyro rates and measures θ twice (eq. 25).
// We measure the rates: an integrated angle carries all past rate errors, so successive
// "measurements" of θ have errors that are strongly correlated in time (a random walk),
// while the Kalman filter assumes white measurement noise; it would then trust the
// integrated angles far too much. The rates themselves have (nearly) independent errors
// from period to period, and θ is integrated once, by the process model, where its
// growing uncertainty is accounted for in P.

#include <Eigen/Core>

#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/linear_models.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/motion_state_space.hpp"

namespace legofeup {

class GyroFusionProcessModel {
  public:
    static constexpr int kNoiseSize = kMotionStateSize;
    using NoiseVector = MotionStateVector;
    using NoiseCovariance = MotionCovariance;

    /// `period` T (s), `a` (m/s²) and `alpha` (rad/s²) the inputs of eq. 24.
    GyroFusionProcessModel(double period, double a, double alpha, const GyroFusionTuning& tuning);

    /// f(X, U) + q (used by the UKF and to check the Jacobians).
    MotionStateVector propagate(const MotionStateVector& x, const NoiseVector& noise) const;

    // Filter hooks.
    MotionStateVector predict_state(const MotionStateVector& x) const {
        return propagate(x, NoiseVector::Zero());
    }
    MotionCovariance state_jacobian(const MotionStateVector& x) const;
    MotionCovariance noise_jacobian(const MotionStateVector& /*x*/) const {
        return MotionCovariance::Identity();
    }
    const NoiseCovariance& noise_covariance() const { return q_; }

  private:
    double period_;  // T
    double a_;
    double alpha_;
    NoiseCovariance q_;
};

/// (v, ω) from the differentiated encoders: h(X) = [v, ω].
class EncoderVelocityMeasurement : public LinearMeasurement<2, kMotionStateSize> {
  public:
    /// r_v in (m/s)², r_w in (rad/s)².
    EncoderVelocityMeasurement(const VelocityCommand& z, double r_v, double r_w);
};

/// The gyroscope's turn rate (rad/s, CCW): h(X) = ω.
class GyroRateMeasurement : public LinearMeasurement<1, kMotionStateSize> {
  public:
    /// r in (rad/s)².
    GyroRateMeasurement(double rate, double r);
};

}  // namespace legofeup
