#pragma once
// How well a run localised: what happened to the observations, and — when the link has a
// ground truth — the errors against it and the filter's consistency (NEES). Pure
// computation; the truth comes from the simulator's separate channel and never reaches the
// filter.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/loop_snapshot.hpp"

namespace legofeup {

inline constexpr int kAssociationOutcomeCount = 7;

/// A truth pose that moves farther than this in one step was carried, not driven (a
/// kidnapping: the robot's top speed, 0.38 m/s, covers 2 cm in a 50 ms period).
inline constexpr double kKidnapPositionJump = 0.25;  ///< m
inline constexpr double kKidnapHeadingJump = 1.0;    ///< rad
/// After a kidnapping the estimate counts as recovered once its position error stays below
/// this for the rest of the run.
inline constexpr double kRecoveredPositionError = 0.10;  ///< m

/// What can be measured only against the ground truth: the errors of the estimate, of dead
/// reckoning, of the raw sensors and of the shadow filter, the NEES, the lap test and the
/// kidnappings. Every error is formed by pose_error (x̃ = x̂ − x). Computed over the steps
/// that had a truth (`steps`); absent altogether from a run that had none (a real robot).
struct TruthMetrics {
    std::uint64_t steps = 0;  ///< steps scored against a truth

    double rms_position_error = 0.0;    ///< m
    double max_position_error = 0.0;    ///< m
    double final_position_error = 0.0;  ///< m
    double rms_heading_error = 0.0;     ///< rad
    double max_heading_error = 0.0;     ///< rad
    double final_heading_error = 0.0;   ///< rad
    /// The odometry-only estimate from the same counts, for comparison.
    double rms_odometry_position_error = 0.0;
    double final_odometry_position_error = 0.0;

    double mean_nees = 0.0;  ///< the time average of the NEES over the steps
    /// Share of steps whose own NEES lies inside RunMetrics::nees_bounds (one χ²(3) value):
    /// about 0.95 for a consistent filter.
    double nees_inside_fraction = 0.0;
    /// How many independent values the run's correlated NEES series is worth, N_eff = N/τ, and
    /// its autocorrelation time τ (effective_samples.hpp).
    double nees_effective_samples = 0.0;
    double nees_autocorrelation_time = 0.0;
    /// The 95 % interval of mean_nees for a consistent filter: χ²(3·N_eff)/N_eff
    /// (time_average_chi_square_interval). Not the bounds of one step, which are far wider.
    ChiSquareInterval time_average_nees_bounds;

    // Heading of dead reckoning alone (the compass and gyro lessons compare against it).
    double rms_odometry_heading_error = 0.0;    ///< rad
    double max_odometry_heading_error = 0.0;    ///< rad
    double final_odometry_heading_error = 0.0;  ///< rad

    // Speeds (paper 003), against the truth's wheel surface speeds and body velocity.
    std::uint64_t speed_steps = 0;
    double rms_wheel_speed_error_kf = 0.0;              ///< m/s, both wheels
    double rms_wheel_speed_error_differentiated = 0.0;  ///< m/s, both wheels
    std::uint64_t velocity_kf_steps = 0;
    double rms_velocity_error_kf = 0.0;         ///< v of the accelerometer KF, m/s
    double rms_velocity_error_encoders = 0.0;   ///< v from differentiated encoders, m/s
    double rms_turn_rate_error_kf = 0.0;        ///< ω of the accelerometer KF, rad/s
    double rms_turn_rate_error_encoders = 0.0;  ///< ω from differentiated encoders, rad/s
    // The speed filters' integrated poses (SpeedEstimates::wheel_kf_pose, body_kf_pose), and
    // the RMS position error of each over the RMS error of odometry (the raw encoders) over
    // the same steps: below 1 the filter's speeds give a better position than the counts.
    double rms_wheel_kf_position_error = 0.0;    ///< m, over speed_steps
    double final_wheel_kf_position_error = 0.0;  ///< m
    double wheel_kf_position_to_odometry_ratio = 0.0;
    double rms_velocity_kf_position_error = 0.0;    ///< m, over velocity_kf_steps
    double final_velocity_kf_position_error = 0.0;  ///< m
    double velocity_kf_position_to_odometry_ratio = 0.0;

    // Raw heading sensors against the truth (when the frames had them).
    std::uint64_t compass_steps = 0;
    double rms_compass_heading_error = 0.0;  ///< rad: the compass alone
    std::uint64_t gyro_steps = 0;
    double final_gyro_heading_error = 0.0;  ///< rad: the integrated gyro alone

    // The shadow filter (the other kind on the same frames).
    std::uint64_t shadow_steps = 0;
    double shadow_rms_position_error = 0.0;    ///< m
    double shadow_final_position_error = 0.0;  ///< m
    double shadow_rms_heading_error = 0.0;     ///< rad
    double shadow_mean_nees = 0.0;

    // The paper's lap test (§IV): how far the final position is from where the run really
    // started (the first truth), for dead reckoning and for the estimate — the robot drives
    // one closed lap, so both should be near 0 (15 cm vs 2.5 cm in the paper).
    double odometry_end_to_start = 0.0;  ///< m
    double estimate_end_to_start = 0.0;  ///< m
    /// final_odometry_position_error / final_position_error: how many times closer to the
    /// truth the estimate ends than dead reckoning (0 when the estimate's error is 0).
    double odometry_to_estimate_final_error_ratio = 0.0;

