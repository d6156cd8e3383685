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
