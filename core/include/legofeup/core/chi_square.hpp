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

/// Two-sided `confidence` interval for a time average of correlated χ²(dof) values worth
/// `effective_samples` independent ones (effective_samples.hpp): the average of N_eff
/// independent χ²(dof) values is χ²(N_eff·dof)/N_eff, so
///   [χ²_{α/2}(N_eff·dof) / N_eff, χ²_{1−α/2}(N_eff·dof) / N_eff],
/// N_eff any real ≥ 1 (χ² of a non-integer number of degrees of freedom is the gamma
/// distribution it always was). The same mean (dof) and variance (2·dof/N_eff) as the time
/// average of a consistent filter's NEES — a two-moment match, as Satterthwaite's.
ChiSquareInterval time_average_chi_square_interval(int dof, double effective_samples,
                                                   double confidence = 0.95);

}  // namespace legofeup
