#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinematic_world.hpp"
#include "legofeup/core/controller.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/visit_waypoints.hpp"

namespace legofeup {
namespace {

constexpr double kPeriod = 0.05;  // the loop's control period, s
const MotionLimits kLimits{0.1, 0.8};
const ControllerGains kGains{};
constexpr double kSpeedSlack = 1e-12;

// One period of a perfect-odometry closed loop, as the loop drives it: the estimate is the
// truth, the command is held for the period on an exact unicycle.
struct Tick {
    double time = 0.0;        // s, when the command was issued
    Pose2 pose;               // where the robot was when the command was issued
    ControlOutput out;        // the command
    ControllerStatus status;  // what the routine reported
};

std::vector<Tick> run(Controller& controller, Pose2 pose, double max_seconds,
                      const MotionLimits& limits = kLimits) {
    std::vector<Tick> ticks;
    ControllerStatus status;
    for (int k = 0; k * kPeriod < max_seconds; ++k) {
        Tick tick;
        tick.time = k * kPeriod;
        tick.pose = pose;
        tick.out = run_controller(controller, pose, limits, kGains, kPeriod, status);
        tick.status = status;
        ticks.push_back(tick);
        if (status.finished) {
            break;
        }
        pose = testing::integrate_arc(pose, tick.out.command.v, tick.out.command.w, kPeriod);
        pose.theta = wrap_angle(pose.theta);
    }
    return ticks;
}

double distance(const Pose2& pose, const Vector2& point) {
    return std::hypot(pose.x - point.x(), pose.y - point.y());
}

bool standing_still(const Tick& tick) {
    return tick.out.command.v == 0.0 && tick.out.command.w == 0.0;
}

TEST(VisitWaypoints, ReachesEveryWaypointInOrderWithinTheLimitsAndFinishes) {
    const std::vector<Vector2> points = {{0.6, 0.0}, {0.6, 0.5}, {-0.3, 0.4}, {0.1, -0.5}};
    Controller controller = VisitWaypoints(points, 0.0, 1);
    const std::vector<Tick> ticks = run(controller, {0.0, 0.0, 0.0}, 120.0);

    ASSERT_TRUE(ticks.back().status.finished);
    EXPECT_EQ(ticks.back().status.kind, ControllerKind::VisitWaypoints);
    EXPECT_EQ(ticks.back().status.lap, 1);

    // The target index only ever steps forward by one, and the robot comes within a
    // couple of centimetres of each waypoint while it is the target.
    std::vector<double> closest(points.size(), std::numeric_limits<double>::infinity());
    int previous_index = 0;
    for (const Tick& tick : ticks) {
        const int index = tick.status.segment;
        ASSERT_GE(index, previous_index);
        ASSERT_LE(index, previous_index + 1);
        previous_index = index;
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (static_cast<int>(i) <= index) {
                closest[i] = std::min(closest[i], distance(tick.pose, points[i]));
            }
        }
        EXPECT_LE(std::abs(tick.out.command.v), kLimits.v_ref + kSpeedSlack);
        EXPECT_LE(std::abs(tick.out.command.w), kLimits.w_ref + kSpeedSlack);
    }
    EXPECT_EQ(previous_index, static_cast<int>(points.size()) - 1);
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_LT(closest[i], 0.03) << "waypoint " << i;
    }
    // It stopped at the last one, within the position tolerance, and stands still there.
    EXPECT_LE(distance(ticks.back().pose, points.back()), kGains.position_tolerance);
    EXPECT_TRUE(standing_still(ticks.back()));
    // It really drove: the total time is at least the path length at V_ref.
    const double path_length = 0.6 + 0.5 + std::hypot(0.9, 0.1) + std::hypot(0.4, 0.9);
    EXPECT_GT(ticks.back().time, path_length / kLimits.v_ref);
}

TEST(VisitWaypoints, FollowsTheLegBetweenWaypoints) {
    // Started 0.1 m off the first leg's line; it converges back onto the leg (cross-track
    // steering) rather than cutting straight to the waypoint.
    const std::vector<Vector2> points = {{0.0, 0.0}, {2.0, 0.0}};
    VisitWaypoints routine(points, 0.0, 1);
    Pose2 pose{0.0, 0.0, 0.0};
    int steps = 0;
    double worst_offset_late_in_leg = 0.0;
    while (!routine.finished() && steps < 2000) {
        const ControlOutput out = routine.step(pose, kLimits, kGains, kPeriod);
        if (routine.waypoint_index() == 1 && pose.x > 1.0) {
            worst_offset_late_in_leg = std::max(worst_offset_late_in_leg, std::abs(pose.y));
        }
        if (steps == 0) {
            pose.y = 0.1;  // a disturbance right after the first waypoint is passed
        }
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        ++steps;
    }
    EXPECT_TRUE(routine.finished());
    EXPECT_LT(worst_offset_late_in_leg, 0.005);
}

