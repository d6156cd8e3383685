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
    add_step(snapshot, truth, false);
}

void RunMetricsAccumulator::add_step(const LoopSnapshot& snapshot, const Pose2& truth,
                                     bool teleported) {
    RunMetrics& m = metrics_;
    if (m.steps == 0) {
        first_time_ = snapshot.time;
        start_truth_ = truth;
        previous_truth_ = truth;
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
    m.odometry_end_to_start = std::hypot(snapshot.odometry_pose.x - start_truth_.x,
                                         snapshot.odometry_pose.y - start_truth_.y);
    m.estimate_end_to_start =
        std::hypot(snapshot.estimate(kX) - start_truth_.x, snapshot.estimate(kY) - start_truth_.y);
    add_kidnapping(snapshot.time, truth, teleported, position_error);

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

    const double odometry_heading_error =
        std::abs(wrap_angle(truth.theta - snapshot.odometry_pose.theta));
    sum_odometry_heading_squared_ += odometry_heading_error * odometry_heading_error;
    m.max_odometry_heading_error = std::max(m.max_odometry_heading_error, odometry_heading_error);
    m.final_odometry_heading_error = odometry_heading_error;

    for (std::size_t i = 0; i < snapshot.beacons.count; ++i) {
        const BeaconUpdate& update = snapshot.beacons.updates[i];
        m.beacon_bearings += update.known ? 1U : 0U;
        if (update.status == StepStatus::Applied) {
            ++m.beacon_updates_applied;
            sum_beacon_nis_ += update.nis;
        }
    }
    const LaserUpdate& laser = snapshot.laser;
    if (laser.scan_received && !laser.wrong_beam_count) {
        ++m.laser_scans;
    }
    m.laser_matches += laser.matched ? 1U : 0U;
    m.laser_skipped_scans += laser.wrong_beam_count ? 1U : 0U;
    m.laser_recoveries += laser.recovery_triggered ? 1U : 0U;

    if (snapshot.readings.has_compass) {
        const double error = wrap_angle(snapshot.readings.compass_heading - truth.theta);
        sum_compass_squared_ += error * error;
        ++m.compass_steps;
    }
    if (snapshot.readings.has_gyro) {
        m.final_gyro_heading_error =
            std::abs(wrap_angle(snapshot.readings.gyro_heading - truth.theta));
        ++m.gyro_steps;
    }
    if (snapshot.shadow.active) {
        ++m.shadow_steps;
        const double error = std::hypot(truth.x - snapshot.shadow.estimate(kX),
                                        truth.y - snapshot.shadow.estimate(kY));
        const double heading = wrap_angle(truth.theta - snapshot.shadow.estimate(kTheta));
        sum_shadow_position_squared_ += error * error;
        sum_shadow_heading_squared_ += heading * heading;
        m.shadow_final_position_error = error;
        const double shadow_nees = normalized_estimation_error(
            to_state(truth), snapshot.shadow.estimate, snapshot.shadow.covariance);
        if (std::isfinite(shadow_nees)) {
            sum_shadow_nees_ += shadow_nees;
            ++shadow_nees_count_;
        }
    }
    sum_filter_seconds_ += snapshot.filter_seconds;
    sum_shadow_filter_seconds_ += snapshot.shadow_filter_seconds;
}

// A kidnapping is a teleport the truth reports or, for truths without that count, a jump no
// drive could make. It restarts the wait for the error to settle; every step at or above the
// threshold restarts it too, so settled_since_ ends as the start of the final good stretch.
void RunMetricsAccumulator::add_kidnapping(double time, const Pose2& truth, bool teleported,
                                           double position_error) {
    RunMetrics& m = metrics_;
    const double jump = std::hypot(truth.x - previous_truth_.x, truth.y - previous_truth_.y);
    const double turn = std::abs(wrap_angle(truth.theta - previous_truth_.theta));
    previous_truth_ = truth;
    if (teleported || jump > kKidnapPositionJump || turn > kKidnapHeadingJump) {
        ++m.kidnappings;
        kidnap_time_ = time;
        settled_ = false;
    }
    if (position_error >= kRecoveredPositionError) {
        settled_ = false;
    } else if (!settled_) {
        settled_ = true;
        settled_since_ = time;
    }
}

void RunMetricsAccumulator::add(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    const bool teleported = metrics_.steps > 0 && truth.teleports != previous_teleports_;
    previous_teleports_ = truth.teleports;
    add_step(snapshot, truth.pose, teleported);
    RunMetrics& m = metrics_;
    const SpeedEstimates& speeds = snapshot.speeds;
    if (!speeds.valid) {
        return;
    }
    ++m.speed_steps;
    const std::array<double, 2> true_wheels{truth.wheel_surface_speeds.right,
                                            truth.wheel_surface_speeds.left};
    for (std::size_t i = 0; i < 2; ++i) {
        const double kf = speeds.wheel_kf[i] - true_wheels[i];
        const double differentiated = speeds.wheel_differentiated[i] - true_wheels[i];
        sum_wheel_kf_squared_ += kf * kf;
        sum_wheel_differentiated_squared_ += differentiated * differentiated;
    }
    if (speeds.body_kf_valid) {
        ++m.velocity_kf_steps;
        const auto squared = [](double a) { return a * a; };
        sum_velocity_kf_squared_ += squared(speeds.body_kf.v - truth.velocity.v);
        sum_velocity_encoders_squared_ += squared(speeds.body_encoders.v - truth.velocity.v);
        sum_turn_rate_kf_squared_ += squared(speeds.body_kf.w - truth.velocity.w);
        sum_turn_rate_encoders_squared_ += squared(speeds.body_encoders.w - truth.velocity.w);
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
        m.rms_odometry_heading_error = std::sqrt(sum_odometry_heading_squared_ / steps);
        m.mean_filter_microseconds = 1e6 * sum_filter_seconds_ / steps;
        m.mean_shadow_filter_microseconds = 1e6 * sum_shadow_filter_seconds_ / steps;
    }
    const auto rms = [](double sum, std::uint64_t count) {
        return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
    };
    if (m.beacon_updates_applied > 0) {
        m.mean_beacon_nis = sum_beacon_nis_ / static_cast<double>(m.beacon_updates_applied);
    }
    m.rms_wheel_speed_error_kf = rms(sum_wheel_kf_squared_, 2 * m.speed_steps);
    m.rms_wheel_speed_error_differentiated =
        rms(sum_wheel_differentiated_squared_, 2 * m.speed_steps);
    m.rms_velocity_error_kf = rms(sum_velocity_kf_squared_, m.velocity_kf_steps);
    m.rms_velocity_error_encoders = rms(sum_velocity_encoders_squared_, m.velocity_kf_steps);
    m.rms_turn_rate_error_kf = rms(sum_turn_rate_kf_squared_, m.velocity_kf_steps);
    m.rms_turn_rate_error_encoders = rms(sum_turn_rate_encoders_squared_, m.velocity_kf_steps);
    m.rms_compass_heading_error = rms(sum_compass_squared_, m.compass_steps);
    m.shadow_rms_position_error = rms(sum_shadow_position_squared_, m.shadow_steps);
    m.shadow_rms_heading_error = rms(sum_shadow_heading_squared_, m.shadow_steps);
    if (shadow_nees_count_ > 0) {
        m.shadow_mean_nees = sum_shadow_nees_ / static_cast<double>(shadow_nees_count_);
    }
    if (nees_count_ > 0) {
        m.mean_nees = sum_nees_ / static_cast<double>(nees_count_);
        m.nees_inside_fraction =
            static_cast<double>(nees_inside_) / static_cast<double>(nees_count_);
    }
    if (m.laser_scans > 0) {
        m.laser_match_fraction =
            static_cast<double>(m.laser_matches) / static_cast<double>(m.laser_scans);
    }
    if (m.final_position_error > 0.0) {
        m.odometry_to_estimate_final_error_ratio =
            m.final_odometry_position_error / m.final_position_error;
    }
    if (m.kidnappings > 0 && settled_) {
        m.time_to_recover = settled_since_ - kidnap_time_;
        m.kidnap_recovered = true;
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
