#include "legofeup/core/pose_estimator_registry.hpp"

#include <array>
#include <stdexcept>

#include "legofeup/core/particle_filter.hpp"
#include "legofeup/core/pose_estimator_for.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"

namespace legofeup {
namespace {

template <class Filter, FilterKind kKind>
std::unique_ptr<PoseEstimator> make() {
    return std::make_unique<PoseEstimatorFor<Filter>>(kKind);
}

constexpr std::array kEstimators{
    PoseEstimatorEntry{FilterKind::Ekf, FilterKind::Ukf,
                       make<ExtendedKalmanFilter<PoseStateSpace>, FilterKind::Ekf>},
    PoseEstimatorEntry{FilterKind::Ukf, FilterKind::Ekf,
                       make<UnscentedKalmanFilter<PoseStateSpace>, FilterKind::Ukf>},
    PoseEstimatorEntry{FilterKind::Pf, FilterKind::Ekf, make<ParticleFilter, FilterKind::Pf>},
};

}  // namespace

std::span<const PoseEstimatorEntry> pose_estimators() {
    return kEstimators;
}

const PoseEstimatorEntry& pose_estimator_entry(FilterKind kind) {
    for (const PoseEstimatorEntry& entry : kEstimators) {
        if (entry.kind == kind) {
            return entry;
        }
    }
    throw std::invalid_argument(std::string("no pose estimator of kind ") + to_string(kind));
}

std::unique_ptr<PoseEstimator> make_pose_estimator(FilterKind kind) {
    return pose_estimator_entry(kind).make();
}

}  // namespace legofeup
