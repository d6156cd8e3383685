#pragma once
// A complete description of one run — what the GUI's configuration panel shows and what a
// TOML configuration file or an experiment preset sets — and its resolution into the values
// the loop and the simulator take.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "legofeup/core/loop_config.hpp"
#include "legofeup/lessons/link_health.hpp"
#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/simulator.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::lessons {

/// The control routine and its parameters (the [control] section).
struct RoutineSpec {
    /// Shuttle: back and forth between line_from and line_to (`laps` times); Piecewise: the
    /// world's square corners with a stop of `pause` s at each (paper 004); Random:
    /// `random_points` random places inside the square path, drawn from the run's seed;
    /// Rectangle: `laps` laps of the axis-aligned rectangle with lower-left corner
    /// `rectangle_corner` and size `rectangle_size`, counter-clockwise from that corner
    /// (paper 001's "rectangular shaped lap").
    enum class Kind : std::uint8_t {
        Square,
        Line,
        Circle,
        Goto,
        Manual,
        Shuttle,
        Piecewise,
        Random,
        Rectangle
    };
    Kind kind = Kind::Square;
    double pause = 0.0;     ///< s stopped at each waypoint (shuttle, piecewise, random)
    int random_points = 8;  ///< random: how many places to visit
    Vector2 line_from{-1.0, -1.0};
    Vector2 line_to{1.0, -1.0};
    Vector2 circle_centre{0.0, 0.0};
    double circle_radius = 0.5;
    bool circle_clockwise = false;
    Pose2 goto_target{0.0, 0.0, 0.0};
    Vector2 rectangle_corner{-1.0, -1.0};  ///< m: lower-left corner, where each lap starts
    Vector2 rectangle_size{2.0, 2.0};      ///< m: width (along x) and height (along y)
};

/// How the robot is built as far as the filter knows (the [robot] section). The simulated
/// robot has the same nominal geometry plus the [simulator] section's errors.
struct RobotGeometry {
    double wheel_diameter = 0.0432;  ///< m
    double wheel_base = 0.12;        ///< m
    double counts_per_turn = 360.0;
    double codo_right = 0.0;  ///< counts per metre; 0: from the diameter and counts per turn
    double codo_left = 0.0;
    IrMount ir_mount;
};

/// A pose whose parts default to another pose (the world's start) unless set.
struct PoseOverride {
    std::optional<double> x;
    std::optional<double> y;
    std::optional<double> theta;

    Pose2 applied_to(const Pose2& base) const {
        return {x.value_or(base.x), y.value_or(base.y), theta.value_or(base.theta)};
    }
};

/// A sensor's own eq. 2 parameters, each the shared [ir_curve]'s unless set
/// (`ir_curve.front_c_m`, …): what calibrating each unit finds.
struct IrCurveOverride {
    std::optional<double> a;
    std::optional<double> c_m;
    std::optional<double> c_r;
    std::optional<double> b;

    bool empty() const { return !a && !c_m && !c_r && !b; }
    IrCurveParameters applied_to(const SharpIrCurve& shared) const {
        return {a.value_or(shared.a), c_m.value_or(shared.c_m), c_r.value_or(shared.c_r),
                b.value_or(shared.b)};
    }
};

/// Where a setting's value came from, to point at it in error messages.
struct SettingOrigin {
    std::string source;  ///< file name, "experiment c", "--seed", …
    int line = 0;
    std::string key;  ///< as written, e.g. "filter.q11"
};

struct RunConfig {
    std::uint64_t seed = 1;
    int laps = 2;           ///< laps of the square path
    double duration = 0.0;  ///< simulated seconds for other routines; 0: 200 s per lap
    /// Empty: the built-in standard arena; a built-in world's name ("office"); else a path.
    std::string world_file;
    /// The laser filter's map (Localisation::Laser): empty: the world's map; a built-in
    /// map's name; else a map YAML path. A different map than the world's is an outdated map.
    std::string laser_map_file;

    FilterTuning filter;
    /// The further lessons: localisation, EKF/UKF, their filters' tunings and calibration.
    LessonFilters lesson;
    InitialBelief initial;      ///< P0; its pose is the world's start with `initial_pose`
    PoseOverride initial_pose;  ///< where the filter believes the robot starts
    RoutineSpec routine;
    SteeringPose steer_by = SteeringPose::Estimate;  ///< what the controller steers by
    MotionLimits motion;
    ControllerGains gains;
    double max_wheel_speed = 0.38;
    RobotGeometry robot;
    SharpIrCurve ir_curve;  ///< both sensors' curve (the paper's one) and trusted range
    /// [kFrontSensor], [kRearSensor]: where a sensor's own curve differs from ir_curve.
    std::array<IrCurveOverride, kIrSensorCount> ir_sensor_curves;
    AssociationParams association;

    /// The simulated robot: its errors, noise, body and motors. Its geometry fields are
    /// taken from `robot` and `ir_curve` when the run is resolved.
    sim::RobotSpec physical;
    sim::SimulatorSettings simulator;
    PoseOverride true_start;  ///< where the robot really starts (default: the world's start)

    /// Setting field name → where its value was set (filled by the readers).
    std::map<std::string, SettingOrigin> origins;
};

/// When a file was last written and its size: whether a file read before may have changed.
struct FileStamp {
    std::filesystem::file_time_type written;
    std::uintmax_t size = 0;
    friend bool operator==(const FileStamp&, const FileStamp&) = default;
};

/// The stamp of the file at `path`; none when there is no such file (a built-in name).
std::optional<FileStamp> stamp_of(const std::string& path);

/// The noise of a simulated robot that a link with live noise takes
/// (RobotConnection::set_noise): E_d, E_b, slip and the IR's σ.
RobotNoise robot_noise(const sim::RobotSpec& robot);

/// A run ready to execute: everything derived, cross-checked and validated.
struct ResolvedRun {
    RunConfig config;
    sim::WorldSpec world;
    /// The world file's and the laser map file's stamps as they were read (none for a
    /// built-in world or map, or none named).
    std::optional<FileStamp> world_stamp;
    std::optional<FileStamp> map_stamp;
    LoopConfig loop;
    sim::RobotSpec robot;
    Pose2 true_start;
    double max_duration = 0.0;  ///< simulated seconds after which the run stops regardless
};

/// Loads the world, derives the loop's and the simulator's parameters and validates all of
/// them. Throws InputError naming each bad setting and where it was set.
ResolvedRun resolve(const RunConfig& config);

/// As resolve(config), but the world and the laser map that `previous` read are taken again,
/// not re-read, when `config` names the same world file and map file and those files'
/// stamps are unchanged. The GUI re-resolves its configuration on every setting edit; a
/// change of Q must not re-read a world file, nor re-decode a building's map. (A map's YAML
/// is stamped, not the image it names: an image edited alone is read again when the
/// configuration is loaded anew.)
ResolvedRun resolve(const RunConfig& config, const ResolvedRun& previous);

}  // namespace legofeup::lessons
