// The loop step must not touch the heap (it runs at 20 Hz for hours, next to a GUI, and on
// the real-robot path). support/allocation_counter.cpp counts
// every allocation made while a step runs.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "kinematic_world.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"

namespace legofeup {
namespace {

TEST(LoopAllocations, CountingWorks) {
    int* probe = nullptr;
    EXPECT_EQ(testing::allocations_of([&] { probe = new int(3); }), 1);
    delete probe;
}

/// Drives `loop` one lap; returns the allocations its steps made and counts the applied
/// wall updates in `updates`.
long allocations_over_a_lap(LegoFeupLoop& loop, int& updates) {
    testing::KinematicRobot robot(loop.config().initial.pose, testing::KinematicRobotParams{});
    const std::vector<Wall>& walls = loop.config().walls.walls();
    long allocations = 0;
    for (int k = 0; k < 1900; ++k) {
        SensorFrame frame;
        frame.time = 0.05 * k;
        frame.encoder_counts = robot.encoder_counts();
        const auto distances = testing::true_ir_distances(robot.pose(), walls);
        frame.ir_adc = {testing::gp2d120_adc(distances[0]), testing::gp2d120_adc(distances[1])};

        const LoopSnapshot* snapshot = nullptr;
        allocations += testing::allocations_of([&] { snapshot = &loop.step(frame); });

        updates += snapshot->update.status == StepStatus::Applied ? 1 : 0;
        robot.drive(snapshot->wheels, 0.05);
    }
    return allocations;
}

TEST(LoopAllocations, StepNeverAllocates) {
    // A full lap: straights, corners (segment switches), walls (association and updates).
    LegoFeupLoop loop(LoopConfig{});
    int updates = 0;
    EXPECT_EQ(allocations_over_a_lap(loop, updates), 0);
    EXPECT_GT(updates, 300);
}

// Every estimator of the registry, with its shadow running beside it: the estimators are
// made when the kind is configured, never in a step.
TEST(LoopAllocations, StepNeverAllocatesWithAnyEstimatorAndItsShadow) {
    for (const PoseEstimatorEntry& entry : pose_estimators()) {
        LoopConfig config;
        config.lesson.kind = entry.kind;
        config.lesson.compare_kinds = true;
        LegoFeupLoop loop(config);
        ASSERT_EQ(loop.filter().kind(), entry.kind);
        int updates = 0;
        EXPECT_EQ(allocations_over_a_lap(loop, updates), 0) << to_string(entry.kind);
        EXPECT_GT(updates, 300) << to_string(entry.kind);
        EXPECT_EQ(loop.snapshot().shadow.kind, entry.shadow) << to_string(entry.kind);
    }
}

}  // namespace
}  // namespace legofeup
