#pragma once
// Everything a pose estimator is tuned with (PoseEstimator::configure); each filter takes
// what applies to it: the covariance guard's limits (all), the unscented spread (UKF), the
// particle filter's tuning, random seed and free space (PF).

#include <cstdint>
#include <memory>

#include "legofeup/core/covariance_guard.hpp"
#include "legofeup/core/free_space.hpp"
#include "legofeup/core/lesson_filters_config.hpp"

namespace legofeup {

struct PoseEstimatorSettings {
    CovarianceLimits limits;
    UkfParams ukf;
    ParticleFilterTuning particles;
    /// The particle filter's random stream starts from this seed at every reset.
    std::uint64_t seed = 1;
    /// Where global localisation and recovery draw poses from (null or empty: recovery
    /// cannot inject, and reset_uniform is refused).
    std::shared_ptr<const FreeSpace> free_space;
};

}  // namespace legofeup
