#pragma once
// The χ² distribution, for consistency bounds (NEES, NIS) and Mahalanobis gates.
// Computed from the regularised incomplete gamma function, not from a table.

namespace legofeup {

/// P(X ≤ x) for X ~ χ²(dof): the regularised lower incomplete gamma P(dof/2, x/2).
double chi_square_cdf(double x, double dof);

/// The p-quantile of χ²(dof), p in (0, 1): x with chi_square_cdf(x, dof) = p, to ~1e-12.
double chi_square_quantile(double p, double dof);

struct ChiSquareInterval {
    double lower = 0.0;
    double upper = 0.0;

    bool contains(double value) const { return value >= lower && value <= upper; }
};

/// Two-sided `confidence` interval for the average of `count` independent χ²(dof) values,
/// e.g. the NEES of an n-state filter averaged over N runs: [χ²_lo(N·n)/N, χ²_hi(N·n)/N]
/// (Bar-Shalom, Li & Kirubarajan, §5.4).
ChiSquareInterval average_chi_square_interval(int dof, int count, double confidence = 0.95);

}  // namespace legofeup
