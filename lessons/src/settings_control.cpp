// The settings table: [initial], the belief the filter starts from, and [control], the
// path-control routine and its gains. The routine's shape waits for the next start; the
// speeds, gains and limits the loop reads at every step.

#include <array>

#include "setting_builders.hpp"

namespace legofeup::lessons {
namespace {

using namespace setting_builders;

constexpr std::array kRoutineKinds = {
    RoutineSpec::Kind::Square,    RoutineSpec::Kind::Line,   RoutineSpec::Kind::Circle,
    RoutineSpec::Kind::Goto,      RoutineSpec::Kind::Manual, RoutineSpec::Kind::Shuttle,
    RoutineSpec::Kind::Piecewise, RoutineSpec::Kind::Random, RoutineSpec::Kind::Rectangle};

const char* routine_name(RoutineSpec::Kind kind) {
    switch (kind) {
        case RoutineSpec::Kind::Square:
            return "square";
        case RoutineSpec::Kind::Line:
            return "line";
        case RoutineSpec::Kind::Circle:
            return "circle";
        case RoutineSpec::Kind::Goto:
            return "goto";
        case RoutineSpec::Kind::Manual:
            return "manual";
        case RoutineSpec::Kind::Shuttle:
            return "shuttle";
        case RoutineSpec::Kind::Piecewise:
            return "piecewise";
        case RoutineSpec::Kind::Random:
            return "random";
        case RoutineSpec::Kind::Rectangle:
            return "rectangle";
    }
    return "square";
}

}  // namespace

void add_initial_and_control_settings(std::vector<Setting>& s) {
    s.push_back(pose_part({.key = "initial.x",
                           .field = "initial.x",
                           .label = in_words("x"),
                           .help = tr_noop("believed start x, m (default: world start)"),
                           .page = SettingPage::InitialBelief,
                           .applies = SettingApplies::NextStart,
                           .use = kEveryRun},
                          &RunConfig::initial_pose, &PoseOverride::x));
    s.push_back(pose_part({.key = "initial.y",
                           .field = "initial.y",
                           .label = in_words("y"),
                           .help = tr_noop("believed start y, m (default: world start)"),
                           .page = SettingPage::InitialBelief,
                           .applies = SettingApplies::NextStart,
                           .use = kEveryRun},
                          &RunConfig::initial_pose, &PoseOverride::y));
    s.push_back(pose_part({.key = "initial.heading_deg",
                           .field = "initial.theta",
                           .label = in_words("heading deg"),
                           .help = tr_noop("believed start heading, ° (default: world start)"),
                           .page = SettingPage::InitialBelief,
                           .applies = SettingApplies::NextStart,
                           .use = kEveryRun},
                          &RunConfig::initial_pose, &PoseOverride::theta, kPi / 180.0));
    s.push_back(real(
        {.key = "initial.var_x",
         .field = "initial.var_x",
         .label = paper_symbol("P0 x"),
         .help = tr_noop("variance of x, m²"),
         .page = SettingPage::InitialBelief,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.initial.var_x; }));
    s.push_back(real(
        {.key = "initial.var_y",
         .field = "initial.var_y",
         .label = paper_symbol("P0 y"),
         .help = tr_noop("variance of y, m²"),
         .page = SettingPage::InitialBelief,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.initial.var_y; }));
    s.push_back(real(
        {.key = "initial.var_theta",
         .field = "initial.var_theta",
         .label = paper_symbol("P0 theta"),
         .help = tr_noop("variance of θ, rad²"),
         .page = SettingPage::InitialBelief,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.initial.var_theta; }));
    s.push_back(boolean(
        {.key = "initial.unknown_pose",
         .field = "initial.unknown_pose",
         .label = in_words("unknown pose"),
         .help = tr_noop("the filter does not know where the robot starts (global "
                         "localisation): a particle filter spreads its cloud over the free "
                         "space, an EKF or UKF takes its mean and covariance; the filter then "
                         "ignores x, y, heading and P0 (odometry still starts at x, y, "
                         "heading)"),
         .page = SettingPage::InitialBelief,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.initial.unknown_pose; }));
    Setting routine =
        described({.key = "control.routine",
                   .field = "control.routine",
                   .label = in_words("routine"),
                   .help = tr_noop("square, line, circle, goto, manual, shuttle (line back and "
                                   "forth), piecewise (corners with stops), random (random places) "
                                   "or rectangle (laps of rectangle_size from rectangle_corner)"),
                   .page = SettingPage::Controller,
                   .applies = SettingApplies::NextStart,
                   .use = kEveryRun},
                  SettingType::Choice);
    for (const RoutineSpec::Kind kind : kRoutineKinds) {
        routine.choices.emplace_back(routine_name(kind));
    }
    routine.get = [](const RunConfig& c) -> SettingValue {
        return std::string(routine_name(c.routine.kind));
    };
    routine.set = [](RunConfig& c, const SettingValue& v) {
        const std::string& name = std::get<std::string>(v);
        for (const RoutineSpec::Kind kind : kRoutineKinds) {
            if (name == routine_name(kind)) {
                c.routine.kind = kind;
            }
        }
    };
    s.push_back(routine);
    s.push_back(choice(
        {.key = "control.steer_by",
         .field = "control.steer_by",
         .label = in_words("steer by"),
         .help = tr_noop("estimate (the paper's loop: the filter's estimate steers the robot) or "
                         "odometry (the path is driven by dead reckoning from the start, "
                         "whatever the filter believes: for global localisation)"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        {SteeringPose::Estimate, SteeringPose::Odometry}, steering_pose_from_string,
        [](auto& c) -> auto& { return c.steer_by; }));
    s.push_back(real(
        {.key = "control.pause",
         .field = "controller.pause",
         .label = in_words("pause"),
         .help = tr_noop("shuttle/piecewise/random: seconds stopped at each waypoint"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.pause; }));
    s.push_back(whole(
        {.key = "control.random_points",
         .field = "control.random_points",
         .label = in_words("random points"),
         .help = tr_noop("how many random places to visit (1 … 100)"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.random_points; }));
    s.push_back(real(
        {.key = "control.v_ref",
         .field = "motion.v_ref",
         .label = paper_symbol("V_ref"),
         .help = tr_noop("reference speed, m/s"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.motion.v_ref; }));
    s.push_back(real(
        {.key = "control.w_ref",
         .field = "motion.w_ref",
         .label = paper_symbol("W_ref"),
         .help = tr_noop("largest turn rate, rad/s"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.motion.w_ref; }));
    s.push_back(real(
        {.key = "control.heading_gain",
         .field = "gains.heading_gain",
         .label = paper_symbol("k_θ"),
         .help = tr_noop("W = k_θ·heading error, 1/s"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.gains.heading_gain; }));
    s.push_back(real(
        {.key = "control.cross_track_gain",
         .field = "gains.cross_track_gain",
         .label = paper_symbol("k_e"),
         .help = tr_noop("approach angle atan(k_e·offset), 1/m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.gains.cross_track_gain; }));
    s.push_back(real(
        {.key = "control.distance_gain",
         .field = "gains.distance_gain",
         .label = paper_symbol("k_ρ"),
         .help = tr_noop("GoXYTheta slows to k_ρ·distance, 1/s"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.gains.distance_gain; }));
    s.push_back(real(
        {.key = "control.position_tolerance",
         .field = "gains.position_tolerance",
         .label = in_words("position tolerance"),
         .help = tr_noop("GoXYTheta arrival distance, m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.gains.position_tolerance; }));
    s.push_back(degrees(
        {.key = "control.heading_tolerance_deg",
         .field = "gains.heading_tolerance",
         .label = in_words("heading tolerance deg"),
         .help = tr_noop("GoXYTheta final heading tolerance, °"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.gains.heading_tolerance; }));
    s.push_back(real(
        {.key = "control.max_wheel_speed",
         .field = "max_wheel_speed",
         .label = in_words("max wheel speed"),
         .help = tr_noop("wheel speed limit, m/s"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::Live,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.max_wheel_speed; }));
    s.push_back(point(
        {.key = "control.line_from",
         .field = "controller.from",
         .label = in_words("line from"),
         .help = tr_noop("first point [x, y], m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.line_from; }));
    s.push_back(point(
        {.key = "control.line_to",
         .field = "controller.to",
         .label = in_words("line to"),
         .help = tr_noop("second point [x, y], m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.line_to; }));
    s.push_back(point(
        {.key = "control.circle_centre",
         .field = "controller.centre",
         .label = in_words("circle centre"),
         .help = tr_noop("centre [x, y], m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.circle_centre; }));
    s.push_back(real(
        {.key = "control.circle_radius",
         .field = "controller.radius",
         .label = in_words("circle radius"),
         .help = tr_noop("radius, m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.circle_radius; }));
    s.push_back(boolean(
        {.key = "control.circle_clockwise",
         .field = "controller.clockwise",
         .label = in_words("circle clockwise"),
         .help = tr_noop("on: clockwise; off: counter-clockwise"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.circle_clockwise; }));
    s.push_back(point(
        {.key = "control.rectangle_corner",
         .field = "controller.rectangle_corner",
         .label = in_words("rectangle corner"),
         .help =
             tr_noop("rectangle: lower-left corner [x, y] where each lap starts, heading +x, m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.rectangle_corner; }));
    s.push_back(point(
        {.key = "control.rectangle_size",
         .field = "controller.rectangle_size",
         .label = in_words("rectangle size"),
         .help =
             tr_noop("rectangle: [width along x, height along y], m (driven counter-clockwise)"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.rectangle_size; }));
    s.push_back(real(
        {.key = "control.goto_x",
         .field = "controller.target.x",
         .label = in_words("goto x"),
         .help = tr_noop("target x, m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.goto_target.x; }));
    s.push_back(real(
        {.key = "control.goto_y",
         .field = "controller.target.y",
         .label = in_words("goto y"),
         .help = tr_noop("target y, m"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.goto_target.y; }));
    s.push_back(degrees(
        {.key = "control.goto_heading_deg",
         .field = "controller.target.theta",
         .label = in_words("goto heading deg"),
         .help = tr_noop("final heading, °"),
         .page = SettingPage::Controller,
         .applies = SettingApplies::NextStart,
         .use = kEveryRun},
        [](auto& c) -> auto& { return c.routine.goto_target.theta; }));
}

}  // namespace legofeup::lessons
