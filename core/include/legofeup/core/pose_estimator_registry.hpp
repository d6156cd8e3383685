#pragma once
// The pose estimators the loop can run, one entry per FilterKind: its name, how to make one
// and which kind LessonFilters::compare_kinds runs beside it as the shadow. The loop looks
// the kind up here and holds the result as a PoseEstimator, so a new filter (the particle
// filter) is its own files plus one entry in pose_estimators() — no switch to extend.

#include <memory>
#include <span>

#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/pose_estimator.hpp"

namespace legofeup {

struct PoseEstimatorEntry {
    FilterKind kind;
    /// The kind compared with this one when compare_kinds is set.
    FilterKind shadow;
    /// A new estimator at x = 0, P = I with default settings (allocates: called when the
    /// kind changes, never in a step).
    std::unique_ptr<PoseEstimator> (*make)();
};

/// Every pose estimator, in FilterKind order.
std::span<const PoseEstimatorEntry> pose_estimators();

/// The entry of `kind` (every FilterKind has one; a test checks it).
const PoseEstimatorEntry& pose_estimator_entry(FilterKind kind);

std::unique_ptr<PoseEstimator> make_pose_estimator(FilterKind kind);

}  // namespace legofeup
