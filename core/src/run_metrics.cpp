#include "legofeup/core/run_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/core/consistency.hpp"

namespace legofeup {

static_assert(static_cast<int>(AssociationOutcome::DistanceMismatch) + 1
                  == kAssociationOutcomeCount,
              "kAssociationOutcomeCount must count every AssociationOutcome");

RunMetricsAccumulator::RunMetricsAccumulator() {
    metrics_.nees_bounds = average_chi_square_interval(kStateSize, 1, 0.95);
}

void RunMetricsAccumulator::add(const LoopSnapshot& snapshot, const Pose2& truth) {
    RunMetrics& m = metrics_;
    if (m.steps == 0) {
        first_time_ = snapshot.time;
    }
    ++m.steps;
    m.duration = snapshot.time - first_time_;

    const double position_error =
        std::hypot(truth.x - snapshot.estimate(kX), truth.y - snapshot.estimate(kY));
    const double heading_error = std::abs(wrap_angle(truth.theta - snapshot.estimate(kTheta)));
    const double odometry_error =
        std::hypot(truth.x - snapshot.odometry_pose.x, truth.y - snapshot.odometry_pose.y);
    sum_position_squared_ += position_error * position_error;
    sum_heading_squared_ += heading_error * heading_error;
    sum_odometry_squared_ += odometry_error * odometry_error;
    const double to_odometry = std::hypot(snapshot.estimate(kX) - snapshot.odometry_pose.x,
                                          snapshot.estimate(kY) - snapshot.odometry_pose.y);
    sum_estimate_to_odometry_squared_ += to_odometry * to_odometry;
    m.max_position_error = std::max(m.max_position_error, position_error);
    m.max_heading_error = std::max(m.max_heading_error, heading_error);
    m.final_position_error = position_error;
    m.final_heading_error = heading_error;
    m.final_odometry_position_error = odometry_error;

    m.observations += snapshot.observation_available ? 1U : 0U;
    if (snapshot.observation_available) {
        ++m.association_outcomes[static_cast<std::size_t>(snapshot.association.outcome)];
    }
    if (snapshot.update.status == StepStatus::Applied) {
        ++m.updates_applied;
        sum_nis_ += snapshot.update.nis;
        const StateVector step = snapshot.update.gain * snapshot.update.innovation;  // W·ν
        sum_update_position_step_ += std::hypot(step(kX), step(kY));
        sum_update_heading_step_ += std::abs(step(kTheta));
    } else if (snapshot.update.status != StepStatus::NotAttempted) {
        ++m.updates_rejected;
    }

    const double nees =
        normalized_estimation_error(to_state(truth), snapshot.estimate, snapshot.covariance);
    if (std::isfinite(nees)) {
        sum_nees_ += nees;
        ++nees_count_;
        nees_inside_ += m.nees_bounds.contains(nees) ? 1U : 0U;
    }
}

RunMetrics RunMetricsAccumulator::result() const {
    RunMetrics m = metrics_;
    if (m.steps > 0) {
        const auto steps = static_cast<double>(m.steps);
        m.rms_position_error = std::sqrt(sum_position_squared_ / steps);
        m.rms_heading_error = std::sqrt(sum_heading_squared_ / steps);
        m.rms_odometry_position_error = std::sqrt(sum_odometry_squared_ / steps);
        m.rms_estimate_to_odometry = std::sqrt(sum_estimate_to_odometry_squared_ / steps);
    }
    if (nees_count_ > 0) {
        m.mean_nees = sum_nees_ / static_cast<double>(nees_count_);
        m.nees_inside_fraction =
            static_cast<double>(nees_inside_) / static_cast<double>(nees_count_);
    }
    if (m.updates_applied > 0) {
        const auto updates = static_cast<double>(m.updates_applied);
        m.mean_nis = sum_nis_ / updates;
        m.mean_update_position_step = sum_update_position_step_ / updates;
        m.mean_update_heading_step = sum_update_heading_step_ / updates;
    }
    return m;
}

}  // namespace legofeup
