#include "legofeup/core/wheel_speed_filter.hpp"

#include <cmath>

namespace legofeup {

WheelSpeedFilter::WheelSpeedFilter(double q_angle, double q_rate, double r, double p0)
    : q_angle_(q_angle), q_rate_(q_rate), r_(r), p0_(p0) {
    reset(0.0);
}

void WheelSpeedFilter::reset(double angle_deg) {
    filter_.reset(Eigen::Vector2d(angle_deg, 0.0), p0_ * Eigen::Matrix2d::Identity());
    gain_.setZero();
}

void WheelSpeedFilter::step(double measured_angle_deg, double period_s) {
    if (!std::isfinite(measured_angle_deg) || !std::isfinite(period_s) || !(period_s > 0.0)) {
        return;
    }
    // Predict (eq. 17): Φ = e^{A·T} = [1 T; 0 1], Q = diag(q_angle, q_rate).
    Eigen::Matrix2d phi;
    phi << 1.0, period_s,  //
        0.0, 1.0;
    const Eigen::Matrix2d q = Eigen::Vector2d(q_angle_, q_rate_).asDiagonal();
    filter_.predict(LinearProcessModel<2>(phi, Eigen::Vector2d::Zero(), q));
    // Update (eq. 18): z = θ, H = [1 0].
    const auto report = filter_.update(
        LinearMeasurement<1, 2>(Eigen::Matrix<double, 1, 1>(measured_angle_deg),
                                Eigen::RowVector2d(1.0, 0.0), Eigen::Matrix<double, 1, 1>(r_)));
    if (report.status == StepStatus::Applied) {
        gain_ = report.gain;
    }
}

}  // namespace legofeup
