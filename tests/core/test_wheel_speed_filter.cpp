#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "legofeup/core/wheel_speed_filter.hpp"

namespace legofeup {
namespace {

// Paper 003 eq. 19 (right wheel): Q = diag(0.1, 10), R = 2.5, P₀ = 10·I, T = 0.05 s.
TEST(WheelSpeedFilter, FirstStepMatchesAHandCalculation) {
    WheelSpeedFilter filter(0.1, 10.0, 2.5, 10.0);
    filter.reset(0.0);
    filter.step(1.0, 0.05);
    // Predict: Φ = [1 0.05; 0 1], P⁻ = Φ·10I·Φᵀ + Q = [10 + 10·0.0025 + 0.1, 0.5; 0.5, 20]
    //        = [10.125 0.5; 0.5 20].
    // Update with z = 1: S = 10.125 + 2.5 = 12.625, K = [10.125, 0.5]/12.625
    //        = [0.80198…, 0.03960…]; x = K·(1 − 0).
    // P⁺ = (I − K·H)·P⁻: P₁₁ = 2.5·10.125/12.625, P₁₂ = 2.5·0.5/12.625, P₂₂ = 20 − 0.25/12.625.
    EXPECT_NEAR(filter.angle_deg(), 10.125 / 12.625, 1e-12);
    EXPECT_NEAR(filter.rate_dps(), 0.5 / 12.625, 1e-12);
    EXPECT_NEAR(filter.last_gain()(0), 10.125 / 12.625, 1e-12);
    const Eigen::Matrix2d P = filter.covariance();
    EXPECT_NEAR(P(0, 0), 2.5 * 10.125 / 12.625, 1e-12);
    EXPECT_NEAR(P(0, 1), 2.5 * 0.5 / 12.625, 1e-12);
    EXPECT_NEAR(P(1, 0), 2.5 * 0.5 / 12.625, 1e-12);
    EXPECT_NEAR(P(1, 1), 20.0 - 0.25 / 12.625, 1e-12);
}

TEST(WheelSpeedFilter, SteadyStateGainSolvesTheDiscreteRiccatiEquation) {
    const double T = 0.05;
    const double r = 1.5;
    // Independent iteration of P⁻ = Φ·P·Φᵀ + Q, K = P⁻·Hᵀ/(H·P⁻·Hᵀ + r), P = (I − K·H)·P⁻.
    Eigen::Matrix2d Phi;
    Phi << 1.0, T, 0.0, 1.0;
    const Eigen::Matrix2d Q = Eigen::Vector2d(0.1, 10.0).asDiagonal();
    const Eigen::RowVector2d H(1.0, 0.0);
    Eigen::Matrix2d P = 10.0 * Eigen::Matrix2d::Identity();
    Eigen::Vector2d K;
    for (int i = 0; i < 5000; ++i) {
        const Eigen::Matrix2d prior = Phi * P * Phi.transpose() + Q;
        K = prior * H.transpose() / (H * prior * H.transpose() + r);
        P = (Eigen::Matrix2d::Identity() - K * H) * prior;
    }
    WheelSpeedFilter filter(0.1, 10.0, r, 10.0);
    filter.reset(5.0);
    std::mt19937_64 rng(1);
    std::normal_distribution<double> noise(0.0, 3.0);
    for (int i = 0; i < 5000; ++i) {
        filter.step(5.0 + 400.0 * T * i + noise(rng), T);  // the gain does not depend on z
    }
    EXPECT_NEAR(filter.last_gain()(0), K(0), 1e-9);
    EXPECT_NEAR(filter.last_gain()(1), K(1), 1e-9);
    EXPECT_LT((filter.covariance() - P).cwiseAbs().maxCoeff(), 1e-9);
}

// A wheel at a constant 360 °/s read by an encoder with whole-degree counts and 1° Gaussian
// noise, T = 50 ms, 20 seeds of 20 s each (the first 2 s skipped). Differencing has an
// error of about √2·√(1 + 1/12)/T ≈ 29 °/s RMS; the KF with eq. 19's tuning averages over
// several periods: its RMS error must be below a fifth of that (measured: 2.1 °/s vs 30.2 °/s).
TEST(WheelSpeedFilter, BeatsDifferencingAQuantisedNoisyEncoder) {
    const double T = 0.05;
    const double rate = 360.0;
    double kf_squares = 0.0;
    double diff_squares = 0.0;
    int count = 0;
    for (unsigned seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> noise(0.0, 1.0);
        std::uniform_real_distribution<double> start(0.0, 360.0);
        const double angle0 = start(rng);
        const auto read = [&](int k) { return std::round(angle0 + rate * T * k + noise(rng)); };
        WheelSpeedFilter filter(0.1, 10.0, 2.5, 10.0);
        double previous = read(0);
        filter.reset(previous);
        for (int k = 1; k <= 400; ++k) {
            const double z = read(k);
            filter.step(z, T);
            const double differenced = (z - previous) / T;
            previous = z;
            if (k > 40) {
                kf_squares += std::pow(filter.rate_dps() - rate, 2);
                diff_squares += std::pow(differenced - rate, 2);
                ++count;
            }
        }
    }
    const double kf_rms = std::sqrt(kf_squares / count);
    const double diff_rms = std::sqrt(diff_squares / count);
    EXPECT_NEAR(diff_rms, 29.4, 3.0);
    EXPECT_LT(kf_rms, 0.2 * diff_rms) << "KF " << kf_rms << " °/s, differencing " << diff_rms;
}

TEST(WheelSpeedFilter, IgnoresNonFiniteInputAndBadPeriods) {
    WheelSpeedFilter filter(0.1, 10.0, 2.5, 10.0);
    filter.reset(3.0);
    filter.step(std::nan(""), 0.05);
    filter.step(4.0, 0.0);
    filter.step(4.0, -0.05);
    EXPECT_EQ(filter.angle_deg(), 3.0);
    EXPECT_EQ(filter.rate_dps(), 0.0);
    EXPECT_EQ(filter.covariance(), 10.0 * Eigen::Matrix2d::Identity());
}

}  // namespace
}  // namespace legofeup
