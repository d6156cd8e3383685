#pragma once
// Two-sided bounds on how many of n independent trials of probability p succeed, from the
// exact binomial distribution (no normal approximation), for tests that count events whose
// probability the design fixes (e.g. a gate at probability p rejects 1 − p of consistent
// measurements).

#include <cmath>

namespace legofeup::testing {

struct CountInterval {
    int lower = 0;
    int upper = 0;

    bool contains(int count) const { return count >= lower && count <= upper; }
};

/// P(X = k) for X ~ Binomial(n, p), 0 < p < 1, through log-gamma (no overflow for large n).
inline double binomial_probability(int n, int k, double p) {
    const double log_choose =
        std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0);
    return std::exp(log_choose + k * std::log(p) + (n - k) * std::log1p(-p));
}

/// [lower, upper] with P(X < lower) ≤ α/2 and P(X > upper) ≤ α/2, α = 1 − confidence, each as
/// tight as the discrete distribution allows: lower is the smallest k with P(X ≤ k) > α/2,
/// upper the smallest k with P(X ≤ k) ≥ 1 − α/2.
inline CountInterval binomial_interval(int n, double p, double confidence) {
    const double tail = 0.5 * (1.0 - confidence);
    CountInterval interval{-1, n};
    double cdf = 0.0;
    for (int k = 0; k <= n; ++k) {
        cdf += binomial_probability(n, k, p);
        if (interval.lower < 0 && cdf > tail) {
            interval.lower = k;
        }
        if (cdf >= 1.0 - tail) {
            interval.upper = k;
            break;
        }
    }
    return interval;
}

}  // namespace legofeup::testing