TEST(VisitWaypoints, PausesForTheStatedTimeAtEachWaypoint) {
    for (const double pause : {1.0, 0.33, 2.5}) {
        const std::vector<Vector2> points = {{0.4, 0.0}, {0.4, 0.3}, {0.0, 0.3}};
        Controller controller = VisitWaypoints(points, pause, 1);
        const std::vector<Tick> ticks = run(controller, {0.0, 0.0, 0.0}, 120.0);
        ASSERT_TRUE(ticks.back().status.finished) << pause;

        // Each stop is a run of still commands while the robot sits on a waypoint; the first
        // two waypoints get one each (the last one finishes the routine instead).
        std::vector<double> stops;
        for (std::size_t k = 0; k + 1 < ticks.size(); ++k) {
            if (!standing_still(ticks[k])) {
                continue;
            }
            std::size_t end = k;
            while (end < ticks.size() && standing_still(ticks[end])) {
                ++end;
            }
            const double stopped_for = static_cast<double>(end - k) * kPeriod;
            if (end < ticks.size()) {  // not the final stop
                stops.push_back(stopped_for);
                for (std::size_t j = k; j < end; ++j) {
                    EXPECT_LE(distance(ticks[j].pose, points[stops.size() - 1]),
                              kGains.position_tolerance);
                }
            }
            k = end;
        }
        ASSERT_EQ(stops.size(), 2u) << pause;
        for (const double stopped_for : stops) {
            EXPECT_NEAR(stopped_for, pause, kPeriod + 1e-9) << pause;
            EXPECT_GE(stopped_for, pause - 1e-9) << pause;  // never leaves early
        }
    }
}

TEST(VisitWaypoints, SlowsDownToStopWithinTheToleranceEvenWhenFast) {
    // At 1 m/s one period is 5 cm, more than the 2 cm tolerance: without slowing down
    // (V ≤ k_ρ·distance) the robot would overshoot the waypoints it must stop at.
    const MotionLimits fast{1.0, 0.8};
    const std::vector<Vector2> points = {{0.93, 0.0}, {0.93, 0.87}, {-0.61, 0.87}};
    Controller controller = VisitWaypoints(points, 0.5, 1);
    const std::vector<Tick> ticks = run(controller, {0.0, 0.0, 0.0}, 120.0, fast);
    ASSERT_TRUE(ticks.back().status.finished);
    int stopped = 0;
    for (const Tick& tick : ticks) {
        if (standing_still(tick)) {
            ++stopped;
            const Vector2& point = points[static_cast<std::size_t>(tick.status.segment)];
            EXPECT_LE(distance(tick.pose, point), kGains.position_tolerance);
        }
    }
    EXPECT_GT(stopped, 2 * 10);  // two pauses of 10 periods, and the end
}

TEST(VisitWaypoints, TurnsOnTheSpotWhenFacingAway) {
    // The waypoint is behind the robot: it must turn in place (V = 0, W at its limit and
    // towards the target) before driving, and drive off only nearly aligned.
    VisitWaypoints routine({{-1.0, 0.05}}, 0.0, 1);
    Pose2 pose{0.0, 0.0, 0.0};
    bool drove = false;
    for (int k = 0; k < 2000 && !routine.finished(); ++k) {
        const ControlOutput out = routine.step(pose, kLimits, kGains, kPeriod);
        if (!drove && out.command.v > 0.0) {
            drove = true;
            EXPECT_LE(std::abs(out.heading_error), kGains.heading_tolerance);
            EXPECT_NEAR(pose.x, 0.0, 1e-12);  // it had not moved while turning
            EXPECT_NEAR(pose.y, 0.0, 1e-12);
        }
        if (!drove) {
            EXPECT_EQ(out.command.v, 0.0);
            if (std::abs(out.heading_error) > 0.5 * kPi) {
                EXPECT_EQ(std::abs(out.command.w), kLimits.w_ref);
            }
        }
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
    }
    EXPECT_TRUE(drove);
    EXPECT_TRUE(routine.finished());
    EXPECT_LE(std::hypot(pose.x + 1.0, pose.y - 0.05), kGains.position_tolerance + 1e-3);
}

