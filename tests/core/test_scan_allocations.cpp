// The laser lesson runs ray casting and ICP every 100 ms of simulated time, at ≥ 100× real
// time: after a warm-up they must not touch the heap (only Icp2d::set_reference, which
// rebuilds nanoflann's tree, may). support/allocation_counter.cpp
// counts every allocation made while they run.
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace legofeup {
namespace {

TEST(ScanAllocations, CountingWorks) {
    int* probe = nullptr;
    EXPECT_EQ(testing::allocations_of([&] { probe = new int(3); }), 1);
    delete probe;
}

TEST(ScanAllocations, RayCastingAndAlignmentDoNotAllocateAfterWarmUp) {
    const OccupancyGrid office = testing::office_grid();
    const ScanGeometry urg;
    const Pose2 predicted{2.0, 2.0, 0.3};
    const Pose2 truth = compose(predicted, Pose2{0.05, -0.03, 0.03});
    LaserScan expected;
    LaserScan measured;
    std::vector<Vector2> reference;
    std::vector<Vector2> source;
    reference.reserve(kMaxScanBeams);
    source.reserve(kMaxScanBeams);
    expected_scan(office, truth, urg, measured);
    for (const IcpMetric metric : {IcpMetric::PointToPoint, IcpMetric::PointToLine}) {
        IcpParams params;
        params.metric = metric;
        Icp2d icp(params);
        // Warm-up: the first alignment sizes the pair buffer (and the normals).
        expected_scan(office, predicted, urg, expected);
        scan_to_points(expected, urg, Pose2{}, reference);
        icp.set_reference(reference);
        scan_to_points(measured, urg, Pose2{}, source);
        ASSERT_TRUE(icp.align(source).converged);

        const long allocations = testing::allocations_of([&] {
            for (int repeat = 0; repeat < 3; ++repeat) {
                expected_scan(office, predicted, urg, expected);
                scan_to_points(expected, urg, Pose2{}, reference);
                scan_to_points(measured, urg, Pose2{}, source);
                const IcpResult result = icp.align(source);
                EXPECT_TRUE(result.converged);
            }
        });
        EXPECT_EQ(allocations, 0) << to_string(metric);
    }
}

}  // namespace
}  // namespace legofeup
