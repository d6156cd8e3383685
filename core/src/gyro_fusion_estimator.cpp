#include "legofeup/core/gyro_fusion_estimator.hpp"

#include "legofeup/core/chi_square.hpp"

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
    // The gyro first: the encoders are then judged against a state that already knows how
    // fast the body turns (both are linear measurements, so the order does not change the
    // estimate when both are used).
    const bool gyro_used = gyro_rate != nullptr && tuning.use_gyro;
    if (gyro_used) {
        result.gyro = filter_.update(GyroRateMeasurement(*gyro_rate, tuning.r_w_gyro)).status;
    }
    if (encoders != nullptr) {
        // Slip gate: wheels that turn while the gyro says the body does not (or the other
        // way round) give an innovation far outside its covariance.
        MahalanobisGate slip_gate;
        slip_gate.enabled = gyro_used && tuning.encoder_gate_probability > 0.0;
        if (slip_gate.enabled) {
            slip_gate.threshold = chi_square_quantile(tuning.encoder_gate_probability,
                                                      EncoderVelocityMeasurement::kSize);
        }
        result.encoders = filter_
                              .update(EncoderVelocityMeasurement(*encoders, tuning.r_v_encoders,
                                                                 tuning.r_w_encoders),
                                      slip_gate)
                              .status;
    }
    return result;
}

}  // namespace legofeup
