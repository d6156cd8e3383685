#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_world.hpp"
#include "legofeup/core/controller.hpp"
#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/path_controllers.hpp"

namespace legofeup {
namespace {

constexpr double kPeriod = 0.05;  // the loop's control period, s
const MotionLimits kLimits{0.1, 0.8};
const ControllerGains kGains{};

// Closed loop of a routine and a perfect unicycle (the estimate is the truth): integrates the
// commanded (V, W) exactly over each period, as the kinematic robot does.
template <class Routine>
Pose2 drive(Routine& routine, Pose2 pose, double seconds, ControlOutput* last = nullptr) {
    for (double t = 0.0; t < seconds; t += kPeriod) {
        const ControlOutput out = routine.step(pose, kLimits, kGains);
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        pose.theta = wrap_angle(pose.theta);
        if (last != nullptr) {
            *last = out;
        }
    }
    return pose;
}

TEST(WheelSpeeds, EquationOneAndItsInverse) {
    const WheelSpeeds wheels = wheel_speeds({0.1, 0.5}, 0.12);
    EXPECT_NEAR(wheels.right, 0.1 + 0.03, 1e-15);  // V1 = V + b·W/2: right wheel
    EXPECT_NEAR(wheels.left, 0.1 - 0.03, 1e-15);
    const VelocityCommand back = velocity_command(wheels, 0.12);
    EXPECT_NEAR(back.v, 0.1, 1e-15);
    EXPECT_NEAR(back.w, 0.5, 1e-12);
}

TEST(WheelSpeeds, LimitingKeepsTheCurvature) {
    const WheelSpeeds limited = limit_wheel_speeds({0.6, 0.2}, 0.3);
    EXPECT_NEAR(limited.right, 0.3, 1e-15);
    EXPECT_NEAR(limited.left, 0.1, 1e-15);
    const WheelSpeeds untouched = limit_wheel_speeds({0.2, -0.25}, 0.3);
    EXPECT_EQ(untouched.right, 0.2);
    EXPECT_EQ(untouched.left, -0.25);
}

TEST(FollowLine, ConvergesToTheLineFromPerturbedStarts) {
    const FollowLine line({-1.0, -1.0}, {20.0, -1.0});
    for (double offset : {-0.4, -0.1, 0.05, 0.3}) {
        for (double heading_deg : {-75.0, -20.0, 0.0, 45.0, 120.0}) {
            const Pose2 start{-1.0, -1.0 + offset, degrees_to_radians(heading_deg)};
            ControlOutput last;
            const Pose2 end = drive(line, start, 40.0, &last);
            EXPECT_NEAR(end.y, -1.0, 0.002) << offset << " m, " << heading_deg << "°";
            EXPECT_NEAR(end.theta, 0.0, degrees_to_radians(1.0));
            EXPECT_NEAR(last.command.v, kLimits.v_ref, 1e-3);  // cruising at V_ref again
        }
    }
}

TEST(FollowLine, OffsetNeverGrowsOnceHeadedBack) {
    // From 30 cm to the left, already facing along the line: |e| decreases monotonically.
    const FollowLine line({0.0, 0.0}, {10.0, 0.0});
    Pose2 pose{0.0, 0.3, 0.0};
    double previous = 0.3;
    for (int k = 0; k < 600; ++k) {
        const ControlOutput out = line.step(pose, kLimits, kGains);
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        EXPECT_LE(std::abs(pose.y), previous + 1e-9) << k;
        previous = std::abs(pose.y);
    }
    EXPECT_LT(previous, 0.005);
}

TEST(FollowLine, FollowsAnyDirectionAndReportsTheEnd) {
    const FollowLine diagonal({0.0, 0.0}, {-1.0, 1.0});  // heading 135°
    ControlOutput last;
    const Pose2 end = drive(diagonal, {0.0, 0.1, 0.0}, 25.0, &last);
    EXPECT_NEAR(end.x + end.y, 0.0, 0.003);  // on the line y = −x
    EXPECT_NEAR(end.theta, degrees_to_radians(135.0), degrees_to_radians(1.0));
    EXPECT_TRUE(last.finished);  // passed (−1, 1) after ~2.1 m
    EXPECT_FALSE(diagonal.step({0.0, 0.0, 0.0}, kLimits, kGains).finished);
}

TEST(GoXYTheta, ReachesTheTargetPoseAndStops) {
    const Pose2 target{0.5, 0.3, degrees_to_radians(90.0)};
    for (const Pose2& start : {Pose2{-1.0, -1.0, 0.0}, Pose2{1.2, 0.9, 2.5}, Pose2{0.5, 0.0, -1.0},
                               Pose2{0.45, 0.35, 3.0}}) {
        GoXYTheta go(target);
        ControlOutput last;
        const Pose2 end = drive(go, start, 90.0, &last);
        EXPECT_TRUE(last.finished) << start.x << ", " << start.y;
        EXPECT_LE(std::hypot(end.x - target.x, end.y - target.y), 2.0 * kGains.position_tolerance);
        EXPECT_LE(std::abs(wrap_angle(end.theta - target.theta)), kGains.heading_tolerance);
        EXPECT_EQ(last.command.v, 0.0);
        EXPECT_EQ(last.command.w, 0.0);
    }
}

TEST(FollowCircle, ConvergesToTheRadiusInBothDirections) {
    for (bool ccw : {true, false}) {
        for (const Pose2& start :
             {Pose2{0.0, 0.0, 0.0}, Pose2{0.8, 0.3, 2.0}, Pose2{-0.1, -0.5, -1.0}}) {
            FollowCircle circle({0.0, 0.0}, 0.5, ccw);
            Pose2 pose = drive(circle, start, 60.0);
            const double radius = std::hypot(pose.x, pose.y);
            EXPECT_NEAR(radius, 0.5, 0.005) << (ccw ? "ccw" : "cw");
            // Moving the commanded way round: the bearing advances with the right sign.
            const double bearing = std::atan2(pose.y, pose.x);
            pose = drive(circle, pose, 2.0);
            const double advance = wrap_angle(std::atan2(pose.y, pose.x) - bearing);
            EXPECT_GT(ccw ? advance : -advance, 0.3);
        }
    }
}

TEST(FollowCircle, ArcIsFinishedAfterItsSweep) {
    FollowCircle arc({0.0, 0.0}, 0.5, true, kPi / 2.0);
    Pose2 pose{0.5, 0.0, kPi / 2.0};
    int steps = 0;
    ControlOutput out = arc.step(pose, kLimits, kGains);
    while (!out.finished && steps < 1000) {
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        out = arc.step(pose, kLimits, kGains);
        ++steps;
    }
    // A quarter of a 0.5 m circle is 0.785 m: ≈7.9 s at 0.1 m/s.
    EXPECT_NEAR(steps * kPeriod, 0.25 * 2.0 * kPi * 0.5 / 0.1, 0.5);
    EXPECT_NEAR(std::atan2(pose.y, pose.x), kPi / 2.0, 0.05);
}

TEST(FollowPath, ClosesTheSquare) {
    FollowPath path(square_path(ArenaSpec{}), 1);
    Pose2 pose{-1.0, -1.0, 0.0};
    const Vector2 corners[] = {{1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}, {-1.0, -1.0}};
    double closest[4] = {1e9, 1e9, 1e9, 1e9};
    double worst_offset_mid_side = 0.0;
    double t = 0.0;
    for (; t < 200.0 && !path.finished(); t += kPeriod) {
        const ControlOutput out = path.step(pose, kLimits, kGains);
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        pose.theta = wrap_angle(pose.theta);
        for (int c = 0; c < 4; ++c) {
            closest[c] =
                std::min(closest[c], std::hypot(pose.x - corners[c].x(), pose.y - corners[c].y()));
        }
        // Along the middle of every side the robot stays on the square.
        const double half = std::max(std::abs(pose.x), std::abs(pose.y));
        if (std::min(std::abs(pose.x), std::abs(pose.y)) < 0.6) {
            worst_offset_mid_side = std::max(worst_offset_mid_side, std::abs(half - 1.0));
        }
    }
    EXPECT_TRUE(path.finished());
    EXPECT_EQ(path.completed_laps(), 1);
    for (double distance : closest) {
        EXPECT_LT(distance, 0.03);
    }
    EXPECT_LT(worst_offset_mid_side, 0.01);
    EXPECT_NEAR(pose.x, -1.0, 0.03);
    EXPECT_NEAR(pose.y, -1.0, 0.03);
    // 8 m at 0.1 m/s plus four turns on the spot: a lap takes 80–100 s.
    EXPECT_GT(t, 80.0);
    EXPECT_LT(t, 100.0);
    const ControlOutput stopped = path.step(pose, kLimits, kGains);
    EXPECT_TRUE(stopped.finished);
    EXPECT_EQ(stopped.command.v, 0.0);
}

TEST(FollowPath, RecoversFromAPerturbedStartAndCountsLaps) {
    FollowPath path(square_path(ArenaSpec{}), 2);
    Pose2 pose{-1.25, -0.8, degrees_to_radians(40.0)};
    int lap_changes = 0;
    int last_lap = 0;
    for (double t = 0.0; t < 400.0 && !path.finished(); t += kPeriod) {
        const ControlOutput out = path.step(pose, kLimits, kGains);
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        pose.theta = wrap_angle(pose.theta);
        if (path.completed_laps() != last_lap) {
            ++lap_changes;
            last_lap = path.completed_laps();
        }
    }
    EXPECT_TRUE(path.finished());
    EXPECT_EQ(lap_changes, 2);
    EXPECT_NEAR(pose.x, -1.0, 0.03);
    EXPECT_NEAR(pose.y, -1.0, 0.03);
}

TEST(FollowPath, MixesLinesAndArcs) {
    // A stadium: two straights joined by half circles of radius 0.5.
    std::vector<PathSegment> stadium{
        LineSegment{{0.0, -0.5}, {1.0, -0.5}}, ArcSegment{{1.0, 0.0}, 0.5, true, kPi},
        LineSegment{{1.0, 0.5}, {0.0, 0.5}}, ArcSegment{{0.0, 0.0}, 0.5, true, kPi}};
    FollowPath path(stadium, 1);
    Pose2 pose{0.0, -0.5, 0.0};
    double worst = 0.0;
    for (double t = 0.0; t < 120.0 && !path.finished(); t += kPeriod) {
        const ControlOutput out = path.step(pose, kLimits, kGains);
        pose = testing::integrate_arc(pose, out.command.v, out.command.w, kPeriod);
        pose.theta = wrap_angle(pose.theta);
        // Distance to the stadium outline.
        const double cx = std::clamp(pose.x, 0.0, 1.0);
        worst = std::max(worst, std::abs(std::hypot(pose.x - cx, pose.y) - 0.5));
    }
    EXPECT_TRUE(path.finished());
    EXPECT_LT(worst, 0.03);
}

TEST(Controller, ManualDriveIsLimitedAndReportsItsKind) {
    Controller controller = ManualDrive{};
    std::get<ManualDrive>(controller).set_command({0.5, -3.0});
    ControllerStatus status;
    const ControlOutput out = run_controller(controller, {}, kLimits, kGains, kPeriod, status);
    EXPECT_EQ(out.command.v, kLimits.v_ref);
    EXPECT_EQ(out.command.w, -kLimits.w_ref);
    EXPECT_EQ(status.kind, ControllerKind::Manual);
    EXPECT_EQ(status.segment, -1);

    Controller path = FollowPath(square_path(ArenaSpec{}), 0);
    run_controller(path, {-1.0, -1.0, 0.0}, kLimits, kGains, kPeriod, status);
    EXPECT_EQ(status.kind, ControllerKind::FollowPath);
    EXPECT_EQ(status.segment, 0);
    EXPECT_STREQ(to_string(kind_of(Controller{GoXYTheta({})})), "GoXYTheta");
}

}  // namespace
}  // namespace legofeup
