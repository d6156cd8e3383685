#pragma once
// Everything one step of the loop computed: the output the GUI, the CLI and the metrics read.
// A plain value (no pointers, no heap), so it can be copied across threads and recorded.

#include <array>
#include <cstdint>

#include "legofeup/core/controller.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/particle_summary.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/wall_association.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {

struct IrSample {
    std::uint16_t adc = 0;  ///< raw A/D value A
    IrDistance reading;     ///< eq. 2 and the range check
};

using WallUpdateReport = UpdateReport<WallMeasurement::kSize, kStateSize>;

/// One beacon bearing the filter processed (Localisation::Beacons).
struct BeaconUpdate {
    std::uint8_t id = 0;
    bool known = false;      ///< the id is in the filter's beacon map (unknown ids are skipped)
    double bearing = 0.0;    ///< measured, rad
    double predicted = 0.0;  ///< h(X̂) before this update, rad
    StepStatus status = StepStatus::NotAttempted;
    double nis = 0.0;
};

struct BeaconUpdates {
    std::uint8_t count = 0;  ///< updates[0 .. count) are valid (one per sighting)
    std::array<BeaconUpdate, kMaxBeaconSightings> updates{};
};

/// Speeds as the lessons of paper 003 estimate them, m/s and rad/s.
struct SpeedEstimates {
    bool valid = false;  ///< false until two frames have been seen
    /// Wheel surface speeds [right, left]: per-wheel KF (eq. 15–19) and differentiated encoders.
    std::array<double, 2> wheel_kf{};
    std::array<double, 2> wheel_differentiated{};
    VelocityCommand body_encoders;  ///< (v, ω) from differentiated encoders (eq. 14)
    bool body_kf_valid = false;     ///< the frame had accelerometers
    VelocityCommand body_kf;        ///< (v, ω) of the KF with accelerometer inputs (eq. 20–23)
    /// Dead reckoning (eq. 13) from the initial pose with the wheel KF's speeds, and with
    /// the (v, ω) KF's (while the frames have accelerometers): the positions the paper
    /// compares with the raw encoders' (its figure 7).
    Pose2 wheel_kf_pose;
    Pose2 body_kf_pose;
};

/// The optional sensors converted to SI units (when the frame had them).
struct ExtraReadings {
    bool has_gyro = false;
    double gyro_rate = 0.0;     ///< rad/s, calibrated (offset removed)
    double gyro_heading = 0.0;  ///< rad, the gyro rate integrated from the initial heading
    bool has_accelerometers = false;
    std::array<double, 2> accel_forward{};  ///< m/s² [right unit, left unit], bias removed
    std::array<double, 2> accel_bias{};     ///< m/s², the bias removed (0 when not estimated)
    bool has_compass = false;
    double compass_heading = 0.0;  ///< rad in (−π, π]
};

/// The other filter kind run on the same frames for comparison (LessonFilters::compare_kinds).
struct ShadowEstimate {
    bool active = false;
    FilterKind kind = FilterKind::Ukf;
    StateVector estimate = StateVector::Zero();
    StateCovariance covariance = StateCovariance::Zero();
};