TEST(VisitWaypoints, DrivesThroughWithoutPauseButTurnsAtSharpCorners) {
    // A 90° corner without a pause: the robot arrives moving, then turns in place
    // (V = 0 for a while) before the next leg. A 30° bend is driven through without stopping.
    VisitWaypoints sharp({{0.5, 0.0}, {0.5, 0.5}}, 0.0, 1);
    VisitWaypoints gentle({{0.5, 0.0}, {0.5 + 0.5 * std::cos(kPi / 6), 0.5 * std::sin(kPi / 6)}},
                          0.0, 1);
    for (VisitWaypoints* routine : {&sharp, &gentle}) {
        Pose2 pose{0.0, 0.0, 0.0};
        int stopped_steps_after_first = 0;
        while (!routine->finished()) {
            const ControlOutput out = routine->step(pose, kLimits, kGains, kPeriod);
            if (routine->waypoint_index() == 1 && out.command.v == 0.0 && !routine->finished()) {
                ++stopped_steps_after_first;
            }
            pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        }
        if (routine == &sharp) {
            EXPECT_GT(stopped_steps_after_first, 10);  // ≥ 0.5 s turning ≈ (π/2 − 2°)/W_ref
        } else {
            EXPECT_EQ(stopped_steps_after_first, 0);
        }
    }
}

TEST(VisitWaypoints, RepeatsForTheRequestedLaps) {
    const std::vector<Vector2> points = {{0.3, 0.0}, {0.3, 0.3}, {0.0, 0.3}, {0.0, 0.0}};
    Controller twice = VisitWaypoints(points, 0.0, 2);
    const std::vector<Tick> ticks = run(twice, {0.0, 0.0, 0.0}, 120.0);
    ASSERT_TRUE(ticks.back().status.finished);
    EXPECT_EQ(ticks.back().status.lap, 2);
    int wraps = 0;
    for (std::size_t k = 1; k < ticks.size(); ++k) {
        wraps += ticks[k].status.segment < ticks[k - 1].status.segment ? 1 : 0;
    }
    EXPECT_EQ(wraps, 1);  // back to waypoint 0 once, between the two laps

    Controller for_ever = VisitWaypoints(points, 0.0, 0);
    const std::vector<Tick> endless = run(for_ever, {0.0, 0.0, 0.0}, 100.0);
    EXPECT_FALSE(endless.back().status.finished);
    EXPECT_GE(endless.back().status.lap, 3);  // a lap: 1.2 m at V_ref + 4 turns ≈ 21 s
}

TEST(VisitWaypoints, WithoutWaypointsItIsFinishedAndStill) {
    Controller controller = VisitWaypoints({}, 1.0, 1);
    ControllerStatus status;
    const ControlOutput out =
        run_controller(controller, {0.3, 0.2, 1.0}, kLimits, kGains, kPeriod, status);
    EXPECT_TRUE(status.finished);
    EXPECT_EQ(out.command.v, 0.0);
    EXPECT_EQ(out.command.w, 0.0);
    EXPECT_STREQ(to_string(status.kind), "visit_waypoints");
}

std::vector<ConfigIssue> controller_issues(const Controller& controller) {
    LoopConfig config;
    config.controller = controller;
    std::vector<ConfigIssue> issues = validate(config);
    issues.erase(std::remove_if(issues.begin(), issues.end(),
                                [](const ConfigIssue& issue) {
                                    return issue.field.rfind("controller.", 0) != 0;
                                }),
                 issues.end());
    return issues;
}

