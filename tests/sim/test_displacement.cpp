// Paper 002's "sudden change in robot position" (SimulatorSettings::displacement) and paper
// 001's kidnapping to a known place (SimulatorSettings::kidnap), and GroundTruth::teleports.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "legofeup/core/angles.hpp"
#include "legofeup/sim/simulator.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

// Where the robot stands on the open floor before it is displaced.
const Pose2 kFloorStart{0.2, -0.3, 0.4};

SimulatorSettings kidnapping(double time) {
    SimulatorSettings settings;
    settings.displacement = {true, time, 1.0, 0.5, -kPi / 2.0};
    return settings;
}

TEST(Displacement, MovesTheRobotOnceInTheFirstPeriodEndingAtItsTime) {
    Simulator simulator(test::open_floor(kFloorStart), RobotSpec{}, kidnapping(0.97), 1);
    for (int i = 0; i < 19; ++i) {  // to 0.95 s: not yet
        simulator.step_control_period();
    }
    EXPECT_NEAR(simulator.ground_truth().pose.x, 0.2, 1e-6);
    simulator.step_control_period();  // the period ending at 1.0 s ≥ 0.97 s
    Pose2 pose = simulator.ground_truth().pose;
    EXPECT_NEAR(simulator.time(), 1.0, 1e-9);
    EXPECT_NEAR(pose.x, 1.2, 1e-6);
    EXPECT_NEAR(pose.y, 0.2, 1e-6);
    EXPECT_NEAR(pose.theta, 0.4 - kPi / 2.0, 1e-6);
    for (int i = 0; i < 40; ++i) {  // only once
        simulator.step_control_period();
    }
    EXPECT_NEAR(simulator.ground_truth().pose.x, 1.2, 1e-6);
    EXPECT_EQ(simulator.sensor_frame().encoder_counts[0], 0);  // the encoders did not see it

    simulator.reset({0.0, 0.0, 0.0}, 2);  // a reset arms it again
    for (int i = 0; i < 20; ++i) {
        simulator.step_control_period();
    }
    pose = simulator.ground_truth().pose;
    EXPECT_NEAR(pose.x, 1.0, 1e-6);
    EXPECT_NEAR(pose.y, 0.5, 1e-6);
}

TEST(Displacement, TheEncodersOnlyCountTheWheelsWhileMoving) {
    const auto run = [](const SimulatorSettings& settings) {
        Simulator simulator(test::open_floor(kFloorStart), RobotSpec{}, settings, 1);
        simulator.set_wheel_command({0.1, 0.1});
        for (int i = 0; i < 60; ++i) {
            simulator.step_control_period();
        }
        return std::pair(simulator.sensor_frame(), simulator.ground_truth());
    };
    const auto [plain_frame, plain_truth] = run({});
    const auto [moved_frame, moved_truth] = run(kidnapping(1.0));
    // The robot stops for an instant (teleport leaves it at rest), so the wheels lose a
    // little while the motors pull it back to speed; the encoders count the rotation only.
    EXPECT_NEAR(moved_frame.encoder_counts[0], plain_frame.encoder_counts[0], 3.0);
    EXPECT_EQ(moved_frame.encoder_counts[0], moved_frame.encoder_counts[1]);
    EXPECT_NEAR(moved_truth.pose.theta, plain_truth.pose.theta - kPi / 2.0, 1e-3);
    // Driving 3 s along 0.4 rad, then along 0.4 − π/2 from the displaced point.
    EXPECT_GT(std::abs(moved_truth.pose.x - plain_truth.pose.x), 0.5);
}

TEST(Displacement, IsValidated) {
    SimulatorSettings settings = kidnapping(1.0);
    settings.displacement.dtheta = std::nan("");
    settings.displacement.time = -1.0;
    std::string fields;
    for (const ConfigIssue& issue : validate(settings)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "simulator.displacement.time simulator.displacement.dtheta ");
}

SimulatorSettings kidnap_at(double time, const Pose2& pose) {
    SimulatorSettings settings;
    settings.kidnap = {true, time, pose};
    return settings;
}

