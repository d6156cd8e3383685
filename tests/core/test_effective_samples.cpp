// The effective number of independent samples of a correlated series (effective_samples.hpp),
// on series whose autocorrelation is known analytically, and the coverage of the time-average
// χ² bounds built on it over many synthetic runs.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "binomial_interval.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/effective_samples.hpp"

namespace legofeup {
namespace {

/// x_t = φ x_{t−1} + √(1 − φ²) e_t, e_t ~ N(0, 1), started from its stationary N(0, 1):
/// a stationary Gaussian series with unit variance and ρ_k = φ^k.
class Ar1 {
  public:
    Ar1(double phi, std::mt19937_64& rng) : phi_(phi), rng_(rng), x_(normal_(rng)) {}
    double next() {
        const double value = x_;
        x_ = phi_ * x_ + std::sqrt(1.0 - phi_ * phi_) * normal_(rng_);
        return value;
    }

  private:
    double phi_;
    std::mt19937_64& rng_;
    std::normal_distribution<double> normal_;
    double x_;
};

std::vector<double> ar1_series(double phi, std::size_t n, std::mt19937_64& rng) {
    Ar1 ar(phi, rng);
    std::vector<double> series(n);
    for (double& x : series) {
        x = ar.next();
    }
    return series;
}

/// A consistent 3-state filter's NEES with correlated errors: ε_t = Σ_{i<3} x_{i,t}² of three
/// independent unit AR(1) series, so ε_t ~ χ²(3) at every step, and corr(ε_t, ε_{t+k}) =
/// corr(x_t², x_{t+k}²) = ρ_k² = φ^{2k} (Isserlis): τ = (1 + φ²)/(1 − φ²).
std::vector<double> correlated_nees(double phi, std::size_t n, std::mt19937_64& rng) {
    std::vector<double> nees(n, 0.0);
    for (int i = 0; i < 3; ++i) {
        Ar1 ar(phi, rng);
        for (double& value : nees) {
            const double x = ar.next();
            value += x * x;
        }
    }
    return nees;
}

double mean_of(const std::vector<double>& values) {
    double sum = 0.0;
    for (const double v : values) {
        sum += v;
    }
    return sum / static_cast<double>(values.size());
}

TEST(EffectiveSamples, Ar1SeriesHaveTheirAnalyticAutocorrelationTime) {
    // τ = 1 + 2 Σ φ^k = (1 + φ)/(1 − φ), N_eff = N (1 − φ)/(1 + φ). One estimate's relative
    // standard deviation is about √(2(2K+1)/N) (K the lags summed, several τ); averaged over
    // 8 independent series of 100 000 steps it is under 3 % for φ ≤ 0.97, so 8 % is ≥ 3σ.
    std::mt19937_64 rng(20201);
    constexpr std::size_t n = 100000;
    constexpr int series = 8;
    for (const double phi : {0.0, 0.5, 0.9, 0.97}) {
        double tau_sum = 0.0;
        double count_sum = 0.0;
        for (int i = 0; i < series; ++i) {
            const EffectiveSamples effective = effective_sample_size(ar1_series(phi, n, rng));
            tau_sum += effective.autocorrelation_time;
            count_sum += effective.count;
        }
        const double tau = (1.0 + phi) / (1.0 - phi);
        EXPECT_NEAR(tau_sum / series, tau, 0.08 * tau) << "φ = " << phi;
        EXPECT_NEAR(count_sum / series, static_cast<double>(n) / tau, 0.10 * n / tau)
            << "φ = " << phi;
    }
}

TEST(EffectiveSamples, SquaredAr1SeriesHaveTheSquaredAutocorrelation) {
    std::mt19937_64 rng(20202);
    constexpr std::size_t n = 100000;
    for (const double phi : {0.8, 0.95}) {
        const EffectiveSamples effective = effective_sample_size(correlated_nees(phi, n, rng));
        const double tau = (1.0 + phi * phi) / (1.0 - phi * phi);
        EXPECT_NEAR(effective.autocorrelation_time, tau, 0.10 * tau) << "φ = " << phi;
    }
}

TEST(EffectiveSamples, EdgeCases) {
    EXPECT_EQ(effective_sample_size(std::vector<double>{}).count, 0.0);
    EXPECT_EQ(effective_sample_size(std::vector<double>{4.2}).count, 1.0);
    EXPECT_EQ(effective_sample_size(std::vector<double>(50, 3.0)).count, 50.0);
    // Alternating: ρ_1 ≈ −1, τ would be ≈ 0 — never more samples than there are.
    std::vector<double> alternating(100);
    for (std::size_t t = 0; t < alternating.size(); ++t) {
        alternating[t] = t % 2 == 0 ? 1.0 : -1.0;
    }
    const EffectiveSamples effective = effective_sample_size(alternating);
    EXPECT_LE(effective.count, 100.0);
    EXPECT_GE(effective.count, 1.0);
    // A trend (a diverging filter): correlated over the whole run, worth very few samples.
    std::vector<double> trend(1000);
    for (std::size_t t = 0; t < trend.size(); ++t) {
        trend[t] = static_cast<double>(t);
    }
    EXPECT_LT(effective_sample_size(trend).count, 10.0);
}

TEST(EffectiveSamples, PoolingWeighsEachAverageByItsVariance) {
    const std::vector<double> equal{1.0, 1.0};
    // Equal weights: N = S² / Σ 1/N_i = 4 / (1/10 + 1/40) = 32, not 10 + 40.
    EXPECT_DOUBLE_EQ(pooled_effective_samples(equal, std::vector<double>{10.0, 40.0}), 32.0);
    EXPECT_DOUBLE_EQ(pooled_effective_samples(equal, std::vector<double>{25.0, 25.0}), 50.0);
    // Weights ∝ N_i (the minimum-variance mean): Σ N_i.
    EXPECT_DOUBLE_EQ(
        pooled_effective_samples(std::vector<double>{10.0, 40.0}, std::vector<double>{10.0, 40.0}),
        50.0);
    EXPECT_EQ(pooled_effective_samples(equal, std::vector<double>{10.0, 0.0}), 0.0);
    EXPECT_THROW(pooled_effective_samples(equal, std::vector<double>{1.0}), std::invalid_argument);
}

// How many of `runs` synthetic consistent runs have their time average inside the bounds
// built from their own N_eff; `scale` multiplies the NEES (a pessimistic filter's is smaller,
// an overconfident one's larger).
int runs_inside(int runs, double phi, std::size_t steps, double scale, std::mt19937_64& rng) {
    int inside = 0;
    for (int run = 0; run < runs; ++run) {
        std::vector<double> nees = correlated_nees(phi, steps, rng);
        for (double& value : nees) {
            value *= scale;
        }
        const double n_eff = effective_sample_size(nees).count;
        inside += time_average_chi_square_interval(3, n_eff).contains(mean_of(nees)) ? 1 : 0;
    }
    return inside;
}

TEST(EffectiveSamples, TimeAverageBoundsCoverAConsistentFiltersMeanNees) {
    // 1000 runs of 2000 correlated steps (τ ≈ 10, N_eff ≈ 200, like a lesson's run): about
    // 95 % inside. The binomial 99.9 % interval of 1000 draws at 0.95 is about [0.925, 0.97];
    // the N_eff estimate's own error costs a little coverage, which the interval allows.
    std::mt19937_64 rng(20203);
    constexpr int runs = 1000;
    const int inside = runs_inside(runs, 0.9, 2000, 1.0, rng);
    const testing::CountInterval expected = testing::binomial_interval(runs, 0.95, 0.999);
    EXPECT_GE(inside, expected.lower) << inside << " of " << runs;
    EXPECT_LE(inside, expected.upper) << inside << " of " << runs;
    // The one-step bounds [0.216, 9.348] would hold every one of them — and also filters whose
    // NEES is 10× too small or 3× too large. The time-average bounds hold none of those.
    EXPECT_EQ(runs_inside(200, 0.9, 2000, 0.1, rng), 0);
    EXPECT_EQ(runs_inside(200, 0.9, 2000, 3.0, rng), 0);
}

TEST(EffectiveSamples, PooledBoundsCoverTheMeanOverSeedsOfTimeAverages) {
    // As grading does: the mean over 20 seeds of each seed's mean NEES, against
    // χ²(3N)/N with N = 20² / Σ 1/N_i. Seeds of different lengths, so the N_i differ.
    std::mt19937_64 rng(20204);
    constexpr int groups = 300;
    constexpr int seeds = 20;
    int inside = 0;
    for (int group = 0; group < groups; ++group) {
        std::vector<double> means;
        std::vector<double> effective;
        for (int seed = 0; seed < seeds; ++seed) {
            const std::vector<double> nees =
                correlated_nees(0.9, static_cast<std::size_t>(600 + 40 * seed), rng);
            means.push_back(mean_of(nees));
            effective.push_back(effective_sample_size(nees).count);
        }
        const double pooled = pooled_effective_samples(std::vector<double>(seeds, 1.0), effective);
        inside += time_average_chi_square_interval(3, pooled).contains(mean_of(means)) ? 1 : 0;
    }
    const testing::CountInterval expected = testing::binomial_interval(groups, 0.95, 0.999);
    EXPECT_GE(inside, expected.lower) << inside << " of " << groups;
    EXPECT_LE(inside, expected.upper) << inside << " of " << groups;
}

TEST(NeesDispersion, HandWorkedAndItsEdgeCases) {
    // m = (2, 4), N = (10, 10), n = 3: m̄ = 3, (mᵢ/m̄ − 1)² = 1/9 each, times n·N/2 = 15:
    // Σ = 10/3 over S − 1 = 1.
    EXPECT_NEAR(nees_dispersion(std::vector<double>{2.0, 4.0}, std::vector<double>{10.0, 10.0}, 3),
                10.0 / 3.0, 1e-12);
    // Each term weighs its own N: (1/9)·(3·10/2) + (1/9)·(3·40/2) = 75/9.
    EXPECT_NEAR(nees_dispersion(std::vector<double>{2.0, 4.0}, std::vector<double>{10.0, 40.0}, 3),
                75.0 / 9.0, 1e-12);
    // Scaled averages (a filter off by a factor) scatter alike in relative terms.
    EXPECT_NEAR(
        nees_dispersion(std::vector<double>{20.0, 40.0}, std::vector<double>{10.0, 10.0}, 3),
        10.0 / 3.0, 1e-12);
    EXPECT_TRUE(std::isnan(nees_dispersion(std::vector<double>{3.0}, std::vector<double>{9.0}, 3)));
    EXPECT_TRUE(std::isnan(
        nees_dispersion(std::vector<double>{3.0, 3.0}, std::vector<double>{9.0, 0.0}, 3)));
    EXPECT_THROW(nees_dispersion(std::vector<double>{3.0, 3.0}, std::vector<double>{9.0}, 3),
                 std::invalid_argument);
    EXPECT_EQ(dispersion_corrected_samples(1000.0, 2.0), 500.0);
    EXPECT_EQ(dispersion_corrected_samples(1000.0, 0.7), 1000.0);  // never narrower
    EXPECT_EQ(dispersion_corrected_samples(1000.0, std::nan("")), 1000.0);
}

// Groups of 20 seeds of correlated NEES, as grading sees them, (a) from a consistent filter,
// (b) from one whose seeds differ more than their autocorrelation says (each seed's NEES
// scaled by its own factor, relative spread 10 %: a robot's own systematic errors), (c) from
// an overconfident one (NEES × 1.2) with that spread. The corrected interval keeps its
// coverage in (a), about 0.95 and not much more, restores it in (b), where the χ² model's
// alone falls short, and still refuses (c).
TEST(NeesDispersion, CorrectedBoundsCoverSeedsThatDifferAndStillRefuseAnOverconfidentFilter) {
    struct Coverage {
        int model = 0;
        int corrected = 0;
        double mean_dispersion = 0.0;
    };
    const auto coverage_of = [](double spread, double factor, std::uint64_t seed) {
        std::mt19937_64 rng(seed);
        std::lognormal_distribution<double> own(0.0, spread);
        constexpr int groups = 300;
        constexpr int seeds = 20;
        Coverage counted;
        for (int group = 0; group < groups; ++group) {
            std::vector<double> means;
            std::vector<double> effective;
            for (int s = 0; s < seeds; ++s) {
                std::vector<double> nees =
                    correlated_nees(0.9, static_cast<std::size_t>(600 + 40 * s), rng);
                const double scale = factor * (spread > 0.0 ? own(rng) : 1.0);
                for (double& value : nees) {
                    value *= scale;
                }
                means.push_back(mean_of(nees));
                effective.push_back(effective_sample_size(nees).count);
            }
            const double pooled =
                pooled_effective_samples(std::vector<double>(seeds, 1.0), effective);
            const double dispersion = nees_dispersion(means, effective, 3);
            counted.mean_dispersion += dispersion / groups;
            const double mean = mean_of(means);
            counted.model += time_average_chi_square_interval(3, pooled).contains(mean) ? 1 : 0;
            counted.corrected += time_average_chi_square_interval(
                                     3, dispersion_corrected_samples(pooled, dispersion))
                                         .contains(mean)
                                     ? 1
                                     : 0;
        }
        return counted;
    };
    const testing::CountInterval expected = testing::binomial_interval(300, 0.95, 0.999);
    const Coverage consistent = coverage_of(0.0, 1.0, 811);
    EXPECT_NEAR(consistent.mean_dispersion, 1.0, 0.15);
    EXPECT_GE(consistent.corrected, expected.lower);
    EXPECT_LE(consistent.corrected, 299);  // wider only when the seeds say so
    const Coverage differing = coverage_of(0.10, 1.0, 812);
    EXPECT_GT(differing.mean_dispersion, 1.5);
    EXPECT_LT(differing.model, expected.lower) << "the premise: the χ² model alone falls short";
    EXPECT_GE(differing.corrected, expected.lower);
    const Coverage overconfident = coverage_of(0.10, 1.2, 813);
    EXPECT_LT(overconfident.corrected, 15) << "of 300 groups";
}

}  // namespace
}  // namespace legofeup