TEST(VisitWaypoints, ValidationNamesTheBadSetting) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(controller_issues(VisitWaypoints({{0.1, 0.2}}, 600.0, 1)).empty());
    EXPECT_TRUE(controller_issues(VisitWaypoints({{0.1, 0.2}, {0.0, 0.0}}, 0.0, 0)).empty());

    const auto fields = [](const std::vector<ConfigIssue>& issues) {
        std::vector<std::string> names;
        for (const ConfigIssue& issue : issues) {
            names.push_back(issue.field);
        }
        return names;
    };
    EXPECT_EQ(fields(controller_issues(VisitWaypoints({}, 1.0, 1))),
              std::vector<std::string>{"controller.waypoints"});
    EXPECT_EQ(fields(controller_issues(VisitWaypoints({{0.0, 0.0}, {nan, 1.0}}, 1.0, 1))),
              std::vector<std::string>{"controller.waypoints[1]"});
    EXPECT_EQ(fields(controller_issues(VisitWaypoints({{0.0, 0.0}}, -0.1, 1))),
              std::vector<std::string>{"controller.pause"});
    EXPECT_EQ(fields(controller_issues(VisitWaypoints({{0.0, 0.0}}, 600.5, 1))),
              std::vector<std::string>{"controller.pause"});
    EXPECT_EQ(fields(controller_issues(VisitWaypoints({{0.0, 0.0}}, nan, 1))),
              std::vector<std::string>{"controller.pause"});
}

TEST(RandomWaypoints, AreDeterministicInsideTheBoxAndSpaced) {
    const Vector2 lower(-0.8, -0.6);
    const Vector2 upper(0.8, 0.6);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const std::vector<Vector2> points = random_waypoints(seed, 30, lower, upper, 0.5);
        ASSERT_EQ(points.size(), 30u);
        EXPECT_EQ(points, random_waypoints(seed, 30, lower, upper, 0.5));
        EXPECT_NE(points, random_waypoints(seed + 1000, 30, lower, upper, 0.5));
        for (std::size_t i = 0; i < points.size(); ++i) {
            EXPECT_GE(points[i].x(), lower.x());
            EXPECT_LT(points[i].x(), upper.x());
            EXPECT_GE(points[i].y(), lower.y());
            EXPECT_LT(points[i].y(), upper.y());
            if (i > 0) {
                EXPECT_GE((points[i] - points[i - 1]).norm(), 0.5);
            }
        }
    }
}

TEST(RandomWaypoints, UseTheStandardsEngineAndTheTop53Bits) {
    // std::mt19937_64 seeded with 5489 (its default) first gives 14514284786278117030
    // (the standard fixes the engine's output); x = lower + (out >> 11)·2⁻⁵³·width.
    const double u = static_cast<double>(14514284786278117030ULL >> 11) * 0x1.0p-53;
    const std::vector<Vector2> points = random_waypoints(5489, 1, {-1.0, 0.0}, {3.0, 1.0}, 0.0);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(points[0].x(), -1.0 + u * 4.0);
}

TEST(RandomWaypoints, SpreadOverTheBox) {
    // Uniform draws: over 4000 points each quadrant of the box holds a quarter, give or
    // take 4σ of a binomial (σ = √(n·¼·¾) ≈ 27).
    const std::vector<Vector2> points = random_waypoints(7, 4000, {0.0, 0.0}, {2.0, 1.0}, 0.0);
    int counts[2][2] = {{0, 0}, {0, 0}};
    for (const Vector2& p : points) {
        ++counts[p.x() < 1.0 ? 0 : 1][p.y() < 0.5 ? 0 : 1];
    }
    for (const auto& row : counts) {
        for (const int count : row) {
            EXPECT_NEAR(count, 1000, 110);
        }
    }
}

TEST(RandomWaypoints, KeepTheSpacingEvenWhenItIsHardToDraw) {
    // Half the diagonal of a 1 × 1 box: only the far corners qualify from the centre.
    const double spacing = 0.5 * std::sqrt(2.0);
    const std::vector<Vector2> points = random_waypoints(3, 50, {0.0, 0.0}, {1.0, 1.0}, spacing);
    for (std::size_t i = 1; i < points.size(); ++i) {
        EXPECT_GE((points[i] - points[i - 1]).norm(), spacing - 1e-12);
    }
}

TEST(RandomWaypoints, RefuseImpossibleRequests) {
    EXPECT_THROW(random_waypoints(1, -1, {0, 0}, {1, 1}, 0.1), std::invalid_argument);
    EXPECT_THROW(random_waypoints(1, 3, {1, 0}, {0, 1}, 0.1), std::invalid_argument);
    EXPECT_THROW(random_waypoints(1, 3, {0, 0}, {1, 1}, 0.8), std::invalid_argument);
    EXPECT_THROW(random_waypoints(1, 3, {0, 0}, {1, 1}, -0.1), std::invalid_argument);
    EXPECT_TRUE(random_waypoints(1, 0, {0, 0}, {1, 1}, 0.1).empty());
}

}  // namespace
}  // namespace legofeup
