// The laser lesson runs ray casting and ICP every 100 ms of simulated time, at ≥ 100× real
// time: after a warm-up they must not touch the heap (only Icp2d::set_reference, which
// rebuilds nanoflann's tree, may). This program replaces the global allocation functions to
// count every allocation made while they run.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (g_counting.load(std::memory_order_relaxed)) {
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    }
    if (void* memory = std::malloc(size == 0 ? 1 : size)) {
        return memory;
    }
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    return operator new(size);
}
void operator delete(void* memory) noexcept {
    std::free(memory);
}
void operator delete[](void* memory) noexcept {
    std::free(memory);
}
void operator delete(void* memory, std::size_t) noexcept {
    std::free(memory);
}
void operator delete[](void* memory, std::size_t) noexcept {
    std::free(memory);
}

namespace legofeup {
namespace {

TEST(ScanAllocations, CountingWorks) {
    g_allocations = 0;
    g_counting = true;
    auto* probe = new int(3);
    g_counting = false;
    delete probe;
    EXPECT_EQ(g_allocations.load(), 1);
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

        g_allocations = 0;
        g_counting = true;
        for (int repeat = 0; repeat < 3; ++repeat) {
            expected_scan(office, predicted, urg, expected);
            scan_to_points(expected, urg, Pose2{}, reference);
            scan_to_points(measured, urg, Pose2{}, source);
            const IcpResult result = icp.align(source);
            EXPECT_TRUE(result.converged);
        }
        g_counting = false;
        EXPECT_EQ(g_allocations.load(), 0) << to_string(metric);
    }
}

}  // namespace
}  // namespace legofeup
