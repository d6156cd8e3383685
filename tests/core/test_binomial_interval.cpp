// The exact binomial bounds of support/binomial_interval.hpp, against hand-worked values.

#include <gtest/gtest.h>

#include <cmath>

#include "binomial_interval.hpp"

namespace legofeup {
namespace {

using testing::binomial_interval;
using testing::binomial_probability;

TEST(BinomialInterval, ProbabilitiesMatchHandWorkedValuesAndSumToOne) {
    // C(5, 3)·0.2³·0.8² = 10 · 0.008 · 0.64.
    EXPECT_NEAR(binomial_probability(5, 3, 0.2), 0.0512, 1e-14);
    EXPECT_NEAR(binomial_probability(10, 0, 0.5), 1.0 / 1024.0, 1e-15);
    double total = 0.0;
    for (int k = 0; k <= 3000; ++k) {
        total += binomial_probability(3000, k, 0.1);
    }
    // lgamma(3001) ≈ 2.1e4 is rounded to ≈ 2e4·2⁻⁵³ ≈ 2e-12, which each probability carries
    // as a relative error.
    EXPECT_NEAR(total, 1.0, 1e-10);
}

TEST(BinomialInterval, TailsOfTenFairCoins) {
    // P(X ≤ k)·1024 = 1, 11, 56, 176, 386, 638, 848, 968, 1013, 1023, 1024. At 90 % each tail
    // may hold 5 %: P(X ≤ 1) = 0.011 ≤ 0.05 < P(X ≤ 2) = 0.055, so lower = 2;
    // P(X ≤ 7) = 0.945 < 0.95 ≤ P(X ≤ 8) = 0.989, so upper = 8.
    const testing::CountInterval interval = binomial_interval(10, 0.5, 0.9);
    EXPECT_EQ(interval.lower, 2);
    EXPECT_EQ(interval.upper, 8);
    EXPECT_TRUE(interval.contains(2));
    EXPECT_FALSE(interval.contains(9));
}

TEST(BinomialInterval, LargeCountsApproachTheNormalApproximation) {
    // Binomial(3000, 0.1): 300 ± 3.29·√270 at 99.9 % (±1 count for the skew and the steps).
    const testing::CountInterval interval = binomial_interval(3000, 0.1, 0.999);
    const double half_width = 3.2905 * std::sqrt(3000 * 0.1 * 0.9);
    EXPECT_NEAR(interval.lower, 300.0 - half_width, 1.5);
    EXPECT_NEAR(interval.upper, 300.0 + half_width, 1.5);
}

}  // namespace
}  // namespace legofeup
