#include "legofeup/core/wheel_speed_filter.hpp"

#include <cmath>

namespace legofeup {

WheelSpeedFilter::WheelSpeedFilter(double q_angle, double q_rate, double r, double p0)
    : q_angle_(q_angle), q_rate_(q_rate), r_(r), p0_(p0), P_(p0 * Eigen::Matrix2d::Identity()) {}

void WheelSpeedFilter::reset(double angle_deg) {
    x_ = Eigen::Vector2d(angle_deg, 0.0);
    P_ = p0_ * Eigen::Matrix2d::Identity();
    gain_.setZero();
}

void WheelSpeedFilter::step(double measured_angle_deg, double period_s) {
    if (!std::isfinite(measured_angle_deg) || !std::isfinite(period_s) || !(period_s > 0.0)) {
        return;
    }
    // Predict (eq. 17): Φ = e^{A·T} = [1 T; 0 1].
    Eigen::Matrix2d Phi;
    Phi << 1.0, period_s,  //
        0.0, 1.0;
    const Eigen::Vector2d x_pred = Phi * x_;
    Eigen::Matrix2d P_pred = Phi * P_ * Phi.transpose();
    P_pred(0, 0) += q_angle_;
    P_pred(1, 1) += q_rate_;

    // Update (eq. 18) with z = θ: S = H·P·Hᵀ + r = P₁₁ + r, K = P·Hᵀ/S = P(:, 0)/S.
    const double S = P_pred(0, 0) + r_;
    if (!(S > 0.0)) {
        return;
    }
    const Eigen::Vector2d K = P_pred.col(0) / S;
    const double innovation = measured_angle_deg - x_pred(0);  // ν = z − H·x
    const Eigen::Vector2d x_new = x_pred + K * innovation;
    Eigen::Matrix2d I_KH = Eigen::Matrix2d::Identity();
    I_KH.col(0) -= K;  // I − K·H with H = [1 0]
    Eigen::Matrix2d P_new = I_KH * P_pred * I_KH.transpose() + r_ * K * K.transpose();  // Joseph
    P_new = (0.5 * (P_new + P_new.transpose())).eval();
    if (!x_new.allFinite() || !P_new.allFinite()) {
        return;
    }
    x_ = x_new;
    P_ = P_new;
    gain_ = K;
}

}  // namespace legofeup
