#pragma once
// The Kalman filter for the robot's body velocities with accelerometer inputs
// (paper 003 §3.3, eq. 20–23).
//
// State x = [v, ω]ᵀ (m/s, rad/s) (eq. 20). The accelerations a and α (from the two
// accelerometers over the wheels, body_acceleration in extra_sensors.hpp) drive it (eq. 21):
//   x_k = x_{k−1} + T·[a; α] + w,      w ~ N(0, Q = diag(q_v, q_w))
// and the encoders' differentiated speeds (eq. 14) measure it directly (eq. 22):
//   z_k = [v; ω] + e,                  e ~ N(0, R = diag(r_v, r_w)),  H = I
// Run by the ExtendedKalmanFilter with linear models (linear_models.hpp): S = P + R (LDLT),
// K = P·S⁻¹, x ← x + K·(z − x), Joseph form for P.

#include <Eigen/Core>

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/linear_models.hpp"
#include "legofeup/core/motion.hpp"

namespace legofeup {

class BodyVelocityFilter {
  public:
    explicit BodyVelocityFilter(const VelocityKfTuning& tuning);

    /// New Q and R (and P₀ for the next reset); the state is kept.
    void set_tuning(const VelocityKfTuning& tuning);
    /// x = 0, P = p0·I.
    void reset();

    /// Eq. 21 over `period_s` with accelerations a (m/s²) and α (rad/s²). Non-finite inputs
    /// or a non-positive period leave the filter unchanged.
    void predict(double a, double alpha, double period_s);
    /// Eq. 22 with (v, ω) from the encoders. Non-finite input leaves the filter unchanged.
    void update(const VelocityCommand& from_encoders);

    VelocityCommand estimate() const { return {filter_.state()(0), filter_.state()(1)}; }
    Eigen::Matrix2d covariance() const { return filter_.covariance(); }

  private:
    VelocityKfTuning tuning_;
    ExtendedKalmanFilter<EuclideanStateSpace<2>> filter_;
};

}  // namespace legofeup
