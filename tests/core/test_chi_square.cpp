#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "legofeup/core/chi_square.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

TEST(ChiSquare, TwoDegreesOfFreedomHaveAClosedForm) {
    // χ²(2) is exponential with mean 2: F(x) = 1 − e^{−x/2}, quantile −2·ln(1 − p).
    for (double p = 0.001; p < 1.0; p += 0.01) {
        EXPECT_NEAR(chi_square_quantile(p, 2.0), -2.0 * std::log(1.0 - p), 1e-9) << p;
    }
    for (double x = 0.0; x < 40.0; x += 0.37) {
        EXPECT_NEAR(chi_square_cdf(x, 2.0), 1.0 - std::exp(-x / 2.0), 1e-13) << x;
    }
}

TEST(ChiSquare, OneAndFourDegreesOfFreedomMatchTheirClosedForms) {
    for (double x = 0.01; x < 30.0; x += 0.23) {
        EXPECT_NEAR(chi_square_cdf(x, 1.0), std::erf(std::sqrt(x / 2.0)), 1e-13) << x;
        EXPECT_NEAR(chi_square_cdf(x, 4.0), 1.0 - std::exp(-x / 2.0) * (1.0 + x / 2.0), 1e-13) << x;
    }
}

TEST(ChiSquare, QuantileInvertsTheCdf) {
    testing::Uniform uniform(51);
    for (int i = 0; i < 2000; ++i) {
        const double dof = std::round(uniform(1.0, 600.0));
        const double p = uniform(1e-6, 1.0 - 1e-6);
        const double x = chi_square_quantile(p, dof);
        EXPECT_NEAR(chi_square_cdf(x, dof), p, 1e-10) << "dof " << dof << " p " << p;
    }
}

TEST(ChiSquare, ReproducesThePublishedConsistencyBounds) {
    // scenario.md (Bar-Shalom et al.): 95 % two-sided bounds of the average NEES / NIS.
    struct Row {
        int dof, count;
        double lower, upper;
    };
    const Row rows[] = {{3, 1, 0.216, 9.348},  {3, 10, 1.679, 4.698},  {3, 25, 2.118, 4.034},
                        {3, 50, 2.360, 3.716}, {3, 100, 2.539, 3.499}, {2, 1, 0.051, 7.378},
                        {2, 50, 1.484, 2.591}, {2, 100, 1.627, 2.411}};
    for (const Row& row : rows) {
        const ChiSquareInterval bounds = average_chi_square_interval(row.dof, row.count, 0.95);
        EXPECT_NEAR(bounds.lower, row.lower, 6e-4) << row.dof << "×" << row.count;
        EXPECT_NEAR(bounds.upper, row.upper, 6e-4) << row.dof << "×" << row.count;
    }
}

TEST(ChiSquare, LargeDegreesOfFreedomMatchTheTables) {
    // NIST/SEMATECH e-Handbook, table 1.3.6.7.4 (100), and the standard tables (1000).
    EXPECT_NEAR(chi_square_quantile(0.025, 100.0), 74.222, 1e-3);
    EXPECT_NEAR(chi_square_quantile(0.975, 100.0), 129.561, 1e-3);
    EXPECT_NEAR(chi_square_quantile(0.025, 1000.0), 914.257, 1e-3);
    EXPECT_NEAR(chi_square_quantile(0.975, 1000.0), 1089.531, 1e-3);
}

// P(X ≤ x) by Simpson's rule on the density, an independent calculation of the CDF for any
// real dof ≥ 6 (the density is smooth enough at 0 for the rule's h⁴ error): x^{k/2−1} e^{−x/2} /
// (2^{k/2} Γ(k/2)).
double cdf_by_simpson(double x, double dof) {
    constexpr int intervals = 20000;
    const auto density = [dof](double t) {
        if (t <= 0.0) {
            return 0.0;
        }
        return std::exp((0.5 * dof - 1.0) * std::log(t) - 0.5 * t - 0.5 * dof * std::log(2.0)
                        - std::lgamma(0.5 * dof));
    };
    const double h = x / intervals;
    double sum = density(0.0) + density(x);
    for (int i = 1; i < intervals; ++i) {
        sum += (i % 2 == 1 ? 4.0 : 2.0) * density(i * h);
    }
    return sum * h / 3.0;
}

TEST(ChiSquare, NonIntegerDegreesOfFreedomMatchAnIntegratedDensity) {
    // N_eff·n is rarely an integer: the quantiles there must be right too.
    for (const double dof : {6.5, 7.3, 31.7, 150.6, 2121.9}) {
        for (const double p : {0.025, 0.5, 0.975}) {
            const double x = chi_square_quantile(p, dof);
            EXPECT_NEAR(cdf_by_simpson(x, dof), p, 1e-8) << "dof " << dof << " p " << p;
        }
    }
}

TEST(ChiSquare, TimeAverageIntervalOfAWholeCountIsTheAverageInterval) {
    const ChiSquareInterval whole = average_chi_square_interval(3, 40, 0.95);
    const ChiSquareInterval time = time_average_chi_square_interval(3, 40.0, 0.95);
    EXPECT_DOUBLE_EQ(time.lower, whole.lower);
    EXPECT_DOUBLE_EQ(time.upper, whole.upper);
    // Between two whole counts, between their intervals (the interval narrows as N grows).
    const ChiSquareInterval between = time_average_chi_square_interval(3, 40.5, 0.95);
    const ChiSquareInterval next = average_chi_square_interval(3, 41, 0.95);
    EXPECT_GT(between.lower, whole.lower);
    EXPECT_LT(between.lower, next.lower);
    EXPECT_LT(between.upper, whole.upper);
    EXPECT_GT(between.upper, next.upper);
    EXPECT_THROW(time_average_chi_square_interval(3, 0.0), std::invalid_argument);
}

TEST(ChiSquare, IntervalContainsItsBounds) {
    const ChiSquareInterval interval{1.0, 2.0};
    EXPECT_TRUE(interval.contains(1.0));
    EXPECT_TRUE(interval.contains(1.5));
    EXPECT_FALSE(interval.contains(2.5));
}

TEST(ChiSquare, RejectsMeaninglessArguments) {
    EXPECT_THROW(chi_square_quantile(0.0, 2.0), std::invalid_argument);
    EXPECT_THROW(chi_square_quantile(1.0, 2.0), std::invalid_argument);
    EXPECT_THROW(chi_square_quantile(0.5, 0.0), std::invalid_argument);
    EXPECT_THROW(chi_square_cdf(1.0, -1.0), std::invalid_argument);
    EXPECT_THROW(average_chi_square_interval(3, 0), std::invalid_argument);
    EXPECT_THROW(average_chi_square_interval(3, 10, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace legofeup
