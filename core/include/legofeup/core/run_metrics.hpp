#pragma once
// How well a run localised: errors against the ground truth, the filter's consistency (NEES)
// and what happened to the observations. Pure computation; the truth comes from the
// simulator's separate channel and never reaches the filter.

#include <array>
#include <cstdint>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/loop_snapshot.hpp"

namespace legofeup {

inline constexpr int kAssociationOutcomeCount = 6;

struct RunMetrics {
    std::uint64_t steps = 0;
    double duration = 0.0;  ///< simulated seconds from the first to the last step

    double rms_position_error = 0.0;    ///< m
    double max_position_error = 0.0;    ///< m
    double final_position_error = 0.0;  ///< m
    double rms_heading_error = 0.0;     ///< rad
    double max_heading_error = 0.0;     ///< rad
    double final_heading_error = 0.0;   ///< rad
    /// The odometry-only estimate from the same counts, for comparison.
    double rms_odometry_position_error = 0.0;
    double final_odometry_position_error = 0.0;

    std::uint64_t observations = 0;  ///< steps with both IR readings in range
    std::array<std::uint64_t, kAssociationOutcomeCount> association_outcomes{};
    std::uint64_t updates_applied = 0;
    std::uint64_t updates_rejected = 0;  ///< associated, but refused by the filter (gate, …)
    /// How far an applied update moves the estimate on average (|W·ν|): large when the
    /// filter jumps to every reading, near zero when it ignores them.
    double mean_update_position_step = 0.0;  ///< m
    double mean_update_heading_step = 0.0;   ///< rad
    /// RMS distance between the estimate and the odometry-only estimate: near zero when
    /// the updates have no effect.
    double rms_estimate_to_odometry = 0.0;  ///< m

    double mean_nees = 0.0;
    ChiSquareInterval nees_bounds;      ///< 95 % two-sided interval of one χ²(3) value
    double nees_inside_fraction = 0.0;  ///< share of steps with NEES inside nees_bounds
    double mean_nis = 0.0;              ///< over applied updates (χ²(2) when consistent)
};

class RunMetricsAccumulator {
  public:
    RunMetricsAccumulator();

    /// Adds one step: the loop's snapshot and where the robot really was.
    void add(const LoopSnapshot& snapshot, const Pose2& truth);

    RunMetrics result() const;

  private:
    RunMetrics metrics_;
    double first_time_ = 0.0;
    double sum_position_squared_ = 0.0;
    double sum_heading_squared_ = 0.0;
    double sum_odometry_squared_ = 0.0;
    double sum_nees_ = 0.0;
    std::uint64_t nees_count_ = 0;
    std::uint64_t nees_inside_ = 0;
    double sum_nis_ = 0.0;
    double sum_update_position_step_ = 0.0;
    double sum_update_heading_step_ = 0.0;
    double sum_estimate_to_odometry_squared_ = 0.0;
};

}  // namespace legofeup
