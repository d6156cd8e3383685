#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "legofeup/core/body_velocity_filter.hpp"

namespace legofeup {
namespace {

/// The tuning these tests were worked out with (independent of the defaults).
VelocityKfTuning test_tuning() {
    VelocityKfTuning tuning;
    tuning.q_v = 2e-4;
    tuning.q_w = 2e-2;
    tuning.r_v = 1e-3;
    tuning.r_w = 0.5;
    tuning.p0 = 1e-2;
    return tuning;
}

TEST(BodyVelocityFilter, OneStepMatchesAHandCalculation) {
    const VelocityKfTuning tuning =
        test_tuning();  // q_v 2e-4, q_w 2e-2, r_v 1e-3, r_w 0.5, p0 1e-2
    BodyVelocityFilter filter(tuning);
    filter.reset();
    filter.predict(0.2, 1.0, 0.05);
    // Eq. 21: x = [0.05·0.2, 0.05·1.0] = [0.01, 0.05], P = diag(0.01 + 2e-4, 0.01 + 2e-2).
    EXPECT_NEAR(filter.estimate().v, 0.01, 1e-15);
    EXPECT_NEAR(filter.estimate().w, 0.05, 1e-15);
    EXPECT_NEAR(filter.covariance()(0, 0), 0.0102, 1e-15);
    EXPECT_NEAR(filter.covariance()(1, 1), 0.03, 1e-15);
    filter.update({0.02, 0.1});
    // Eq. 22, P and R diagonal: K = diag(0.0102/0.0112, 0.03/0.53);
    // v = 0.01 + K₁·0.01, ω = 0.05 + K₂·0.05; P = diag(0.0102·1e-3/0.0112, 0.03·0.5/0.53).
    EXPECT_NEAR(filter.estimate().v, 0.01 + 0.0102 / 0.0112 * 0.01, 1e-15);
    EXPECT_NEAR(filter.estimate().w, 0.05 + 0.03 / 0.53 * 0.05, 1e-15);
    EXPECT_NEAR(filter.covariance()(0, 0), 0.0102 * 1e-3 / 0.0112, 1e-15);
    EXPECT_NEAR(filter.covariance()(1, 1), 0.03 * 0.5 / 0.53, 1e-15);
    EXPECT_NEAR(filter.covariance()(0, 1), 0.0, 1e-18);
}

// A robot whose speeds follow v = 0.1·sin(0.5t) m/s, ω = 0.8·sin(0.3t) rad/s; the
// accelerometers give a, α with white noise (0.02 m/s², 0.2 rad/s²), the encoders give
// v, ω with the tuning's R (σ_v ≈ 0.032 m/s, σ_ω ≈ 0.71 rad/s). Over 20 seeds × 20 s
// (first 2 s skipped) the KF's RMS error must be below half the encoders' for both.
TEST(BodyVelocityFilter, WithAccelerationsBeatsTheRawEncoderSpeeds) {
    const VelocityKfTuning tuning = test_tuning();
    const double T = 0.05;
    double kf_v = 0.0, kf_w = 0.0, raw_v = 0.0, raw_w = 0.0;
    int count = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> normal(0.0, 1.0);
        BodyVelocityFilter filter(tuning);
        filter.reset();
        for (int k = 1; k <= 400; ++k) {
            const double t_prev = (k - 1) * T;
            const double t = k * T;
            const double a = 0.05 * std::cos(0.5 * t_prev) + 0.02 * normal(rng);
            const double alpha = 0.24 * std::cos(0.3 * t_prev) + 0.2 * normal(rng);
            const double v = 0.1 * std::sin(0.5 * t);
            const double w = 0.8 * std::sin(0.3 * t);
            const VelocityCommand encoders{v + std::sqrt(tuning.r_v) * normal(rng),
                                           w + std::sqrt(tuning.r_w) * normal(rng)};
            filter.predict(a, alpha, T);
            filter.update(encoders);
            if (k > 40) {
                kf_v += std::pow(filter.estimate().v - v, 2);
                kf_w += std::pow(filter.estimate().w - w, 2);
                raw_v += std::pow(encoders.v - v, 2);
                raw_w += std::pow(encoders.w - w, 2);
                ++count;
            }
        }
    }
    EXPECT_LT(std::sqrt(kf_v / count), 0.5 * std::sqrt(raw_v / count));
    EXPECT_LT(std::sqrt(kf_w / count), 0.5 * std::sqrt(raw_w / count));
}

TEST(BodyVelocityFilter, IgnoresNonFiniteInput) {
    BodyVelocityFilter filter(test_tuning());
    filter.reset();
    filter.predict(std::nan(""), 0.0, 0.05);
    filter.predict(0.1, 0.0, 0.0);
    filter.update({std::nan(""), 0.0});
    EXPECT_EQ(filter.estimate().v, 0.0);
    EXPECT_EQ(filter.covariance(), 1e-2 * Eigen::Matrix2d::Identity());
}

}  // namespace
}  // namespace legofeup
