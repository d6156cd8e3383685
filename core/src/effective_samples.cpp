#include "legofeup/core/effective_samples.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

namespace legofeup {

EffectiveSamples effective_sample_size(std::span<const double> series) {
    const std::size_t n = series.size();
    if (n == 0) {
        return {0.0, 1.0, 0};
    }
    double mean = 0.0;
    for (const double x : series) {
        mean += x;
    }
    mean /= static_cast<double>(n);
    std::vector<double> centred(series.begin(), series.end());
    for (double& x : centred) {
        x -= mean;
    }
    // c_k · N (the 1/N cancels in ρ_k = c_k / c_0).
    const auto autocovariance = [&](std::size_t lag) {
        double sum = 0.0;
        for (std::size_t t = 0; t + lag < n; ++t) {
            sum += centred[t] * centred[t + lag];
        }
        return sum;
    };
    const double c0 = autocovariance(0);
    if (!(c0 > 0.0)) {
        return {static_cast<double>(n), 1.0, 0};
    }
    const std::size_t max_lag = std::min(n - 1, kMaxAutocorrelationLag);
    // τ = −1 + 2 Σ_m Γ_m, Γ_m = ρ_{2m} + ρ_{2m+1}, while Γ_m > 0.
    double tau = -1.0;
    std::size_t lags = 0;
    for (std::size_t m = 0; 2 * m + 1 <= max_lag; ++m) {
        const double even = m == 0 ? 1.0 : autocovariance(2 * m) / c0;
        const double pair = even + autocovariance(2 * m + 1) / c0;
        if (!(pair > 0.0)) {
            break;
        }
        tau += 2.0 * pair;
        lags = 2 * m + 1;
    }
    if (lags == 0) {
        tau = 1.0;  // ρ_1 ≤ −1: no positive pair; count the series as independent
    }
    const double count = std::clamp(static_cast<double>(n) / tau, 1.0, static_cast<double>(n));
    return {count, tau, lags};
}

double pooled_effective_samples(std::span<const double> weights,
                                std::span<const double> effective_samples) {
    if (weights.size() != effective_samples.size()) {
        throw std::invalid_argument("pooled_effective_samples: one weight per time average");
    }
    double weight_sum = 0.0;
    double variance_sum = 0.0;  // Σ wᵢ² / N_i
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (!(effective_samples[i] > 0.0)) {
            return 0.0;
        }
        weight_sum += weights[i];
        variance_sum += weights[i] * weights[i] / effective_samples[i];
    }
    return variance_sum > 0.0 ? weight_sum * weight_sum / variance_sum : 0.0;
}

double nees_dispersion(std::span<const double> averages, std::span<const double> effective_samples,
                       int dof) {
    if (averages.size() != effective_samples.size()) {
        throw std::invalid_argument("nees_dispersion: one effective sample count per average");
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (averages.size() < 2) {
        return nan;
    }
    double sum = 0.0;
    for (const double m : averages) {
        sum += m;
    }
    const double mean = sum / static_cast<double>(averages.size());
    if (!(mean > 0.0)) {
        return nan;
    }
    double pearson = 0.0;  // Σ (mᵢ/m̄ − 1)² / (2 / (n·N_i))
    for (std::size_t i = 0; i < averages.size(); ++i) {
        if (!(effective_samples[i] > 0.0)) {
            return nan;
        }
        const double deviation = averages[i] / mean - 1.0;
        pearson += deviation * deviation * static_cast<double>(dof) * effective_samples[i] / 2.0;
    }
    return pearson / static_cast<double>(averages.size() - 1);
}

double dispersion_corrected_samples(double pooled_effective_samples, double dispersion) {
    return dispersion > 1.0 ? pooled_effective_samples / dispersion : pooled_effective_samples;
}

}  // namespace legofeup
