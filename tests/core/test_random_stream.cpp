// The particle filter's random stream (random_stream.hpp): its normals against the normal
// distribution computed here from std::erfc — a chi-square test over bins that split the
// ziggurat's fast path, its wedges and its tail, the tail's share beyond r = 3.6541528853610088,
// the moments — and its uniforms and reproducibility from the seed. A wrong layer table, a
// wedge test with the wrong sign or a tail sampler off by r would each move some bins by
// many standard deviations.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "legofeup/core/random_stream.hpp"

namespace legofeup {
namespace {

constexpr double kNoBound = std::numeric_limits<double>::infinity();

/// P(X ≤ x) for X ~ N(0, 1), computed independently of the stream.
double normal_cdf(double x) {
    return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

TEST(RandomStream, NormalsFollowTheNormalDistributionBinByBin) {
    RandomStream stream(20261207);
    constexpr int kDraws = 2'000'000;
    // 80 bins of 0.1 over [−4, 4] plus the two tails beyond ±4: the fast path covers
    // |x| < 3.65 mostly, the wedges sit near every layer's edge, the tail is beyond 3.65.
    constexpr int kBins = 80;
    constexpr double kLow = -4.0;
    constexpr double kWidth = 0.1;
    std::vector<double> counts(kBins + 2, 0.0);
    double sum = 0.0;
    double sum_squares = 0.0;
    double sum_fourth = 0.0;
    int beyond_r = 0;
    for (int i = 0; i < kDraws; ++i) {
        const double x = stream.normal();
        ASSERT_TRUE(std::isfinite(x));
        sum += x;
        sum_squares += x * x;
        sum_fourth += x * x * x * x;
        beyond_r += std::abs(x) > 3.6541528853610088 ? 1 : 0;
        const double position = (x - kLow) / kWidth;
        const int bin = position < 0.0 ? 0 : position >= kBins ? kBins + 1 : 1 + int(position);
        counts[static_cast<std::size_t>(bin)] += 1.0;
    }
    double chi_square = 0.0;
    for (int bin = 0; bin < kBins + 2; ++bin) {
        const double lower = bin == 0 ? -kNoBound : kLow + (bin - 1) * kWidth;
        const double upper = bin == kBins + 1 ? kNoBound : kLow + bin * kWidth;
        const double expected = kDraws * (normal_cdf(upper) - normal_cdf(lower));
        const double deviation = counts[static_cast<std::size_t>(bin)] - expected;
        chi_square += deviation * deviation / expected;
    }
    // 81 degrees of freedom: mean 81, σ = √162 ≈ 12.7; the 0.999 quantile is 126.4.
    EXPECT_LT(chi_square, 126.4);
    const double n = kDraws;
    EXPECT_NEAR(sum / n, 0.0, 5.0 / std::sqrt(n));
    EXPECT_NEAR(sum_squares / n, 1.0, 5.0 * std::sqrt(2.0 / n));
    EXPECT_NEAR(sum_fourth / n, 3.0, 5.0 * std::sqrt(96.0 / n));  // Var(x⁴) = 105 − 9
    // The tail sampler's share: 2·(1 − Φ(r)) ≈ 2.58e-4, Poisson within 5σ.
    const double tail_expected = n * 2.0 * (1.0 - normal_cdf(3.6541528853610088));
    EXPECT_NEAR(beyond_r, tail_expected, 5.0 * std::sqrt(tail_expected));
}

TEST(RandomStream, TheTailBeyondRHasTheNormalsShape) {
    // Beyond r the draws come from the exact tail sampler alone: their mean excess over r
    // is E[X − r | X > r] = φ(r)/(1 − Φ(r)) − r, computed here.
    RandomStream stream(5);
    constexpr double r = 3.6541528853610088;
    double excess = 0.0;
    int count = 0;
    for (int i = 0; i < 8'000'000; ++i) {
        const double x = std::abs(stream.normal());
        if (x > r) {
            excess += x - r;
            ++count;
        }
    }
    const double density = std::exp(-0.5 * r * r) / std::sqrt(2.0 * M_PI);
    const double mean_excess = density / (1.0 - normal_cdf(r)) - r;  // ≈ 0.246
    ASSERT_GT(count, 1500);
    // The excess has a standard deviation close to its mean (nearly exponential).
    EXPECT_NEAR(excess / count, mean_excess, 5.0 * mean_excess / std::sqrt(count));
}

TEST(RandomStream, UniformsLieInTheUnitIntervalWithTheRightMoments) {
    RandomStream stream(11);
    constexpr int kDraws = 1'000'000;
    double sum = 0.0;
    double sum_squares = 0.0;
    for (int i = 0; i < kDraws; ++i) {
        const double u = stream.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
        sum_squares += u * u;
    }
    EXPECT_NEAR(sum / kDraws, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / kDraws));
    EXPECT_NEAR(sum_squares / kDraws, 1.0 / 3.0, 5.0 * std::sqrt(4.0 / 45.0 / kDraws));
}

TEST(RandomStream, TheGeneratorIsXoshiro256StarStarSeededBySplitmix64) {
    // xoshiro256** from the state {1, 2, 3, 4}, worked by hand from its definition:
    // out = rotl(s₁·5, 7)·9 = rotl(10, 7)·9 = 1280·9; then s = {7, 0, 262146, rotl(6, 45)}
    // and out = rotl(0, 7)·9 = 0; then s₁ = 0 ^ (262146 ^ 7) and so on.
    RandomStream known = RandomStream::from_state({1, 2, 3, 4});
    EXPECT_EQ(known.bits(), 11520U);
    EXPECT_EQ(known.bits(), 0U);
    const std::uint64_t s1 = 262146U ^ 7U;  // the third output scrambles this word
    EXPECT_EQ(known.bits(), std::rotl(s1 * 5U, 7) * 9U);
    // Seeding: splitmix64's first output from 0 is 0xe220a8397b1dcdaf (its published
    // reference value), so the stream seeded with 0 starts from that as s₀ and its second
    // output as s₁; the first draw scrambles s₁.
    std::uint64_t x = 0;
    const auto splitmix = [&x] {
        std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    };
    EXPECT_EQ(splitmix(), 0xe220a8397b1dcdafULL);
    const std::uint64_t second = splitmix();
    RandomStream seeded(0);
    EXPECT_EQ(seeded.bits(), std::rotl(second * 5U, 7) * 9U);
}

TEST(RandomStream, TheSameSeedGivesTheSameStreamAndAnotherSeedAnother) {
    RandomStream a(42);
    RandomStream b(42);
    RandomStream c(43);
    int differences = 0;
    for (int i = 0; i < 1000; ++i) {
        const double x = a.normal();
        EXPECT_EQ(x, b.normal());
        differences += x != c.normal() ? 1 : 0;
        EXPECT_EQ(a.uniform(), b.uniform());
        c.uniform();
    }
    EXPECT_EQ(differences, 1000);
    a.reseed(42);
    RandomStream fresh(42);
    EXPECT_EQ(a.normal(), fresh.normal());  // reseeding starts the stream again
}

}  // namespace
}  // namespace legofeup
