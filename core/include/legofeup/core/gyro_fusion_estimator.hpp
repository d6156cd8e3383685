#pragma once
// The 5-state EKF of paper 003 §3.4 run as the loop's localisation: X = [x, y, θ, v, ω],
// predicted with the accelerations as inputs (eq. 24) and corrected each period by the
// encoders' (v, ω) (eq. 14) and the gyroscope's ω.

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/gyro_fusion_model.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/motion_state_space.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct GyroFusionStep {
    StepStatus predict = StepStatus::NotAttempted;
    StepStatus encoders = StepStatus::NotAttempted;
    StepStatus gyro = StepStatus::NotAttempted;
};

class GyroFusionEstimator {
  public:
    /// Starts at `pose` with P0 = diag(P_pose, p_velocity·I) and (v, ω) = 0 (at rest).
    void reset(const StateVector& pose, const StateCovariance& pose_covariance,
               double velocity_variance);
    void set_limits(const CovarianceLimits& limits) { filter_.set_limits(limits); }

    /// One period: predict over `period` with the body acceleration (zero when unused), then
    /// update with the encoder velocities (if `encoders` is set) and the gyro rate (if set).
    GyroFusionStep step(double period, const VelocityCommand& acceleration,
                        const VelocityCommand* encoders, const double* gyro_rate,
                        const GyroFusionTuning& tuning);

    StateVector pose() const { return filter_.state().head<kStateSize>(); }
    StateCovariance pose_covariance() const {
        return filter_.covariance().topLeftCorner<kStateSize, kStateSize>();
    }
    VelocityCommand velocity() const {
        return {filter_.state()(kMotionV), filter_.state()(kMotionW)};
    }

  private:
    ExtendedKalmanFilter<MotionStateSpace> filter_;
};

}  // namespace legofeup
