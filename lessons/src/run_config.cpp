#include "legofeup/lessons/run_config.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/world_file.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kSecondsPerLap = 200.0;        // a lap takes ~90 s; a lost robot gets twice that
constexpr double kStandardLapLength = 8.0;      // m: the square of side 2 m the above is for
constexpr double kRandomWaypointSpacing = 0.5;  // m between consecutive random places

// A validation issue, pointed at the setting the user wrote and where they wrote it.
InputProblem locate(const RunConfig& config, const ConfigIssue& issue) {
    InputProblem problem{"", 0, issue.field, issue.value, issue.reason};
    if (const Setting* setting = find_setting_by_field(issue.field)) {
        problem.key = setting->key;
    }
    if (const auto origin = config.origins.find(issue.field); origin != config.origins.end()) {
        problem.source = origin->second.source;
        problem.line = origin->second.line;
        problem.key = origin->second.key;
    }
    return problem;
}

Controller make_controller(const RunConfig& config, const sim::WorldSpec& world) {
    const RoutineSpec& routine = config.routine;
    switch (routine.kind) {
        case RoutineSpec::Kind::Square:
            return FollowPath(sim::world_square_path(world), config.laps);
        case RoutineSpec::Kind::Line:
            return FollowLine(routine.line_from, routine.line_to);
        case RoutineSpec::Kind::Circle:
            return FollowCircle(routine.circle_centre, routine.circle_radius,
                                !routine.circle_clockwise);
        case RoutineSpec::Kind::Goto:
            return GoXYTheta(routine.goto_target);
        case RoutineSpec::Kind::Manual:
            return ManualDrive{};
        case RoutineSpec::Kind::Shuttle:
            return VisitWaypoints({routine.line_to, routine.line_from}, routine.pause, config.laps);
        case RoutineSpec::Kind::Piecewise: {
            std::vector<Vector2> corners;
            for (const PathSegment& segment : sim::world_square_path(world)) {
                if (const auto* line = std::get_if<LineSegment>(&segment)) {
                    corners.push_back(line->to);
                }
            }
            return VisitWaypoints(std::move(corners), routine.pause, config.laps);
        }
        case RoutineSpec::Kind::Rectangle: {
            // Counter-clockwise from the lower-left corner, heading +x first.
            const Vector2 low = routine.rectangle_corner;
            const Vector2 high = low + routine.rectangle_size;
            const Vector2 corners[] = {low, {high.x(), low.y()}, high, {low.x(), high.y()}};
            std::vector<PathSegment> segments;
            for (int i = 0; i < 4; ++i) {
                segments.emplace_back(LineSegment{corners[i], corners[(i + 1) % 4]});
            }
            return FollowPath(std::move(segments), config.laps);
        }
        case RoutineSpec::Kind::Random: {
            // Inside the square path (the arena's free floor), from the run's seed.
            const Vector2 half = Vector2::Constant(0.5 * world.path_side);
            const int count = std::clamp(routine.random_points, 1, 100);
            return VisitWaypoints(
                random_waypoints(config.seed, count, world.path_centre - half,
                                 world.path_centre + half, kRandomWaypointSpacing),
                routine.pause, 1);
        }
    }
    return ManualDrive{};
}

/// The laser filter's map: [laser] map when given (an outdated map is a lesson), else the
/// world's. Problems of the map file come with the configuration line that names it.
std::shared_ptr<const OccupancyGrid> filter_map(const RunConfig& config,
                                                const sim::WorldSpec& world) {
    if (config.laser_map_file.empty()) {
        return world.surveyed_map ? world.surveyed_map : world.map;
    }
    try {
        return load_map(config.laser_map_file);
    } catch (const InputError& error) {
        std::vector<InputProblem> problems = error.problems();
        InputProblem named{"", 0, "laser.map", "\"" + config.laser_map_file + "\"",
                           "the map file is unusable"};
        if (const auto origin = config.origins.find("map"); origin != config.origins.end()) {
            named.source = origin->second.source;
            named.line = origin->second.line;
        }
        problems.push_back(named);
        throw InputError(std::move(problems));
    }
}

/// The filter must expect as many beams per scan as the simulated scanner measures (else
/// it would refuse every scan). Whether there is a map at all the loop's validate() checks.
void check_laser_beams(const RunConfig& config, ConfigChecker& check) {
    const ScanGeometry& believed = config.lesson.laser.geometry;
    const sim::LaserScannerSpec& scanner = config.physical.laser_scanner;
    if (config.lesson.localisation == Localisation::Laser && scanner.enabled) {
        check.require(believed.beam_count == scanner.geometry.beam_count,
                      "lesson.laser.geometry.beam_count", believed.beam_count,
                      "must equal the simulated scanner's laser_scanner.beam_count ("
                          + std::to_string(scanner.geometry.beam_count) + ")");
    }
}

}  // namespace

