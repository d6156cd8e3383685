#include "legofeup/core/gyro_fusion_model.hpp"

#include <cmath>

namespace legofeup {

GyroFusionProcessModel::GyroFusionProcessModel(double period, double a, double alpha,
                                               const GyroFusionTuning& tuning)
    : period_(period), a_(a), alpha_(alpha), q_(NoiseCovariance::Zero()) {
    q_(kMotionX, kMotionX) = tuning.q_position;
    q_(kMotionY, kMotionY) = tuning.q_position;
    q_(kMotionTheta, kMotionTheta) = tuning.q_heading;
    q_(kMotionV, kMotionV) = tuning.q_v;
    q_(kMotionW, kMotionW) = tuning.q_w;
}

MotionStateVector GyroFusionProcessModel::propagate(const MotionStateVector& x,
                                                    const NoiseVector& noise) const {
    const double T = period_;
    const double v = x(kMotionV);
    const double w = x(kMotionW);
    const double phi = x(kMotionTheta) + 0.5 * w * T;  // φ = θ + ω·T/2
    MotionStateVector next = x + noise;
    next(kMotionX) += v * T * std::cos(phi);
    next(kMotionY) += v * T * std::sin(phi);
    next(kMotionTheta) = wrap_angle(next(kMotionTheta) + w * T);
    next(kMotionV) += T * a_;
    next(kMotionW) += T * alpha_;
    return next;
}

MotionCovariance GyroFusionProcessModel::state_jacobian(const MotionStateVector& x) const {
    const double T = period_;
    const double v = x(kMotionV);
    const double phi = x(kMotionTheta) + 0.5 * x(kMotionW) * T;
    const double c = std::cos(phi);
    const double s = std::sin(phi);
    MotionCovariance F = MotionCovariance::Identity();
    F(kMotionX, kMotionTheta) = -v * T * s;        // ∂x/∂θ
    F(kMotionX, kMotionV) = T * c;                 // ∂x/∂v
    F(kMotionX, kMotionW) = -v * T * s * 0.5 * T;  // ∂x/∂ω
    F(kMotionY, kMotionTheta) = v * T * c;         // ∂y/∂θ
    F(kMotionY, kMotionV) = T * s;                 // ∂y/∂v
    F(kMotionY, kMotionW) = v * T * c * 0.5 * T;   // ∂y/∂ω
    F(kMotionTheta, kMotionW) = T;                 // ∂θ/∂ω
    return F;
}

namespace {

// H of the encoders: picks v and ω.
Eigen::Matrix<double, 2, kMotionStateSize> encoder_rows() {
    Eigen::Matrix<double, 2, kMotionStateSize> h =
        Eigen::Matrix<double, 2, kMotionStateSize>::Zero();
    h(0, kMotionV) = 1.0;
    h(1, kMotionW) = 1.0;
    return h;
}

// H of the gyro: picks ω.
Eigen::Matrix<double, 1, kMotionStateSize> gyro_row() {
    Eigen::Matrix<double, 1, kMotionStateSize> h =
        Eigen::Matrix<double, 1, kMotionStateSize>::Zero();
    h(0, kMotionW) = 1.0;
    return h;
}

}  // namespace

EncoderVelocityMeasurement::EncoderVelocityMeasurement(const VelocityCommand& z, double r_v,
                                                       double r_w)
    : LinearMeasurement(Eigen::Vector2d(z.v, z.w), encoder_rows(),
                        Eigen::Vector2d(r_v, r_w).asDiagonal()) {}

GyroRateMeasurement::GyroRateMeasurement(double rate, double r)
    : LinearMeasurement(Eigen::Matrix<double, 1, 1>(rate), gyro_row(),
                        Eigen::Matrix<double, 1, 1>(r)) {}

}  // namespace legofeup
