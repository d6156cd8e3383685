// The loop step must not touch the heap (it runs at 20 Hz for hours, next to a GUI, and on
// the real-robot path). This program replaces the global allocation functions to count
// every allocation made while a step runs.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "kinematic_world.hpp"
#include "legofeup/core/legofeup_loop.hpp"

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

TEST(LoopAllocations, CountingWorks) {
    g_allocations = 0;
    g_counting = true;
    auto* probe = new int(3);
    g_counting = false;
    delete probe;
    EXPECT_EQ(g_allocations.load(), 1);
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

        g_allocations = 0;
        g_counting = true;
        const LoopSnapshot& snapshot = loop.step(frame);
        g_counting = false;
        allocations += g_allocations.load();

        updates += snapshot.update.status == StepStatus::Applied ? 1 : 0;
        robot.drive(snapshot.wheels, 0.05);
    }
    EXPECT_GT(updates, 300);
    EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace legofeup
