// The accelerometer bias estimate (accelerometer_bias.hpp) against hand calculations: with
// readings that are exactly the wheels' speed change plus a bias, b̂ = b·t/(t + τ₀) whatever
// the speed profile; at rest it is the readings' mean shrunk by the prior; bad input is
// ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "legofeup/core/accelerometer_bias.hpp"

namespace legofeup {
namespace {

constexpr double kBiasPeriod = 0.05;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPriorTau = AccelerometerBiasEstimator::kPriorSeconds;

// A speed profile with starts, stops and reversals: u(t) = 0.1·sin(0.7·t) + 0.05·sin(2.3·t).
double profile_speed(double t, double scale) {
    return scale * (0.1 * std::sin(0.7 * t) + 0.05 * std::sin(2.3 * t));
}

TEST(AccelerometerBias, ExactReadingsGiveTheBiasShrunkByThePrior) {
    AccelerometerBiasEstimator estimator;
    const double b_right = 0.03;
    const double b_left = -0.02;
    estimator.add({0.0, 0.0}, {profile_speed(0.0, 1.0), profile_speed(0.0, -1.0)},
                  kBiasPeriod);  // the reference
    int periods = 0;
    for (int k = 1; k <= 600; ++k) {
        const double t0 = (k - 1) * kBiasPeriod;
        const double t1 = k * kBiasPeriod;
        // The mean acceleration over the period: (u(t1) − u(t0))/T, plus the bias.
        const double a_right =
            (profile_speed(t1, 1.0) - profile_speed(t0, 1.0)) / kBiasPeriod + b_right;
        const double a_left =
            (profile_speed(t1, -1.0) - profile_speed(t0, -1.0)) / kBiasPeriod + b_left;
        estimator.add({a_right, a_left}, {profile_speed(t1, 1.0), profile_speed(t1, -1.0)},
                      kBiasPeriod);
        ++periods;
    }
    const double t = periods * kBiasPeriod;  // 30 s
    EXPECT_NEAR(estimator.bias()[0], b_right * t / (t + kPriorTau), 1e-12);
    EXPECT_NEAR(estimator.bias()[1], b_left * t / (t + kPriorTau), 1e-12);
}

TEST(AccelerometerBias, AtRestItIsTheMeanOfTheReadingsWithThePriorsWeight) {
    AccelerometerBiasEstimator estimator;
    EXPECT_EQ(estimator.bias()[0], 0.0);                 // nothing seen: the prior, 0
    estimator.add({1.0, 1.0}, {0.0, 0.0}, kBiasPeriod);  // reference only
    EXPECT_EQ(estimator.bias()[0], 0.0);
    // Readings 0.1, 0.2, 0.3, 0.4 at rest: Σ a·T = 0.05, t = 0.2 s.
    for (const double a : {0.1, 0.2, 0.3, 0.4}) {
        estimator.add({a, -a}, {0.0, 0.0}, kBiasPeriod);
    }
    EXPECT_NEAR(estimator.bias()[0], 0.05 / (0.2 + kPriorTau), 1e-15);
    EXPECT_NEAR(estimator.bias()[1], -0.05 / (0.2 + kPriorTau), 1e-15);
}

TEST(AccelerometerBias, NoiseAveragesOutAsTheSquareRootOfTheTime) {
    // σ_n = 0.1 m/s² (the simulated 2 counts) over 200 s: σ(b̂) ≈ σ_n·√(T/t) = 0.0016 m/s².
    std::mt19937 random(7);
    std::normal_distribution<double> noise(0.0, 0.1);
    AccelerometerBiasEstimator estimator;
    estimator.add({0.0, 0.0}, {0.0, 0.0}, kBiasPeriod);
    const int periods = 4000;
    for (int k = 1; k <= periods; ++k) {
        const double t0 = (k - 1) * kBiasPeriod;
        const double t1 = k * kBiasPeriod;
        const double a = (profile_speed(t1, 1.0) - profile_speed(t0, 1.0)) / kBiasPeriod + 0.025;
        estimator.add({a + noise(random), a + noise(random)},
                      {profile_speed(t1, 1.0), profile_speed(t1, 1.0)}, kBiasPeriod);
    }
    const double sigma = 0.1 * std::sqrt(kBiasPeriod / (periods * kBiasPeriod));
    EXPECT_NEAR(estimator.bias()[0], 0.025, 4.0 * sigma);
    EXPECT_NEAR(estimator.bias()[1], 0.025, 4.0 * sigma);
}

TEST(AccelerometerBias, BadInputIsIgnoredAndResetForgets) {
    AccelerometerBiasEstimator estimator;
    estimator.add({0.0, 0.0}, {0.0, 0.0}, kBiasPeriod);
    estimator.add({0.5, 0.5}, {0.0, 0.0}, kBiasPeriod);
    const double before = estimator.bias()[0];
    estimator.add({kNaN, 0.0}, {0.0, 0.0}, kBiasPeriod);
    estimator.add({0.5, 0.5}, {kInfinity, 0.0}, kBiasPeriod);
    estimator.add({0.5, 0.5}, {0.0, 0.0}, 0.0);
    estimator.add({0.5, 0.5}, {0.0, 0.0}, kNaN);
    EXPECT_EQ(estimator.bias()[0], before);
    EXPECT_GT(before, 0.0);
    estimator.reset();
    EXPECT_EQ(estimator.bias()[0], 0.0);
}

}  // namespace
}  // namespace legofeup
