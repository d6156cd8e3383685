#pragma once
// The LegoFeup loop (paper §IV, Fig. 3): one control period in, one wheel command out.
//
//   sensor frame ─► odometry (eq. 7–9) ─► EKF predict (eq. 11–13)
//                ─► IR A/D → d_s1, d_s2 (eq. 2) ─► observation (eq. 3) if both in range
//                ─► wall association (Fig. 4) ─► EKF update (eq. 14–21)
//                ─► control routine on the estimate ─► (V, W) ─► (V1, V2) (eq. 1)
//
// The loop knows nothing of where frames come from (simulator, UDP, NXT): it is a value-in /
// value-out step that never allocates. Odometry-only, "direct" (R ≈ 0) and EKF operation are
// settings of FilterTuning, not separate code paths.
//
// The further lessons replace what corrects the odometry (LessonFilters::localisation):
// bearings to beacons (paper 002), the 5-state encoder + accelerometer + gyro EKF (paper 003)
// or a compass with state-dependent odometry noise (paper 004), or a laser scan matched (ICP)
// against the expected scan in an occupancy-grid map (paper 001). The pose filter is any
// PoseEstimator of the registry (pose_estimator_registry.hpp: the EKF or the UKF, a live
// setting), held through that one interface; a "shadow" of the kind the registry pairs with
// it can run on the same frames for comparison. The localisation picks the models (which
// prediction, which measurements), the estimator the algorithm: the two never meet in a
// switch. The speed estimators of paper 003 run beside every localisation.

#include <memory>
#include <vector>

#include "legofeup/core/gyro_fusion_estimator.hpp"
#include "legofeup/core/laser_localiser.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/pose_estimator.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/core/speed_estimators.hpp"

namespace legofeup {

class LegoFeupLoop {
  public:
    /// Throws std::invalid_argument listing every issue if `config` does not validate.
    explicit LegoFeupLoop(LoopConfig config);

    /// Runs one control period. The returned snapshot stays valid until the next call.
    const LoopSnapshot& step(const SensorFrame& frame);

    /// Runs a control period for which no frame arrived (a lossy link): predict only, with
    /// a zero odometry increment but the full process noise Q, so P grows as the paper's
    /// model says it must; no observation; the routine runs on the prediction. The encoder
    /// reference is kept, so the next frame's counts bring the missed motion in (the counts
    /// are cumulative). `time` is when the frame was due. Flags snapshot().frame_missing.
    const LoopSnapshot& step_without_frame(double time);

    /// Back to the initial belief with the configured routine restarted; the next frame only
    /// sets the encoder reference.
    void reset();

    /// Applies a new configuration while running: everything takes effect at the next step
    /// except the initial belief (next reset) and the routine (next reset or
    /// set_controller). Returns the issues and changes nothing if it does not validate.
    std::vector<ConfigIssue> reconfigure(LoopConfig config);

    /// Replaces the running routine (it starts afresh) and the configured one.
    void set_controller(Controller controller);

    /// The command used while the routine is ManualDrive (keyboard driving); ignored otherwise.
    void set_manual_command(const VelocityCommand& command);

    const LoopConfig& config() const { return config_; }
    const LoopSnapshot& snapshot() const { return snapshot_; }
    const PoseEstimator& filter() const { return *filter_; }

  private:
    void apply_tuning();
    /// Replaces `estimator` by one of `kind` (when it differs) that continues from its x and P.
    void switch_kind(std::unique_ptr<PoseEstimator>& estimator, FilterKind kind) const;
    void update_map_models();
    void weigh_scan(PoseEstimator& filter, const LaserScan& scan, LaserUpdate& report);
    bool advance_odometry(const SensorFrame& frame);
    Eigen::Matrix2d skipped_motion_noise(double period) const;
    double periods_between(double seconds) const;  // Δt/Ts, see predict_pose
    void estimate(const SensorFrame* frame, bool predict, double period);
    StepStatus predict_pose(PoseEstimator& filter, const OdometryIncrement& increment,
                            double period);
    void read_ir(const SensorFrame& frame);
    void update_with_walls(PoseEstimator& filter, bool primary);
    void update_with_beacons(PoseEstimator& filter, const SensorFrame& frame, bool primary);
    void update_with_compass(PoseEstimator& filter, const LoopSnapshot& s);
    void update_with_laser(PoseEstimator& filter, const SensorFrame& frame, bool primary);
    void begin_laser_report();
    void run_pose_filter(PoseEstimator& filter, const SensorFrame* frame, bool predict,
                         double period, bool primary);
    void run_gyro_fusion(const SensorFrame* frame, double period);
    void control_and_publish();
    bool uses_pose_filter() const;

    LoopConfig config_;
    // The pose filter and its shadow (run when lesson.compare_kinds), made by the registry
    // when the kind changes, never in a step; the settings they were last configured with.
    PoseEstimatorSettings estimator_settings_;
    /// Where an unknown pose may be (the laser map's free cells, else the walls' box), for
    /// global localisation and the particle filter's recovery; rebuilt when the map changes.
    std::shared_ptr<const FreeSpace> free_space_;
    const OccupancyGrid* free_space_map_ = nullptr;
    /// The laser map's likelihood field (the particle filter's laser model): null until a
    /// filter weighs scans in a run with a map; `likelihood_field_map_` is the map it is of.
    std::shared_ptr<const LikelihoodField> likelihood_field_;
    const OccupancyGrid* likelihood_field_map_ = nullptr;
    double likelihood_field_max_distance_ = 0.0;
    std::vector<Vector2> scan_endpoints_;  ///< this scan's, reused (no allocation in a step)
    std::unique_ptr<PoseEstimator> filter_;
    std::unique_ptr<PoseEstimator> shadow_;
    GyroFusionEstimator fusion_;
    // The laser lesson's scan matching, one per pose filter (each matches against its own
    // prediction and keeps its own mismatch streak); the shadow's report is not published.
    LaserLocaliser laser_;
    LaserLocaliser shadow_laser_;
    LaserUpdate shadow_laser_report_;
    SpeedEstimators speeds_;
    double last_time_ = 0.0;
    Controller controller_;
    Pose2 odometry_pose_;
    std::array<std::int32_t, 2> last_counts_{};
    bool have_counts_ = false;
    double last_counts_time_ = 0.0;  // the time of the frame last_counts_ came with
    std::uint64_t steps_ = 0;
    std::uint64_t glitches_ = 0;  // encoder glitches since the reset

    // Derived from config_.filter by apply_tuning(), so the step does no setup work.
    Eigen::Matrix2d process_noise_ = Eigen::Matrix2d::Zero();  // Q
    Eigen::Matrix2d ir_noise_ = Eigen::Matrix2d::Zero();       // R
    MahalanobisGate gate_;
    double association_threshold_ = 0.0;  // χ²₂ quantile of the association gate
    MahalanobisGate beacon_gate_;

    LoopSnapshot snapshot_;
    bool laser_report_empty_ = true;  // snapshot_.laser is LaserUpdate{} (begin_laser_report)
};

}  // namespace legofeup
