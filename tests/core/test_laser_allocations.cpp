// The laser localisation's step must not touch the heap except for the ICP's kd-tree
// rebuild over each expected scan: the ray casting, the point buffers and the ICP's pairs
// reuse what they reserved. support/allocation_counter.cpp counts
// every allocation made while a step runs, and compares a scan's step with rebuilding the
// same kd-tree alone.
#include <gtest/gtest.h>

#include <random>

#include "allocation_counter.hpp"
#include "kinematic_world.hpp"
#include "laser_room.hpp"
#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup {
namespace {

using testing::allocations_of;

TEST(LaserAllocations, OnlyTheKdTreeRebuildAllocates) {
    LoopConfig config;
    config.lesson.localisation = Localisation::Laser;
    config.map = testing::laser_test_room();
    LegoFeupLoop loop(config);
    testing::KinematicRobot robot(config.initial.pose, testing::KinematicRobotParams{});
    std::mt19937_64 rng(4);
    Icp2d reference_only(config.lesson.laser.icp);
    std::vector<Vector2> expected_points;
    expected_points.reserve(kMaxScanBeams);
    long scan_steps = 0;
    long excess = 0;  // allocations of scan steps beyond their kd-tree rebuild
    long other = 0;   // allocations of steps without a scan
    for (int k = 0; k < 400; ++k) {
        SensorFrame frame;
        frame.time = 0.05 * k;
        frame.encoder_counts = robot.encoder_counts();
        frame.has_laser_scan = k % 2 == 0;
        if (frame.has_laser_scan) {
            testing::synthesize_scan(*config.map, robot.pose(), config.lesson.laser.geometry, 0.01,
                                     rng, frame.laser);
        }
        const LoopSnapshot* snapshot = nullptr;
        const long step = allocations_of([&] { snapshot = &loop.step(frame); });
        if (k >= 10) {  // after warming up
            if (frame.has_laser_scan) {
                ASSERT_TRUE(snapshot->laser.matched);
                scan_steps += 1;
                scan_to_points(snapshot->laser.expected, config.lesson.laser.geometry, Pose2{},
                               expected_points);
                const long tree =
                    allocations_of([&] { reference_only.set_reference(expected_points); });
                excess += std::max(0L, step - tree);
            } else {
                other += step;
            }
        } else if (frame.has_laser_scan) {
            scan_to_points(snapshot->laser.expected, config.lesson.laser.geometry, Pose2{},
                           expected_points);
            reference_only.set_reference(expected_points);  // warm it up the same way
        }
        robot.drive(snapshot->wheels, 0.05);
    }
    EXPECT_GT(scan_steps, 150);
    EXPECT_EQ(other, 0);
    EXPECT_EQ(excess, 0);
}

}  // namespace
}  // namespace legofeup
