// The loop step must not touch the heap (it runs at 20 Hz for hours, next to a GUI, and on
// the real-robot path). support/allocation_counter.cpp counts
// every allocation made while a step runs.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "kinematic_world.hpp"
#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup {
namespace {

TEST(LoopAllocations, CountingWorks) {
    int* probe = nullptr;
    EXPECT_EQ(testing::allocations_of([&] { probe = new int(3); }), 1);
    delete probe;
}

TEST(LoopAllocations, StepNeverAllocates) {
    // A full lap: straights, corners (segment switches), walls (association and updates).
    LegoFeupLoop loop(LoopConfig{});
    testing::KinematicRobot robot(loop.config().initial.pose, testing::KinematicRobotParams{});
    const std::vector<Wall>& walls = loop.config().walls.walls();
    long allocations = 0;
    int updates = 0;
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
    EXPECT_GT(updates, 300);
    EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace legofeup