RobotNoise robot_noise(const sim::RobotSpec& robot) {
    return {robot.wheel_diameter_ratio, robot.wheel_base_ratio, robot.slip_noise, robot.ir_noise};
}

std::optional<FileStamp> stamp_of(const std::string& path) {
    std::error_code error;
    const std::filesystem::path file(path);
    if (path.empty() || !std::filesystem::is_regular_file(file, error)) {
        return std::nullopt;
    }
    const auto written = std::filesystem::last_write_time(file, error);
    const auto size = std::filesystem::file_size(file, error);
    if (error) {
        return std::nullopt;
    }
    return FileStamp{written, size};
}

namespace {

/// The world `config` names, read (its own problems carry their lines).
sim::WorldSpec read_world(const RunConfig& config) {
    if (config.world_file.empty()) {
        return built_in_world();
    }
    try {
        return load_world(config.world_file);
    } catch (const InputError& error) {
        std::vector<InputProblem> problems = error.problems();
        if (const auto origin = config.origins.find("world"); origin != config.origins.end()) {
            problems.push_back({origin->second.source, origin->second.line, "world",
                                "\"" + config.world_file + "\"", "the world file is unusable"});
        }
        throw InputError(std::move(problems));
    }
}

/// The rest of resolve(), once the world and the filter's map are at hand.
ResolvedRun resolve_with(const RunConfig& config, sim::WorldSpec world,
                         std::shared_ptr<const OccupancyGrid> laser_map) {
    ResolvedRun run;
    run.config = config;
    run.world = std::move(world);

    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range_or_zero("duration", config.duration, 1.0, 1e6);
    check.in_range("control.random_points", config.routine.random_points, 1.0, 100.0);
    const std::size_t issues_before_rectangle = issues.size();
    if (config.routine.kind == RoutineSpec::Kind::Rectangle) {
        check.require(config.routine.rectangle_corner.allFinite(), "controller.rectangle_corner",
                      config.routine.rectangle_corner.norm(), "must be a point of finite numbers");
        for (const double side :
             {config.routine.rectangle_size.x(), config.routine.rectangle_size.y()}) {
            check.require(side >= 0.1 && side <= 1000.0, "controller.rectangle_size", side,
                          "each side must be between 0.1 and 1000 m");
        }
    }
    const bool bad_rectangle = issues.size() > issues_before_rectangle;
    check_laser_beams(config, check);
    check.in_range("robot.wheel_diameter", config.robot.wheel_diameter, 0.005, 1.0);
    check.in_range("robot.counts_per_turn", config.robot.counts_per_turn, 1.0, 1e6);
    check.in_range_or_zero("odometry.codo_right", config.robot.codo_right, 1.0, 1e6);
    check.in_range_or_zero("odometry.codo_left", config.robot.codo_left, 1.0, 1e6);

    // The filter's side: the robot as it is believed to be built, and the world's walls.
    const double nominal_codo =
        nominal_counts_per_metre(config.robot.wheel_diameter, config.robot.counts_per_turn);
    LoopConfig& loop = run.loop;
    loop.odometry.codo_right =
        config.robot.codo_right > 0.0 ? config.robot.codo_right : nominal_codo;
    loop.odometry.codo_left = config.robot.codo_left > 0.0 ? config.robot.codo_left : nominal_codo;
    loop.odometry.wheel_base = config.robot.wheel_base;
    loop.ir_mount = config.robot.ir_mount;
    loop.ir_curve = config.ir_curve;
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto index = static_cast<std::size_t>(sensor);
        if (!config.ir_sensor_curves[index].empty()) {
            loop.ir_sensor_parameters[index] =
                config.ir_sensor_curves[index].applied_to(config.ir_curve);
        }
    }
    loop.walls = WallMap(run.world.walls);
    loop.association = config.association;
    loop.filter = config.filter;
    loop.lesson = config.lesson;
    loop.beacons = run.world.beacons;  // the filter's beacon map is the world's
    loop.map = laser_map;
    loop.control_period = config.simulator.control_period;
    loop.initial = config.initial;
    loop.initial.pose = config.initial_pose.applied_to(run.world.start);
    loop.random_seed = config.seed;
    loop.motion = config.motion;
    loop.gains = config.gains;
    loop.controller = make_controller(config, run.world);
    loop.steer_by = config.steer_by;
    loop.max_wheel_speed = config.max_wheel_speed;
    for (const ConfigIssue& issue : validate(loop)) {
        // A bad rectangle is reported once, as such, not again as its degenerate segments.
        if (!(bad_rectangle && issue.field.starts_with("controller.path"))) {
            issues.push_back(issue);
        }
    }

