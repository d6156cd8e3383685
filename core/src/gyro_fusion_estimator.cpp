#include "legofeup/core/gyro_fusion_estimator.hpp"

namespace legofeup {

void GyroFusionEstimator::reset(const StateVector& pose, const StateCovariance& pose_covariance,
                                double velocity_variance) {
    MotionStateVector x = MotionStateVector::Zero();
    x.head<kStateSize>() = pose;
    MotionCovariance P = MotionCovariance::Zero();
    P.topLeftCorner<kStateSize, kStateSize>() = pose_covariance;
    P(kMotionV, kMotionV) = velocity_variance;
    P(kMotionW, kMotionW) = velocity_variance;
    filter_.reset(x, P);
}

GyroFusionStep GyroFusionEstimator::step(double period, const VelocityCommand& acceleration,
                                         const VelocityCommand* encoders, const double* gyro_rate,
                                         const GyroFusionTuning& tuning) {
    GyroFusionStep result;
    const VelocityCommand input = tuning.use_accelerometers ? acceleration : VelocityCommand{};
    // Eq. 24 with w ~ N(0, Q).
    result.predict = filter_.predict(GyroFusionProcessModel(period, input.v, input.w, tuning));
    if (encoders != nullptr) {
        result.encoders = filter_
                              .update(EncoderVelocityMeasurement(*encoders, tuning.r_v_encoders,
                                                                 tuning.r_w_encoders))
                              .status;
    }
    if (gyro_rate != nullptr && tuning.use_gyro) {
        result.gyro = filter_.update(GyroRateMeasurement(*gyro_rate, tuning.r_w_gyro)).status;
    }
    return result;
}

}  // namespace legofeup
