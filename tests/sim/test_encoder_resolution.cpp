// The encoders count at the robot's resolution, counts_per_turn a wheel turn: a frame reports
// ⌊turns · counts_per_turn⌋ of each wheel as a 32-bit counter that wraps. (They once counted
// degrees whatever the setting, so 720 counts a turn halved every distance the loop measured.)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/sim/simulator.hpp"
#include "world_test_support.hpp"

namespace legofeup::sim {
namespace {

RobotSpec robot_counting(double counts_per_turn) {
    RobotSpec robot;
    robot.counts_per_turn = counts_per_turn;
    return robot;
}

void run_periods(Simulator& simulator, int periods) {
    for (int i = 0; i < periods; ++i) {
        simulator.step_control_period();
    }
}

/// ⌊a / b⌋ for integers, b > 0 (C++ division truncates towards zero instead).
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    return a / b - (a % b != 0 && a < 0 ? 1 : 0);
}

class CountsPerTurn : public ::testing::TestWithParam<double> {};

// Spinning on the spot at exactly one wheel turn per second (surface speed π·D with the
// nominal D, which is what the motors convert with). After 5 s the motors' lag (τ = 50 ms,
// e^−100 left) is gone, so the next 10 s are exactly 10 turns of each wheel: 10·counts_per_turn
// counts, ±1 for where the floors fall. Degrees would be 3600 whatever the setting.
TEST_P(CountsPerTurn, TenWheelTurnsGiveTenTimesCountsPerTurn) {
    const double counts_per_turn = GetParam();
    const RobotSpec robot = robot_counting(counts_per_turn);
    Simulator simulator(test::open_floor(), robot, {}, 1);
    const double one_turn_per_second = kPi * robot.wheel_diameter;  // m/s
    simulator.set_wheel_command({one_turn_per_second, -one_turn_per_second});
    const int periods_per_second =
        static_cast<int>(std::lround(1.0 / simulator.settings().control_period));
    run_periods(simulator, 5 * periods_per_second);
    const auto before = simulator.sensor_frame().encoder_counts;
    run_periods(simulator, 10 * periods_per_second);
    const auto after = simulator.sensor_frame().encoder_counts;
    EXPECT_NEAR(after[0] - before[0], 10.0 * counts_per_turn, 1.0);   // right: forwards
    EXPECT_NEAR(after[1] - before[1], -10.0 * counts_per_turn, 1.0);  // left: backwards
}

INSTANTIATE_TEST_SUITE_P(Resolutions, CountsPerTurn, ::testing::Values(180.0, 360.0, 720.0));

// The resolution changes what the encoders report, never the physics: three robots that differ
// only in counts_per_turn move bit for bit alike, and at every frame, forwards and backwards,
// the 360-count one's counts are ⌊degrees⌋, the 720-count one's ⌊2·degrees⌋ ∈ {2c, 2c + 1} and
// the 180-count one's ⌊degrees / 2⌋ = ⌊c / 2⌋ (rounded down, not towards zero, when negative).
TEST(EncoderResolution, CountsAreTheFloorOfTurnsTimesCountsPerTurnAtEveryFrame) {
    std::vector<std::unique_ptr<Simulator>> robots;  // 360, 720 and 180 counts a turn
    for (const double counts_per_turn : {360.0, 720.0, 180.0}) {
        robots.push_back(std::make_unique<Simulator>(
            test::open_floor(), robot_counting(counts_per_turn), SimulatorSettings{}, 1));
    }
    // A curve forwards, then backwards far enough that both wheels' counts go negative.
    const std::vector<std::pair<WheelSpeeds, int>> legs = {{{0.12, 0.05}, 40},
                                                           {{-0.15, -0.09}, 120}};
    int negative_frames = 0;
    for (const auto& [command, periods] : legs) {
        for (const auto& robot : robots) {
            robot->set_wheel_command(command);
        }
        for (int i = 0; i < periods; ++i) {
            for (const auto& robot : robots) {
                robot->step_control_period();
            }
            const GroundTruth truth = robots[0]->ground_truth();
            for (const std::size_t other : {1U, 2U}) {
                ASSERT_EQ(robots[other]->ground_truth().pose.x, truth.pose.x);
                ASSERT_EQ(robots[other]->ground_truth().pose.theta, truth.pose.theta);
            }
            for (std::size_t wheel = 0; wheel < 2; ++wheel) {
                const std::int64_t degrees = robots[0]->sensor_frame().encoder_counts[wheel];
                const std::int64_t fine = robots[1]->sensor_frame().encoder_counts[wheel];
                const std::int64_t coarse = robots[2]->sensor_frame().encoder_counts[wheel];
                EXPECT_TRUE(fine == 2 * degrees || fine == 2 * degrees + 1)
                    << "wheel " << wheel << ": " << fine << " at 720 counts, " << degrees
                    << " at 360";
                EXPECT_EQ(coarse, floor_div(degrees, 2)) << "wheel " << wheel;
                negative_frames += degrees < 0 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(negative_frames, 40);  // the backwards leg did take the counts below zero
}

// A fine encoder on a fast motor passes 2³¹ counts within seconds; the counter then wraps as
// the NXT's SLONG counters (and the protocol's i32) do, so the loop's wrapping difference
// (encoder_delta) still gives each period's true increment, ω·dt·counts_per_turn/2π.
TEST(EncoderResolution, CountersWrapAtThirtyTwoBitsAndTheirDifferencesStayTrue) {
    RobotSpec robot = robot_counting(1e6);
    robot.max_motor_rpm = 10000.0;
    robot.motor_time_constant = 0.0;  // at full speed from the first step
    Simulator simulator(test::open_floor(), robot, {}, 1);
    simulator.set_wheel_command({100.0, 100.0});  // clipped at 10000 rpm
    const double per_period =
        robot.max_motor_rpm / 60.0 * simulator.settings().control_period * robot.counts_per_turn;
    std::int32_t last = simulator.sensor_frame().encoder_counts[0];
    bool wrapped = false;
    const int periods = static_cast<int>(std::ceil(2.5 * 4294967296.0 / per_period));
    for (int i = 0; i < periods; ++i) {
        simulator.step_control_period();
        const std::int32_t now = simulator.sensor_frame().encoder_counts[0];
        ASSERT_NEAR(static_cast<double>(encoder_delta(now, last)), per_period, 1.0) << i;
        wrapped = wrapped || now < last;
        last = now;
    }
    EXPECT_TRUE(wrapped);
}

}  // namespace
}  // namespace legofeup::sim
