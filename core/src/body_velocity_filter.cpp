#include "legofeup/core/body_velocity_filter.hpp"

#include <cmath>

namespace legofeup {

BodyVelocityFilter::BodyVelocityFilter(const VelocityKfTuning& tuning) : tuning_(tuning) {
    reset();
}

void BodyVelocityFilter::set_tuning(const VelocityKfTuning& tuning) {
    tuning_ = tuning;
}

void BodyVelocityFilter::reset() {
    filter_.reset(Eigen::Vector2d::Zero(), tuning_.p0 * Eigen::Matrix2d::Identity());
}

void BodyVelocityFilter::predict(double a, double alpha, double period_s) {
    if (!std::isfinite(period_s) || !(period_s > 0.0)) {
        return;
    }
    // Eq. 21: Φ = I, input T·[a; α], Q = diag(q_v, q_w). Non-finite inputs are refused by
    // the filter (x and P unchanged).
    const Eigen::Matrix2d q = Eigen::Vector2d(tuning_.q_v, tuning_.q_w).asDiagonal();
    filter_.predict(LinearProcessModel<2>(Eigen::Matrix2d::Identity(),
                                          period_s * Eigen::Vector2d(a, alpha), q));
}

void BodyVelocityFilter::update(const VelocityCommand& from_encoders) {
    // Eq. 22: z = (v, ω) from the encoders, H = I, R = diag(r_v, r_w).
    const Eigen::Matrix2d r = Eigen::Vector2d(tuning_.r_v, tuning_.r_w).asDiagonal();
    filter_.update(LinearMeasurement<2, 2>(Eigen::Vector2d(from_encoders.v, from_encoders.w),
                                           Eigen::Matrix2d::Identity(), r));
}

}  // namespace legofeup
