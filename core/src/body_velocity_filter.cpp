#include "legofeup/core/body_velocity_filter.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace legofeup {

BodyVelocityFilter::BodyVelocityFilter(const VelocityKfTuning& tuning)
    : tuning_(tuning), P_(tuning.p0 * Eigen::Matrix2d::Identity()) {}

void BodyVelocityFilter::set_tuning(const VelocityKfTuning& tuning) {
    tuning_ = tuning;
}

void BodyVelocityFilter::reset() {
    x_.setZero();
    P_ = tuning_.p0 * Eigen::Matrix2d::Identity();
}

void BodyVelocityFilter::predict(double a, double alpha, double period_s) {
    if (!std::isfinite(a) || !std::isfinite(alpha) || !std::isfinite(period_s)
        || !(period_s > 0.0)) {
        return;
    }
    // Eq. 21: the transition is I, so P ← P + Q.
    const Eigen::Vector2d x_new = x_ + period_s * Eigen::Vector2d(a, alpha);
    Eigen::Matrix2d P_new = P_;
    P_new(0, 0) += tuning_.q_v;
    P_new(1, 1) += tuning_.q_w;
    if (!x_new.allFinite() || !P_new.allFinite()) {
        return;
    }
    x_ = x_new;
    P_ = P_new;
}

void BodyVelocityFilter::update(const VelocityCommand& from_encoders) {
    const Eigen::Vector2d z(from_encoders.v, from_encoders.w);
    const Eigen::Matrix2d R = Eigen::Vector2d(tuning_.r_v, tuning_.r_w).asDiagonal();
    if (!z.allFinite() || !R.allFinite()) {
        return;
    }
    // Eq. 22 with H = I: S = P + R, K = P·S⁻¹ = (S⁻¹·P)ᵀ (P, S symmetric).
    Eigen::Matrix2d S = P_ + R;
    S = (0.5 * (S + S.transpose())).eval();
    const Eigen::LDLT<Eigen::Matrix2d> ldlt(S);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0.0).all()) {
        return;
    }
    const Eigen::Matrix2d K = ldlt.solve(P_).transpose();
    const Eigen::Vector2d x_new = x_ + K * (z - x_);
    const Eigen::Matrix2d I_K = Eigen::Matrix2d::Identity() - K;
    Eigen::Matrix2d P_new = I_K * P_ * I_K.transpose() + K * R * K.transpose();  // Joseph
    P_new = (0.5 * (P_new + P_new.transpose())).eval();
    if (!x_new.allFinite() || !P_new.allFinite()) {
        return;
    }
    x_ = x_new;
    P_ = P_new;
}

}  // namespace legofeup
