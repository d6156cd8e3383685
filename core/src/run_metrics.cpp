#include "legofeup/core/run_metrics.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/core/consistency.hpp"
#include "legofeup/core/effective_samples.hpp"
#include "legofeup/core/pose_error.hpp"

namespace legofeup {

static_assert(static_cast<int>(AssociationOutcome::MahalanobisMismatch) + 1
                  == kAssociationOutcomeCount,
              "kAssociationOutcomeCount must count every AssociationOutcome");

RunMetricsAccumulator::RunMetricsAccumulator() {
    metrics_.nees_bounds = average_chi_square_interval(kStateSize, 1, 0.95);
}

void RunMetricsAccumulator::add(const LoopSnapshot& snapshot) {
    add_counts(snapshot);
}

void RunMetricsAccumulator::add(const LoopSnapshot& snapshot, const Pose2& truth) {
    add_counts(snapshot);
    add_truth(snapshot, truth, false);
}

void RunMetricsAccumulator::add(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    const bool teleported = truth_.steps > 0 && truth.teleports != previous_teleports_;
    previous_teleports_ = truth.teleports;
    add_counts(snapshot);
    add_truth(snapshot, truth.pose, teleported);
    add_speeds(snapshot, truth);
}

// What the loop did, whatever the robot really did: the same on a real robot as in the
// simulator.
void RunMetricsAccumulator::add_counts(const LoopSnapshot& snapshot) {
    RunMetrics& m = metrics_;
    if (m.steps == 0) {
        first_time_ = snapshot.time;
    }
    ++m.steps;
    m.duration = snapshot.time - first_time_;

    const double to_odometry = std::hypot(snapshot.estimate(kX) - snapshot.odometry_pose.x,
                                          snapshot.estimate(kY) - snapshot.odometry_pose.y);
    sum_estimate_to_odometry_squared_ += to_odometry * to_odometry;

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

    sum_filter_seconds_ += snapshot.filter_seconds;
    sum_shadow_filter_seconds_ += snapshot.shadow_filter_seconds;
}

// Every error below is pose_error's x̃ = x̂ − x (or heading_error's wrap(θ̂ − θ)).
void RunMetricsAccumulator::add_truth(const LoopSnapshot& snapshot, const Pose2& truth,
                                      bool teleported) {
    TruthMetrics& t = truth_;
    if (t.steps == 0) {
        start_truth_ = truth;
        previous_truth_ = truth;
    }
    ++t.steps;

    const PoseError error = pose_error(snapshot.estimate, truth);
    const PoseError odometry = pose_error(snapshot.odometry_pose, truth);
    sum_position_squared_ += error.position() * error.position();
    sum_heading_squared_ += error.theta * error.theta;
    sum_odometry_squared_ += odometry.position() * odometry.position();
    t.max_position_error = std::max(t.max_position_error, error.position());
    t.max_heading_error = std::max(t.max_heading_error, error.heading());
    t.final_position_error = error.position();
    t.final_heading_error = error.heading();
    t.final_odometry_position_error = odometry.position();
    t.odometry_end_to_start = pose_error(snapshot.odometry_pose, start_truth_).position();
    t.estimate_end_to_start = pose_error(snapshot.estimate, start_truth_).position();
    add_kidnapping(snapshot.time, truth, teleported, error.position());

    const double nees = normalized_estimation_error(error, snapshot.covariance);
    if (std::isfinite(nees)) {
        sum_nees_ += nees;
        ++nees_count_;
        nees_series_.push_back(nees);
        nees_inside_ += metrics_.nees_bounds.contains(nees) ? 1U : 0U;
    }

    sum_odometry_heading_squared_ += odometry.theta * odometry.theta;
    t.max_odometry_heading_error = std::max(t.max_odometry_heading_error, odometry.heading());
    t.final_odometry_heading_error = odometry.heading();

    if (snapshot.readings.has_compass) {
        const double compass = heading_error(snapshot.readings.compass_heading, truth.theta);
        sum_compass_squared_ += compass * compass;
        ++t.compass_steps;
    }
    if (snapshot.readings.has_gyro) {
        t.final_gyro_heading_error =
            std::abs(heading_error(snapshot.readings.gyro_heading, truth.theta));
        ++t.gyro_steps;
    }
    if (snapshot.shadow.active) {
        ++t.shadow_steps;
        const PoseError shadow = pose_error(snapshot.shadow.estimate, truth);
        sum_shadow_position_squared_ += shadow.position() * shadow.position();
        sum_shadow_heading_squared_ += shadow.theta * shadow.theta;
        t.shadow_final_position_error = shadow.position();
        const double shadow_nees = normalized_estimation_error(shadow, snapshot.shadow.covariance);
        if (std::isfinite(shadow_nees)) {
            sum_shadow_nees_ += shadow_nees;
            ++shadow_nees_count_;
        }
    }
}

// A kidnapping is a teleport the truth reports or, for truths without that count, a jump no
// drive could make. It restarts the wait for the error to settle; every step at or above the
// threshold restarts it too, so settled_since_ ends as the start of the final good stretch.
void RunMetricsAccumulator::add_kidnapping(double time, const Pose2& truth, bool teleported,
                                           double position_error) {
    TruthMetrics& t = truth_;
    const double jump = std::hypot(truth.x - previous_truth_.x, truth.y - previous_truth_.y);
    const double turn = std::abs(wrap_angle(truth.theta - previous_truth_.theta));
    previous_truth_ = truth;
    if (teleported || jump > kKidnapPositionJump || turn > kKidnapHeadingJump) {
        ++t.kidnappings;
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

void RunMetricsAccumulator::add_speeds(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    TruthMetrics& t = truth_;
    const SpeedEstimates& speeds = snapshot.speeds;
    if (!speeds.valid) {
        return;
    }
    ++t.speed_steps;
    const std::array<double, 2> true_wheels{truth.wheel_surface_speeds.right,
                                            truth.wheel_surface_speeds.left};
    for (std::size_t i = 0; i < 2; ++i) {
        const double kf = speeds.wheel_kf[i] - true_wheels[i];
        const double differentiated = speeds.wheel_differentiated[i] - true_wheels[i];
        sum_wheel_kf_squared_ += kf * kf;
        sum_wheel_differentiated_squared_ += differentiated * differentiated;
    }
    const auto squared = [](double a) { return a * a; };
    const double odometry = pose_error(snapshot.odometry_pose, truth.pose).position();
    const double wheel_kf = pose_error(speeds.wheel_kf_pose, truth.pose).position();
    sum_wheel_kf_position_squared_ += squared(wheel_kf);
    sum_speed_odometry_squared_ += squared(odometry);
    t.final_wheel_kf_position_error = wheel_kf;
    if (speeds.body_kf_valid) {
        ++t.velocity_kf_steps;
        const double velocity_kf = pose_error(speeds.body_kf_pose, truth.pose).position();
        sum_velocity_kf_position_squared_ += squared(velocity_kf);
        sum_velocity_odometry_squared_ += squared(odometry);
        t.final_velocity_kf_position_error = velocity_kf;
        sum_velocity_kf_squared_ += squared(speeds.body_kf.v - truth.velocity.v);
        sum_velocity_encoders_squared_ += squared(speeds.body_encoders.v - truth.velocity.v);
        sum_turn_rate_kf_squared_ += squared(speeds.body_kf.w - truth.velocity.w);
        sum_turn_rate_encoders_squared_ += squared(speeds.body_encoders.w - truth.velocity.w);
    }
}

void RunMetricsAccumulator::finish_truth(TruthMetrics& t) const {
    const auto rms = [](double sum, std::uint64_t count) {
        return count > 0 ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
    };
    t.rms_position_error = rms(sum_position_squared_, t.steps);
    t.rms_heading_error = rms(sum_heading_squared_, t.steps);
    t.rms_odometry_position_error = rms(sum_odometry_squared_, t.steps);
    t.rms_odometry_heading_error = rms(sum_odometry_heading_squared_, t.steps);
    t.rms_wheel_speed_error_kf = rms(sum_wheel_kf_squared_, 2 * t.speed_steps);
    t.rms_wheel_speed_error_differentiated =
        rms(sum_wheel_differentiated_squared_, 2 * t.speed_steps);
    t.rms_velocity_error_kf = rms(sum_velocity_kf_squared_, t.velocity_kf_steps);
    t.rms_velocity_error_encoders = rms(sum_velocity_encoders_squared_, t.velocity_kf_steps);
    t.rms_turn_rate_error_kf = rms(sum_turn_rate_kf_squared_, t.velocity_kf_steps);
    t.rms_turn_rate_error_encoders = rms(sum_turn_rate_encoders_squared_, t.velocity_kf_steps);
    t.rms_wheel_kf_position_error = rms(sum_wheel_kf_position_squared_, t.speed_steps);
    t.rms_velocity_kf_position_error = rms(sum_velocity_kf_position_squared_, t.velocity_kf_steps);
    // Ratios of RMS errors over the same steps (0 when odometry had no error at all).
    const auto rms_ratio = [](double sum, double odometry_sum) {
        return odometry_sum > 0.0 ? std::sqrt(sum / odometry_sum) : 0.0;
    };
    t.wheel_kf_position_to_odometry_ratio =
        rms_ratio(sum_wheel_kf_position_squared_, sum_speed_odometry_squared_);
    t.velocity_kf_position_to_odometry_ratio =
        rms_ratio(sum_velocity_kf_position_squared_, sum_velocity_odometry_squared_);
    t.rms_compass_heading_error = rms(sum_compass_squared_, t.compass_steps);
    t.shadow_rms_position_error = rms(sum_shadow_position_squared_, t.shadow_steps);
    t.shadow_rms_heading_error = rms(sum_shadow_heading_squared_, t.shadow_steps);
    if (shadow_nees_count_ > 0) {
        t.shadow_mean_nees = sum_shadow_nees_ / static_cast<double>(shadow_nees_count_);
    }
    if (nees_count_ > 0) {
        t.mean_nees = sum_nees_ / static_cast<double>(nees_count_);
        t.nees_inside_fraction =
            static_cast<double>(nees_inside_) / static_cast<double>(nees_count_);
        const EffectiveSamples effective = effective_sample_size(nees_series_);
        t.nees_effective_samples = effective.count;
        t.nees_autocorrelation_time = effective.autocorrelation_time;
        t.time_average_nees_bounds =
            time_average_chi_square_interval(kStateSize, effective.count, 0.95);
    }
    if (t.final_position_error > 0.0) {
        t.odometry_to_estimate_final_error_ratio =
            t.final_odometry_position_error / t.final_position_error;
    }
    if (t.kidnappings > 0 && settled_) {
        t.time_to_recover = settled_since_ - kidnap_time_;
        t.kidnap_recovered = true;
    }
}

RunMetrics RunMetricsAccumulator::result() const {
    RunMetrics m = metrics_;
    if (m.steps > 0) {
        const auto steps = static_cast<double>(m.steps);
        m.rms_estimate_to_odometry = std::sqrt(sum_estimate_to_odometry_squared_ / steps);
        m.mean_filter_microseconds = 1e6 * sum_filter_seconds_ / steps;
        m.mean_shadow_filter_microseconds = 1e6 * sum_shadow_filter_seconds_ / steps;
    }
    if (m.beacon_updates_applied > 0) {
        m.mean_beacon_nis = sum_beacon_nis_ / static_cast<double>(m.beacon_updates_applied);
    }
    if (m.laser_scans > 0) {
        m.laser_match_fraction =
            static_cast<double>(m.laser_matches) / static_cast<double>(m.laser_scans);
    }
    if (m.updates_applied > 0) {
        const auto updates = static_cast<double>(m.updates_applied);
        m.mean_nis = sum_nis_ / updates;
        m.mean_update_position_step = sum_update_position_step_ / updates;
        m.mean_update_heading_step = sum_update_heading_step_ / updates;
    }
    if (truth_.steps > 0) {
        m.truth = truth_;
        finish_truth(*m.truth);
    }
    return m;
}

}  // namespace legofeup
