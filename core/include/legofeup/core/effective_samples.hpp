#pragma once
// How many independent samples a correlated series is worth: what a time average of the NEES
// may be compared with. Consecutive NEES values of a filter are strongly correlated (the
// error changes little in one 50 ms step), so the average of N of them varies far more than
// the average of N independent χ²(n) values would, and the bounds of one step (or of N
// independent steps) say nothing about it.

#include <cstddef>
#include <span>

namespace legofeup {

struct EffectiveSamples {
    double count = 0.0;                 ///< N_eff = N / τ, clamped to [1, N]
    double autocorrelation_time = 1.0;  ///< τ = 1 + 2 Σ_{k=1}^{K} ρ_k
    std::size_t lags = 0;               ///< K, where the sum was truncated
};

/// N_eff of a series x_0 … x_{N−1} (treated as stationary):
///   ρ_k = c_k / c_0,  c_k = (1/N) Σ_{t=0}^{N−1−k} (x_t − x̄)(x_{t+k} − x̄)   (the biased estimate,
///   which keeps the sequence positive definite),
///   τ = 1 + 2 Σ_{k=1}^{K} ρ_k,  N_eff = N / τ.
/// Truncation (Geyer 1992, "initial positive sequence"): the autocorrelations are summed in
/// pairs Γ_m = ρ_{2m} + ρ_{2m+1} (ρ_0 = 1) for as long as the pairs stay positive, so
/// τ = −1 + 2 Σ_{m=0}^{M} Γ_m and K = 2M + 1 — the noisy tail beyond the first non-positive
/// pair is left out. At most kMaxAutocorrelationLag lags are summed (a longer correlation is
/// cut there, which makes N_eff too large and the bounds stricter, never looser).
/// An empty series gives count 0; a constant one (c_0 = 0) gives N_eff = N.
EffectiveSamples effective_sample_size(std::span<const double> series);

inline constexpr std::size_t kMaxAutocorrelationLag = 20000;

/// The effective samples of the weighted mean Σ wᵢ mᵢ / Σ wᵢ of independent time averages mᵢ,
/// each worth N_i samples: Var(mᵢ) ∝ 1/N_i, so Var(mean) ∝ Σ wᵢ² / N_i / (Σ wᵢ)², the variance
/// of an average of N = (Σ wᵢ)² / Σ (wᵢ² / N_i) independent samples. Equal weights (the mean
/// over seeds of per-seed averages) give N = S² / Σ 1/N_i, which is Σ N_i when every N_i is the
/// same; weights proportional to N_i give Σ N_i. Both spans have the same length; an N_i that
/// is not positive makes the result 0.
double pooled_effective_samples(std::span<const double> weights,
                                std::span<const double> effective_samples);

/// How much more independent time averages scatter about their mean than their effective
/// samples predict: the Pearson dispersion statistic of quasi-likelihood (McCullagh & Nelder,
/// Generalized Linear Models, §9.2). For a filter whose NEES is c·χ²(n), seed i's average mᵢ
/// is c·χ²(n·N_i)/N_i, so mᵢ/c has variance 2/(n·N_i), and
///   φ = 1/(S − 1) · Σᵢ (mᵢ/m̄ − 1)² · n·N_i / 2,   m̄ = Σ mᵢ / S,
/// is about 1 when that model holds and larger when the averages scatter more — as they do
/// when a seed's systematic errors (its robot's own wheels and sensors) repeat lap after lap,
/// so that one seed's average is not the N_i independent samples its autocorrelation counts.
/// Relative deviations make φ independent of c: an overconfident or a pessimistic filter is
/// not excused by its own larger (or smaller) scatter. NaN for fewer than two averages, a
/// mean that is not positive, or an N_i that is not positive.
double nees_dispersion(std::span<const double> averages, std::span<const double> effective_samples,
                       int dof);

/// The pooled effective samples of a mean of time averages, deflated by their dispersion
/// when it is above 1 (N / φ: the interval widens by √φ, about): what the interval of a mean
/// over seeds must use when the seeds differ more than the model says. Below 1 it is not
/// inflated, so the bounds are never narrower than the χ² model's.
double dispersion_corrected_samples(double pooled_effective_samples, double dispersion);

}  // namespace legofeup
