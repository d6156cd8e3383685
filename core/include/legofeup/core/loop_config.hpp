#pragma once
// Every parameter of the LegoFeup loop, with the defaults of the standard scenario
// (docs/loop.md), and their validation. Files (TOML), the GUI and the CLI all fill this
// one structure; validate() is the single place that decides what is acceptable.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/controller.hpp"
#include "legofeup/core/covariance_guard.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/core/wall_association.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

/// The EKF's noise model and switches; all of it may change while the robot runs.
struct FilterTuning {
    double q11 = 1e-7;  ///< Q₁₁: variance of ε_d per control period, m²
    double q22 = 1e-5;  ///< Q₂₂: variance of ε_Δθ per control period, rad²
    double r11 = 1e-4;  ///< R₁₁: variance of ε_ds1 (front IR distance), m²
    double r22 = 1e-4;  ///< R₂₂: variance of ε_ds2 (rear IR distance), m²
    /// false: odometry only — walls are still associated (and shown) but never used.
    bool wall_updates = true;
    bool gate_enabled = false;       ///< reject updates whose NIS exceeds the gate
    double gate_probability = 0.99;  ///< the gate is the χ²(2) quantile at this probability
    CovarianceLimits limits;
};

/// The belief the filter starts from (and returns to on reset).
struct InitialBelief {
    Pose2 pose{-1.0, -1.0, 0.0};  ///< the start of the standard square path
    double var_x = 1e-4;          ///< P0 diagonal, m²
    double var_y = 1e-4;          ///< m²
    double var_theta = 1e-3;      ///< rad²
    /// The pose is unknown (global localisation): the filter starts from the whole free
    /// space — the particle filter's cloud uniform over it, a Gaussian filter its mean and
    /// covariance (PoseEstimator::reset_uniform) — and `pose` and the variances are unused.
    bool unknown_pose = false;
};

/// The pose the path controller steers by. The estimate is the paper's loop (a wrong estimate
/// steers the robot wrong, as on the real robot). Odometry is how a robot that has not been
/// told where it stands drives a planned path: by dead reckoning from where it was put, while
/// the filter finds out where that is (global localisation, lesson mcl) — the path is then
/// driven whatever the estimate does, so a lost filter cannot drive the robot into a wall.
enum class SteeringPose : std::uint8_t { Estimate, Odometry };

const char* to_string(SteeringPose pose);  ///< "estimate", "odometry"
std::optional<SteeringPose> steering_pose_from_string(std::string_view text);

struct LoopConfig {
    OdometryParams odometry;
    IrMount ir_mount;
    /// Eq. 2 of both IR sensors (the paper's one curve) and their trusted range.
    SharpIrCurve ir_curve;
    /// A sensor's own eq. 2 parameters ([kFrontSensor], [kRearSensor]), as calibrating each
    /// unit finds them; empty: ir_curve's. The trusted range is ir_curve's for both.
    std::array<std::optional<IrCurveParameters>, kIrSensorCount> ir_sensor_parameters;
    WallMap walls = standard_arena_walls(ArenaSpec{});
    AssociationParams association;
    FilterTuning filter;
    InitialBelief initial;
    /// The further lessons' estimators; `lesson.localisation` picks what corrects the
    /// odometry (the walls by default).
    LessonFilters lesson;
    BeaconMap beacons;  ///< the filter's map of beacons (Localisation::Beacons)
    /// The filter's occupancy-grid map (Localisation::Laser), shared read-only between
    /// copies of the configuration; required when the localisation is Laser.
    std::shared_ptr<const OccupancyGrid> map;
    double control_period = 0.05;  ///< Ts, s: the nominal period (frames carry their times)
    /// The seed of the loop's own random streams (the particle filter's): the run's seed,
    /// so that a run is the same bits for the same seed.
    std::uint64_t random_seed = 1;
    MotionLimits motion;
    ControllerGains gains;
    Controller controller = FollowPath(square_path(ArenaSpec{}), 0);
    SteeringPose steer_by = SteeringPose::Estimate;
    double max_wheel_speed = 0.38;  ///< m/s: ≈170 rpm on 43.2 mm wheels
    /// m: a wheel moving farther than this in one period is an encoder glitch (e.g. a
    /// counter reset on the robot); that period's odometry is skipped and flagged.
    double max_wheel_travel_per_step = 0.25;
};

/// The curve the loop reads `sensor` with: ir_curve with that sensor's own parameters, if any.
SharpIrCurve ir_sensor_curve(const LoopConfig& config, IrSensor sensor);

/// The name of a sensor's own curve in settings and messages: "ir_curve.front", "ir_curve.rear".
std::string ir_sensor_curve_name(IrSensor sensor);

/// Everything wrong with `config` (empty when it is usable).
std::vector<ConfigIssue> validate(const LoopConfig& config);

/// The IR parts of validate(), for other owners of a curve or mount (the simulator's
/// physical sensors); fields are named "<prefix>.<name>".
std::vector<ConfigIssue> validate(const SharpIrCurve& curve, const std::string& prefix);
std::vector<ConfigIssue> validate(const IrMount& mount, const std::string& prefix);

/// Bounds accepted for every variance a user types (Q, R, P0): wide enough for the
/// experiments' "very low" and "very high" settings, narrow enough to stay finite.
inline constexpr double kMinUserVariance = 1e-15;
inline constexpr double kMaxUserVariance = 1e9;

}  // namespace legofeup
