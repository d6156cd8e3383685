#pragma once
// What the views draw: every step of the current run, on the GUI thread, in a memory that
// grows by ~0.75 kB a step (a 256-byte record, a deflated trace row of ~0.2 kB, a whole
// sample a second) instead of a whole sample's 5.9 kB (two 1024-beam scans alone are 4 kB,
// in every snapshot of every lesson); bytes() tells how much.
//
// The session's worker thread produces RunSamples; the session moves them here in one batch
// per repaint (docs/gui.md) and tells the views which ones are new. Of every step the history
// keeps a StepRecord (the numbers the plots and the arena's paths need) and its trace.csv row
// (for File ▸ Export trace); whole samples, scans and all, only for the last kRecentSamples
// steps, the latest batch, and one step per kKeptPeriod of run time before them. Views read
// this history only on the GUI thread, so it needs no lock.

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/particle_cloud.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup::ui {

/// One control period of a run: what the loop computed and what really happened.
struct RunSample {
    LoopSnapshot snapshot;
    /// The simulator's truth at the step's time (none over a link without truth, e.g. NXT).
    std::optional<GroundTruth> truth;
    /// NEES x̃ᵀ P⁻¹ x̃ of the pose error x̃ = x̂ − x (pose_error.hpp); NaN without truth.
    double nees = std::numeric_limits<double>::quiet_NaN();
    /// The particle filter's cloud after the step, thinned to at most kParticlesShown points
    /// (particle_cloud.hpp); null for the Gaussian filters, and for samples the history keeps
    /// from before its recent ones (16 kB each: the arena draws the cloud of a step only
    /// within the last kRecentSamples).
    std::shared_ptr<const std::vector<ParticlePoint>> particles;
};

/// The laser lesson's (paper 001) scanner and thresholds, for the arena's scan layer and the
/// plots' reference lines.
struct LaserScene {
    bool active = false;                ///< the run localises with the laser (Localisation::Laser)
    ScanGeometry geometry;              ///< the beams as the filter believes them
    Pose2 mount;                        ///< the scanner on the robot as the filter believes it
    ScanGeometry true_geometry;         ///< the simulated scanner's beams
    Pose2 true_mount;                   ///< the simulated scanner on the robot
    int min_matched_points = 0;         ///< fewer matched points is a mismatch (§III-B)
    int recovery_after_mismatches = 0;  ///< consecutive mismatches before P is inflated
    bool kidnap_recovery = false;       ///< the recovery is on
    double recovery_covariance_factor = 1.0;  ///< P is multiplied by it
};

/// What stays fixed during a run: the world and the path drawn behind the robot.
struct ArenaScene {
    std::vector<Wall> walls;        ///< the walls of the world (and of the filter's map)
    std::vector<PathSegment> path;  ///< the intended path; empty when driving by hand
    IrMount ir_mount;               ///< where the IR sensors sit, to draw their rays
    double ir_max_range = 0.8;      ///< m: the trusted IR range
    AssociationParams association;  ///< the wall association's gate and its limits
    double control_period = 0.05;   ///< s
    /// The world's bearing-only beacons (paper 002) when the run localises with them.
    BeaconMap beacons;
    /// The world's occupancy-grid map (paper 001), drawn under everything; null: none.
    std::shared_ptr<const OccupancyGrid> map;
    /// The laser filter's map when it is not the world's (an outdated map); null otherwise.
    std::shared_ptr<const OccupancyGrid> filter_map;
    LaserScene laser;
    /// The loop the run uses (the trace rows name its walls); null: the trace is its header.
    std::shared_ptr<const LoopConfig> loop;
};

/// The laser lesson's numbers of one step (paper 001), for the plots of the scan matching.
struct LaserNumbers {
    bool processed = false;  ///< a scan was matched this step (not one skipped for its beams)
    bool matched = false;    ///< its match was used
    bool updated = false;    ///< the H = I update ran (status other than NotAttempted)
    bool recovery_triggered = false;
    std::int32_t matched_points = 0;  ///< ICP's
    std::int32_t consecutive_mismatches = 0;
    Eigen::Vector3f innovation = Eigen::Vector3f::Zero();  ///< V = Z − Ẑ, m and rad
};

/// Two wheels' speeds as a record keeps them, m/s.
struct RecordedWheelSpeeds {
    float right = 0.0F;  ///< V1
    float left = 0.0F;   ///< V2
};

/// What the history keeps of every step, also once the step's sample is dropped: the numbers
/// the plots draw (plot_series.cpp reads nothing else) and the arena's paths and covariance
/// trail. make_step_record() fills it from a sample.
///
/// 264 bytes, 36,000 of them in a 30-minute run: the time, the estimate, the truth and NEES
/// are doubles (the arena's paths, and the errors and the lesson panel's checks computed from
/// them, are exact); every other number is a float, 7 significant digits, finer than any
/// plot's pixel; the members are ordered by size, so there is no padding between them.
struct StepRecord {
    double time = 0.0;  ///< the frame's time stamp, s
    Pose2 estimate;     ///< x̂, ŷ, θ̂
    Pose2 truth;        ///< the truth at the step's time (when has_truth)
    double nees = std::numeric_limits<double>::quiet_NaN();  ///< RunSample::nees

    /// P's pose block: the three variances and the x–y covariance (m², rad²).
    float pxx = 0.0F;
    float pxy = 0.0F;
    float pyy = 0.0F;
    float ptt = 0.0F;
    Eigen::Vector2f odometry = Eigen::Vector2f::Zero();  ///< the dead-reckoning position
    RecordedWheelSpeeds wheels;                          ///< (V1, V2) sent to the robot
    /// The IR distances ds1, ds2 as measured, m; NaN when out of range.
    std::array<float, kIrSensorCount> ir_distance{};
    /// NIS of the wall update, if one ran and computed it (NaN otherwise).
    float wall_nis = std::numeric_limits<float>::quiet_NaN();

    std::uint32_t teleports = 0;  ///< GroundTruth::teleports
    RecordedWheelSpeeds true_wheel_speeds;
    float true_turn_rate = 0.0F;  ///< rad/s

    /// Beacon updates with a known beacon that computed an innovation (paper 002): the bearing
    /// innovations z − h(X̂) in rad, wrapped (bearing_count of them), and whether each was
    /// applied.
    std::array<float, kMaxBeaconSightings> bearing_innovation{};
    // Paper 003's sensors and estimates.
    float gyro_rate = 0.0F;     ///< rad/s
    float gyro_heading = 0.0F;  ///< rad
    float compass_heading = 0.0F;
    std::array<float, 2> wheel_kf{};              ///< [right, left], m/s
    std::array<float, 2> wheel_differentiated{};  ///< [right, left], m/s
    float encoder_turn_rate = 0.0F;               ///< ω from differentiated encoders, rad/s
    float fused_turn_rate = 0.0F;                 ///< the 5-state EKF's ω, rad/s
    // The comparison filter run on the same frames (paper 002).
    Eigen::Vector2f shadow_position = Eigen::Vector2f::Zero();
    float filter_seconds = 0.0F;
    float shadow_filter_seconds = 0.0F;
    // The particle filter's cloud (ParticleSummary; count 0 with the Gaussian filters).
    float particle_effective = 0.0F;  ///< N_eff
    std::int32_t particle_count = 0;
    LaserNumbers laser;

    std::array<bool, kMaxBeaconSightings> bearing_applied{};
    std::uint8_t bearing_count = 0;
    bool has_truth = false;  ///< false over a link without a truth: `truth` is not set
    Localisation localisation = Localisation::Walls;
    FilterKind filter_kind = FilterKind::Ekf;
    bool has_gyro = false;
    bool has_compass = false;
    bool has_accelerometers = false;
    bool speeds_valid = false;
    bool shadow_active = false;
    FilterKind shadow_kind = FilterKind::Ukf;
};

/// A record's float as the double the views compute with.
constexpr double widen(float value) {
    return static_cast<double>(value);
}

/// The record of one sample (every number a StepRecord holds, from its snapshot and truth).
StepRecord make_step_record(const RunSample& sample);

/// The history of the current run (see the top of this file).
class RunHistory {
  public:
    /// Whole samples kept at the end of the history: 30 s at 20 Hz (and never fewer than
    /// the latest batch, so that whoever is told of it can read it whole).
    static constexpr std::size_t kRecentSamples = 600;
    /// Before those, one whole sample per this much run time (s) is kept.
    static constexpr double kKeptPeriod = 1.0;

    RunHistory();
    ~RunHistory();
    RunHistory(RunHistory&&) noexcept;
    RunHistory& operator=(RunHistory&&) noexcept;
    RunHistory(const RunHistory&) = delete;
    RunHistory& operator=(const RunHistory&) = delete;

    /// Starts a new run: drops every step and bumps epoch().
    void restart(ArenaScene scene);
    /// Takes the scene of a run reconfigured while it goes (its thresholds may change);
    /// keeps the steps and the epoch.
    void update_scene(ArenaScene scene);
    void append(std::vector<RunSample>&& batch);

    /// Steps of the run so far.
    std::size_t size() const { return records_.size(); }
    bool empty() const { return records_.empty(); }
    /// Every step's record, in order.
    const std::vector<StepRecord>& records() const { return records_; }
    const StepRecord& record(std::size_t step) const { return records_[step]; }
    /// Step `step`'s whole sample if it is still kept (always for the last kRecentSamples
    /// and the latest batch), else nullptr.
    const RunSample* sample(std::size_t step) const;
    /// The whole sample kept nearest to step `step` (< size()), and its step: what a view
    /// showing a past step's scan shows. Nearest in steps; the later one on a tie.
    std::pair<std::size_t, const RunSample*> nearest_sample(std::size_t step) const;
    /// How many whole samples are kept.
    std::size_t samples_kept() const { return recent_.size() + older_.size(); }
    /// The step of the oldest sample in the kept recent run (sample(i) is whole from there).
    std::size_t recent_begin() const { return records_.size() - recent_.size(); }
    const RunSample& latest() const { return recent_.back(); }
    const ArenaScene& scene() const { return scene_; }
    /// Changes whenever the history starts over, so views know to drop what they cached.
    std::uint64_t epoch() const { return epoch_; }
    /// Every step in the CLI's trace.csv format, with its header (written as the steps come).
    std::string trace_csv() const;

    /// The bytes the history holds for its steps, by part: what it allocated (capacity
    /// included), not what the allocator adds to it.
    struct Bytes {
        std::size_t records = 0;    ///< every step's StepRecord
        std::size_t samples = 0;    ///< the whole samples kept
        std::size_t trace = 0;      ///< the trace rows: deflated blocks and the open one
        std::size_t particles = 0;  ///< the particle clouds of the kept samples
        std::size_t total() const { return records + samples + trace + particles; }
    };
    Bytes bytes() const;

  private:
    struct KeptSample {
        std::size_t step = 0;
        RunSample sample;
    };
    class TraceRows;
    /// Moves the samples beyond the recent ones (at least `batch_size`) out of recent_,
    /// keeping the first of each kKeptPeriod in older_.
    void drop_old_samples(std::size_t batch_size);

    ArenaScene scene_;
    std::vector<StepRecord> records_;
    std::deque<RunSample> recent_;  ///< steps recent_begin() … size() − 1
    /// One per kKeptPeriod before them, in order (a deque: never copied as it grows).
    std::deque<KeptSample> older_;
    /// A sample leaving recent_ is kept in older_ if its time is at least this (the first
    /// always is): the first sample of each kKeptPeriod.
    double next_kept_time_ = -std::numeric_limits<double>::infinity();
    std::unique_ptr<TraceRows> trace_;
    std::uint64_t epoch_ = 0;
};

}  // namespace legofeup::ui
