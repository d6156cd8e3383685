#include "legofeup/core/chi_square.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace legofeup {
namespace {

constexpr double kEpsilon = 1e-15;
constexpr int kMaxIterations = 1000;

// P(a, x) by its power series, good for x < a + 1:
//   P(a, x) = e^{−x} x^a / Γ(a) · Σ_{n≥0} x^n / (a (a+1) ⋯ (a+n)).
double lower_gamma_series(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < kMaxIterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * kEpsilon) {
            break;
        }
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) = 1 − P(a, x) by its continued fraction (modified Lentz), good for x ≥ a + 1:
//   Q(a, x) = e^{−x} x^a / Γ(a) · 1/(x+1−a− 1·(1−a)/(x+3−a− 2·(2−a)/(x+5−a− ⋯))).
double upper_gamma_fraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int n = 1; n < kMaxIterations; ++n) {
        const double an = -n * (n - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) {
            d = tiny;
        }
        c = b + an / c;
        if (std::abs(c) < tiny) {
            c = tiny;
        }
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEpsilon) {
            break;
        }
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

double regularized_lower_gamma(double a, double x) {
    if (x <= 0.0) {
        return 0.0;
    }
    if (x < a + 1.0) {
        return lower_gamma_series(a, x);
    }
    return 1.0 - upper_gamma_fraction(a, x);
}

// Density of χ²(k): x^{k/2−1} e^{−x/2} / (2^{k/2} Γ(k/2)), in logs to avoid overflow.
double chi_square_pdf(double x, double dof) {
    if (x <= 0.0) {
        return 0.0;
    }
    const double half = 0.5 * dof;
    return std::exp((half - 1.0) * std::log(x) - 0.5 * x - half * std::log(2.0)
                    - std::lgamma(half));
}

}  // namespace

double chi_square_cdf(double x, double dof) {
    if (!(dof > 0.0)) {
        throw std::invalid_argument("chi_square_cdf: degrees of freedom must be positive");
    }
    return regularized_lower_gamma(0.5 * dof, 0.5 * x);
}

double chi_square_quantile(double p, double dof) {
    if (!(p > 0.0 && p < 1.0)) {
        throw std::invalid_argument("chi_square_quantile: probability must be in (0, 1)");
    }
    if (!(dof > 0.0)) {
        throw std::invalid_argument("chi_square_quantile: degrees of freedom must be positive");
    }
    // Bracket the root of F(x) − p, then Newton steps (F' is the density), falling back to
    // bisection whenever a step leaves the bracket. F is increasing, so this converges.
    double low = 0.0;
    double high = std::max(1.0, dof);
    while (chi_square_cdf(high, dof) < p) {
        low = high;
        high *= 2.0;
    }
    double x = 0.5 * (low + high);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double error = chi_square_cdf(x, dof) - p;
        if (error > 0.0) {
            high = x;
        } else {
            low = x;
        }
        const double density = chi_square_pdf(x, dof);
        double next = density > 0.0 ? x - error / density : 0.5 * (low + high);
        if (!(next > low && next < high)) {
            next = 0.5 * (low + high);
        }
        if (std::abs(next - x) <= 1e-14 * std::max(1.0, x)) {
            return next;
        }
        x = next;
    }
    return x;
}

ChiSquareInterval average_chi_square_interval(int dof, int count, double confidence) {
    if (dof <= 0 || count <= 0 || !(confidence > 0.0 && confidence < 1.0)) {
        throw std::invalid_argument(
            "average_chi_square_interval: dof and count must be positive, confidence in (0, 1)");
    }
    return time_average_chi_square_interval(dof, static_cast<double>(count), confidence);
}

ChiSquareInterval time_average_chi_square_interval(int dof, double effective_samples,
                                                   double confidence) {
    if (dof <= 0 || !(effective_samples > 0.0) || !(confidence > 0.0 && confidence < 1.0)) {
        throw std::invalid_argument(
            "time_average_chi_square_interval: dof and effective samples must be positive, "
            "confidence in (0, 1)");
    }
    const double total_dof = static_cast<double>(dof) * effective_samples;
    const double tail = 0.5 * (1.0 - confidence);
    return {chi_square_quantile(tail, total_dof) / effective_samples,
            chi_square_quantile(1.0 - tail, total_dof) / effective_samples};
}

}  // namespace legofeup