TEST(Kidnap, PutsTheRobotAtItsPoseOnceInTheFirstPeriodEndingAtItsTime) {
    const Pose2 place{-0.7, 0.9, 2.0};
    Simulator simulator(test::open_floor(kFloorStart), RobotSpec{}, kidnap_at(0.97, place), 1);
    for (int i = 0; i < 19; ++i) {  // to 0.95 s: not yet
        simulator.step_control_period();
    }
    EXPECT_NEAR(simulator.ground_truth().pose.x, 0.2, 1e-6);
    EXPECT_EQ(simulator.ground_truth().teleports, 0U);
    simulator.step_control_period();  // the period ending at 1.0 s ≥ 0.97 s
    GroundTruth truth = simulator.ground_truth();
    EXPECT_NEAR(truth.pose.x, place.x, 1e-6);
    EXPECT_NEAR(truth.pose.y, place.y, 1e-6);
    EXPECT_NEAR(truth.pose.theta, place.theta, 1e-6);
    EXPECT_EQ(truth.teleports, 1U);
    simulator.set_wheel_command({0.1, 0.1});
    for (int i = 0; i < 40; ++i) {  // only once: it drives off from there
        simulator.step_control_period();
    }
    truth = simulator.ground_truth();
    EXPECT_EQ(truth.teleports, 1U);
    // About 2 s at 0.1 m/s along θ = 2 rad from the place it was put down.
    EXPECT_NEAR(truth.pose.x - place.x, std::cos(place.theta) * 0.19, 0.02);
    EXPECT_NEAR(truth.pose.y - place.y, std::sin(place.theta) * 0.19, 0.02);
    // The encoders saw the drive, not the kidnapping: both wheels, the same count.
    EXPECT_NEAR(simulator.sensor_frame().encoder_counts[0], 0.19 / (kPi * 0.0432) * 360.0, 30.0);

    simulator.reset({0.0, 0.0, 0.0}, 2);  // a reset arms it again and clears the count
    EXPECT_EQ(simulator.ground_truth().teleports, 0U);
    for (int i = 0; i < 20; ++i) {
        simulator.step_control_period();
    }
    truth = simulator.ground_truth();
    EXPECT_NEAR(truth.pose.x, place.x, 1e-6);
    EXPECT_EQ(truth.teleports, 1U);
}

TEST(Kidnap, AfterADisplacementInTheSamePeriodTheAbsolutePoseWins) {
    SimulatorSettings settings = kidnap_at(0.5, {1.0, 1.0, 0.0});
    settings.displacement = {true, 0.5, 0.3, 0.0, 0.0};
    Simulator simulator(test::open_floor(kFloorStart), RobotSpec{}, settings, 1);
    for (int i = 0; i < 10; ++i) {
        simulator.step_control_period();
    }
    const GroundTruth truth = simulator.ground_truth();
    EXPECT_NEAR(truth.pose.x, 1.0, 1e-6);
    EXPECT_NEAR(truth.pose.y, 1.0, 1e-6);
    EXPECT_EQ(truth.teleports, 2U);  // both happened
}

TEST(Kidnap, EveryTeleportIsCountedInTheGroundTruth) {
    Simulator simulator(test::open_floor(kFloorStart), RobotSpec{}, {}, 1);
    EXPECT_EQ(simulator.ground_truth().teleports, 0U);
    simulator.teleport({0.5, 0.5, 0.0});
    simulator.step_control_period();
    simulator.teleport({0.6, 0.5, 0.0});
    EXPECT_EQ(simulator.ground_truth().teleports, 2U);
    simulator.reset({0.0, 0.0, 0.0}, 1);
    EXPECT_EQ(simulator.ground_truth().teleports, 0U);
}

TEST(Kidnap, IsValidated) {
    SimulatorSettings settings = kidnap_at(-0.5, {std::nan(""), 2000.0, 1.0});
    std::string fields;
    for (const ConfigIssue& issue : validate(settings)) {
        fields += issue.field + " ";
    }
    EXPECT_EQ(fields, "simulator.kidnap.time simulator.kidnap.pose.x simulator.kidnap.pose.y ");
    settings.kidnap = {true, 1.0, {0.0, 0.0, std::numeric_limits<double>::infinity()}};
    ASSERT_EQ(validate(settings).size(), 1U);
    EXPECT_EQ(validate(settings)[0].field, "simulator.kidnap.pose.theta");
    EXPECT_THROW(Simulator(test::open_floor(kFloorStart), RobotSpec{}, settings, 1),
                 std::invalid_argument);
}

}  // namespace
}  // namespace legofeup::sim