    // The simulated robot: the same nominal robot with the [simulator] section's errors.
    run.robot = config.physical;
    run.robot.wheel_diameter = config.robot.wheel_diameter;
    run.robot.wheel_base = config.robot.wheel_base;
    run.robot.counts_per_turn = config.robot.counts_per_turn;
    run.robot.ir_mount = config.robot.ir_mount;
    // Ideal sensors follow the filter's own curve (the paper's simulation). Realistic ones are
    // GP2D120 units around the sensor's typical curve (the [ir_curve] defaults) whatever the
    // filter believes, so a calibrated [ir_curve] or profile changes the filter only.
    run.robot.ir_curve = config.physical.ir_model == sim::IrSensorModel::Realistic
                             ? SharpIrCurve{}
                             : config.ir_curve;
    for (const ConfigIssue& issue : sim::validate(run.robot, config.simulator)) {
        // Geometry shared with the filter is reported once, under the filter's name.
        const bool shared = issue.field.rfind("simulator.ir_mount.", 0) == 0
                            || issue.field.rfind("simulator.ir_curve.", 0) == 0
                            || issue.field == "simulator.wheel_diameter"
                            || issue.field == "simulator.wheel_base"
                            || issue.field == "simulator.counts_per_turn";
        if (!shared) {
            issues.push_back(issue);
        }
    }
    run.true_start = config.true_start.applied_to(run.world.start);

    if (!issues.empty()) {
        std::vector<InputProblem> problems;
        for (const ConfigIssue& issue : issues) {
            problems.push_back(locate(config, issue));
        }
        throw InputError(std::move(problems));
    }

    const bool lapped = config.routine.kind == RoutineSpec::Kind::Square
                        || config.routine.kind == RoutineSpec::Kind::Rectangle;
    // Longer laps than the standard square get proportionally more time.
    const double lap_scale =
        config.routine.kind == RoutineSpec::Kind::Rectangle
            ? std::max(1.0, 2.0 * config.routine.rectangle_size.sum() / kStandardLapLength)
            : 1.0;
    // A lapped routine ends with its laps, or at 200 s per lap; a duration, when given, ends
    // it sooner (a lesson that shows only the start of a lap). Other routines run for the
    // duration, or as long as a lap would take.
    const double lap_limit = kSecondsPerLap * config.laps * lap_scale;
    if (config.duration <= 0.0) {
        run.max_duration = lap_limit;
    } else {
        run.max_duration = lapped ? std::min(lap_limit, config.duration) : config.duration;
    }
    return run;
}

}  // namespace

ResolvedRun resolve(const RunConfig& config) {
    // Stamped before reading: a file written meanwhile is read again next time.
    const std::optional<FileStamp> world_stamp = stamp_of(config.world_file);
    const std::optional<FileStamp> map_stamp = stamp_of(config.laser_map_file);
    sim::WorldSpec world = read_world(config);
    std::shared_ptr<const OccupancyGrid> laser_map = filter_map(config, world);
    ResolvedRun run = resolve_with(config, std::move(world), std::move(laser_map));
    run.world_stamp = world_stamp;
    run.map_stamp = map_stamp;
    return run;
}

ResolvedRun resolve(const RunConfig& config, const ResolvedRun& previous) {
    const std::optional<FileStamp> world_stamp = stamp_of(config.world_file);
    const std::optional<FileStamp> map_stamp = stamp_of(config.laser_map_file);
    const bool same_world =
        config.world_file == previous.config.world_file && world_stamp == previous.world_stamp;
    const bool same_map = same_world && config.laser_map_file == previous.config.laser_map_file
                          && map_stamp == previous.map_stamp;
    sim::WorldSpec world = same_world ? previous.world : read_world(config);
    std::shared_ptr<const OccupancyGrid> laser_map =
        same_map ? previous.loop.map : filter_map(config, world);
    ResolvedRun run = resolve_with(config, std::move(world), std::move(laser_map));
    run.world_stamp = world_stamp;
    run.map_stamp = map_stamp;
    return run;
}

}  // namespace legofeup::lessons