    // Kidnapping (paper 001 §IV-B): a step whose truth reports a new teleport
    // (GroundTruth::teleports) or jumps more than kKidnapPositionJump or kKidnapHeadingJump
    // from the previous truth.
    std::uint64_t kidnappings = 0;
    /// Seconds from the last kidnapping to the first step after which the position error
    /// stays below kRecoveredPositionError until the end of the run; −1 when there was no
    /// kidnapping or the error never settled.
    double time_to_recover = -1.0;
    bool kidnap_recovered = false;  ///< there was a kidnapping and time_to_recover ≥ 0
};

/// How a run went. The counts need no truth and are right on any link; what needs the truth
/// is in `truth`, empty when no step had one — never zeros that would read as measured.
struct RunMetrics {
    std::uint64_t steps = 0;
    double duration = 0.0;  ///< seconds from the first to the last step

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

    /// 95 % two-sided interval of one χ²(3) value: what one step's NEES is compared with
    /// (nees_inside_fraction), never an average (TruthMetrics::time_average_nees_bounds).
    ChiSquareInterval nees_bounds;
    double mean_nis = 0.0;  ///< over applied updates (χ²(2) when consistent)

    // Beacons (paper 002).
    std::uint64_t beacon_bearings = 0;         ///< sightings of known beacons
    std::uint64_t beacon_updates_applied = 0;  ///< bearings the filter used
    double mean_beacon_nis = 0.0;              ///< χ²(1) when consistent

    // Laser scan matching (paper 001).
    std::uint64_t laser_scans = 0;          ///< scans matched against the map (skipped excluded)
    std::uint64_t laser_matches = 0;        ///< scans whose ICP match updated the filter (§III-B)
    std::uint64_t laser_skipped_scans = 0;  ///< scans skipped for a wrong beam count
    std::uint64_t laser_recoveries = 0;  ///< times P was inflated after a mismatch streak (§IV-B)
    double laser_match_fraction = 0.0;   ///< laser_matches / laser_scans (0 without scans)

    // Cost per step (wall clock: machine-dependent, shown, never graded).
    double mean_filter_microseconds = 0.0;
    double mean_shadow_filter_microseconds = 0.0;

    /// Against the ground truth; empty when no step had one.
    std::optional<TruthMetrics> truth;
};

class RunMetricsAccumulator {
  public:
    RunMetricsAccumulator();

    /// Adds one step without a truth (a real robot): counted, not scored.
    void add(const LoopSnapshot& snapshot);
    /// Adds one step and where the robot really was.
    void add(const LoopSnapshot& snapshot, const Pose2& truth);
    /// The same with the whole truth, which also scores the speed estimates.
    void add(const LoopSnapshot& snapshot, const GroundTruth& truth);

    RunMetrics result() const;

  private:
    void add_counts(const LoopSnapshot& snapshot);
    void add_truth(const LoopSnapshot& snapshot, const Pose2& truth, bool teleported);
    void add_speeds(const LoopSnapshot& snapshot, const GroundTruth& truth);
    void add_kidnapping(double time, const Pose2& truth, bool teleported, double position_error);
    void finish_truth(TruthMetrics& t) const;

    RunMetrics metrics_;
    TruthMetrics truth_;
    double first_time_ = 0.0;
    double sum_position_squared_ = 0.0;
    double sum_heading_squared_ = 0.0;
    double sum_odometry_squared_ = 0.0;
    double sum_nees_ = 0.0;
    std::uint64_t nees_count_ = 0;
    std::vector<double> nees_series_;  // every finite NEES, in step order, for N_eff
    std::uint64_t nees_inside_ = 0;
    double sum_nis_ = 0.0;
    double sum_update_position_step_ = 0.0;
    double sum_update_heading_step_ = 0.0;
    double sum_estimate_to_odometry_squared_ = 0.0;
    double sum_odometry_heading_squared_ = 0.0;
    double sum_beacon_nis_ = 0.0;
    double sum_wheel_kf_squared_ = 0.0;
    double sum_wheel_differentiated_squared_ = 0.0;
    double sum_velocity_kf_squared_ = 0.0;
    double sum_velocity_encoders_squared_ = 0.0;
    double sum_turn_rate_kf_squared_ = 0.0;
    double sum_turn_rate_encoders_squared_ = 0.0;
    double sum_wheel_kf_position_squared_ = 0.0;
    double sum_speed_odometry_squared_ = 0.0;  // odometry over speed_steps
    double sum_velocity_kf_position_squared_ = 0.0;
    double sum_velocity_odometry_squared_ = 0.0;  // odometry over velocity_kf_steps
    double sum_compass_squared_ = 0.0;
    double sum_shadow_position_squared_ = 0.0;
    double sum_shadow_heading_squared_ = 0.0;
    double sum_shadow_nees_ = 0.0;
    std::uint64_t shadow_nees_count_ = 0;
    double sum_filter_seconds_ = 0.0;
    double sum_shadow_filter_seconds_ = 0.0;
    Pose2 start_truth_;     // the first truth
    Pose2 previous_truth_;  // for spotting kidnappings
    std::uint32_t previous_teleports_ = 0;
    double kidnap_time_ = 0.0;
    bool settled_ = false;        // the error has stayed below kRecoveredPositionError since...
    double settled_since_ = 0.0;  // ...this step's time
};

}  // namespace legofeup