/// Localisation::Laser (paper 001): what the scan matching did this period.
struct LaserUpdate {
    bool scan_received = false;  ///< the frame carried a scan (and a map was configured)
    /// The ICP result was used: it converged and matched ≥ min_matched_points (§III-B), and
    /// the filter applied the update.
    bool matched = false;
    StepStatus status = StepStatus::NotAttempted;  ///< of the H = I update (eq. 15–18)
    IcpResult icp;  ///< the alignment of the measured scan onto the expected one
    int consecutive_mismatches = 0;
    bool recovery_triggered = false;  ///< P was multiplied this period (kidnapping, §IV-B)
    bool recovery_active = false;     ///< ICP tightened until the next match
    /// m: the ICP threshold used for this scan (without a scan: the one the next will use).
    double correspondence_distance = 0.0;
    Pose2 scanner_pose;   ///< predicted scanner pose the expected scan was cast from (world)
    Pose2 observed_pose;  ///< Z: the robot pose the match implies (eq. 2), world frame
    Eigen::Vector3d innovation = Eigen::Vector3d::Zero();  ///< V = Z − Ẑ (eq. 3), θ wrapped
    LaserScan expected;  ///< ray-cast at scanner_pose in the filter's map (Fig. 2)
    /// The scan's beam_count differed from lesson.laser.geometry.beam_count: it was skipped
    /// (no ICP, not counted as a mismatch).
    bool wrong_beam_count = false;
    int measured_points = 0;  ///< points of the measured scan given to the ICP (source)
    int expected_points = 0;  ///< points of the expected scan (the ICP's reference)
    double nis = 0.0;         ///< Vᵀ(P + R)⁻¹V of the update (χ²(3) when consistent)
    /// Since the last reset: scans matched against the map (skipped ones excluded), scans
    /// whose match was used, covariance inflations, and scans skipped for their beam count.
    std::uint32_t total_scans = 0;
    std::uint32_t total_matches = 0;
    std::uint32_t total_recoveries = 0;
    std::uint32_t total_skipped = 0;
};

struct LoopSnapshot {
    std::uint64_t step = 0;      ///< frames processed since the last reset (1 for the first)
    double time = 0.0;           ///< the frame's time stamp, s
    std::uint32_t sequence = 0;  ///< the frame's sequence number
    /// No frame came this period (lost or late on a real link): the loop only predicted,
    /// with no odometry increment, and the controller ran on the prediction.
    bool frame_missing = false;
    /// The raw frame exactly as the loop received it, for recording and replay
    /// (lessons/recording); when frame_missing, a default frame stamped with the due time.
    SensorFrame frame;

    // Estimation module.
    StateVector estimate = StateVector::Zero();            ///< X̂ after this step
    StateCovariance covariance = StateCovariance::Zero();  ///< P after this step
    Pose2 odometry_pose;          ///< dead reckoning from the same counts (no updates ever)
    OdometryIncrement increment;  ///< this period's d1, d2, d, Δθ
    /// The encoders jumped beyond max_wheel_travel_per_step (per nominal period, times the
    /// periods this step spans): the increment was not used, and the prediction added the
    /// noise of a skipped motion instead.
    bool odometry_glitch = false;
    std::uint64_t odometry_glitches = 0;  ///< glitches since the run began, this one included
    StepStatus predict_status = StepStatus::NotAttempted;

    Localisation localisation = Localisation::Walls;
    FilterKind filter_kind = FilterKind::Ekf;
    /// 5-state fusion only: the estimated (v, ω) of the state.
    VelocityCommand fused_velocity;

    // Observation and association modules.
    std::array<IrSample, kIrSensorCount> ir{};
    bool observation_available = false;  ///< both readings in range
    WallObservation observation;         ///< eq. 3 (valid when observation_available)
    AssociationResult association;       ///< outcome NoObservation when there was none
    WallUpdateReport update;             ///< status NotAttempted when no update ran

    BeaconUpdates beacons;  ///< Localisation::Beacons
    LaserUpdate laser;      ///< Localisation::Laser
    ExtraReadings readings;
    SpeedEstimates speeds;
    ShadowEstimate shadow;
    /// The particle filter's cloud after this step (count 0 with the other filters).
    ParticleSummary particles;
    /// Wall-clock seconds this step spent in the pose filter's predict and updates, and in the
    /// shadow filter's (machine-dependent: shown, never graded).
    double filter_seconds = 0.0;
    double shadow_filter_seconds = 0.0;

    // Control module.
    ControllerStatus controller;
    VelocityCommand velocity;  ///< (V, W) from the routine
    WheelSpeeds wheels;        ///< (V1, V2) sent to the robot (eq. 1, speed-limited)
};

}  // namespace legofeup
