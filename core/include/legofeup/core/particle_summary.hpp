#pragma once
// What the particle filter says about its cloud each step, beside the mean and covariance
// every filter publishes: the plots of N_eff and the particle count, the trace's pf_*
// columns and the lesson mcl's checks read it. A Gaussian filter's summary is empty
// (count 0).

#include <cstdint>

namespace legofeup {

struct ParticleSummary {
    int count = 0;  ///< particles in the cloud (0: not a particle filter)
    /// N_eff = 1 / Σ wᵢ² of the last update's weights, before the resampling they may have
    /// triggered (the value the resampling test compares with resample_threshold·N); before
    /// the cloud's first update, of its weights now (N for a new cloud).
    double effective = 0.0;
    /// The share of the weight within kNearMeanRadius of the weighted mean position: about 1
    /// for one tight cluster, well below 1 for a cloud split in two (the twin halls) or
    /// spread over a building (global localisation).
    double near_mean_share = 0.0;
    bool resampled = false;  ///< the last update resampled the cloud
    int injected = 0;  ///< particles the last update replaced by free-space draws (augmented MCL)
    double w_slow = 0.0;  ///< the long-term average likelihood (augmented MCL)
    double w_fast = 0.0;  ///< the short-term one
};

/// m: the radius of ParticleSummary::near_mean_share.
inline constexpr double kNearMeanRadius = 0.5;

}  // namespace legofeup
