// Benchmarks of the LegoFeup loop (Google Benchmark). Run from a release build:
//   build/release/bench/legofeup_core_bench
// Each benchmark repeats 10 times and reports mean / median / stddev; quote the median.
// The loop step also reports allocations_per_step: this program replaces the global
// operator new with one that counts (the step must stay at 0).

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/odometry_process_model.hpp"

namespace {

std::atomic<long> g_allocations{0};

}  // namespace

void* operator new(std::size_t size) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* memory = std::malloc(size == 0 ? 1 : size)) {
        return memory;
    }
    throw std::bad_alloc();
}
void operator delete(void* memory) noexcept {
    std::free(memory);
}
void operator delete(void* memory, std::size_t /*size*/) noexcept {
    std::free(memory);
}

namespace {

using namespace legofeup;

// Frames of the robot driving along the first wall (x from −0.95 to −0.05, 15 cm from it)
// at 0.1 m/s: every frame has both IR readings in range, so every step runs predict,
// observation, association, update and control.
std::vector<SensorFrame> frames_along_first_wall(const LoopConfig& config) {
    std::vector<SensorFrame> frames;
    const double codo = config.odometry.codo_right;
    for (int k = 0; k < 180; ++k) {
        const Pose2 pose{-0.95 + 0.005 * k, -1.0, 0.0};
        SensorFrame frame;
        frame.time = 0.05 * k;
        frame.sequence = static_cast<std::uint32_t>(k);
        const auto counts = static_cast<std::int32_t>(0.005 * k * codo);
        frame.encoder_counts = {counts, counts};
        for (int sensor = 0; sensor < kIrSensorCount; ++sensor) {
            const BeamHit hit =
                cast_beam(ir_beam(pose, config.ir_mount, sensor), config.walls.line(0), 0.0);
            frame.ir_adc[static_cast<std::size_t>(sensor)] = quantize_adc(
                adc_from_distance(hit.range, config.ir_curve), config.ir_curve.adc_max);
        }
        frames.push_back(frame);
    }
    return frames;
}

void BM_LoopStepWithWallUpdate(benchmark::State& state) {
    const LoopConfig config;
    const std::vector<SensorFrame> frames = frames_along_first_wall(config);
    LegoFeupLoop loop(config);
    std::size_t next = 0;
    long updates = 0;
    long steps = 0;
    long allocations = 0;
    for (auto _ : state) {
        const long before = g_allocations.load(std::memory_order_relaxed);
        const LoopSnapshot& snapshot = loop.step(frames[next]);
        allocations += g_allocations.load(std::memory_order_relaxed) - before;
        benchmark::DoNotOptimize(snapshot.wheels);
        updates += snapshot.update.status == StepStatus::Applied ? 1 : 0;
        ++steps;
        if (++next == frames.size()) {
            state.PauseTiming();
            loop.reset();  // start the pass along the wall again
            next = 0;
            state.ResumeTiming();
        }
    }
    state.counters["updates_per_step"] =
        benchmark::Counter(static_cast<double>(updates) / static_cast<double>(steps));
    state.counters["allocations_per_step"] =
        benchmark::Counter(static_cast<double>(allocations) / static_cast<double>(steps));
}
BENCHMARK(BM_LoopStepWithWallUpdate)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_EkfPredictAndWallUpdate(benchmark::State& state) {
    const WallMap walls = standard_arena_walls(ArenaSpec{});
    const Eigen::Matrix2d Q = Eigen::Vector2d(1e-7, 1e-5).asDiagonal();
    const Eigen::Matrix2d R = Eigen::Vector2d(1e-4, 1e-4).asDiagonal();
    const OdometryIncrement increment = odometry_increment(13, 14, OdometryParams{});
    const WallObservation observation = observe_wall(0.151, 0.149, IrMount{});
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ekf.reset(StateVector(-0.5, -1.0, 0.0), StateVector(1e-4, 1e-4, 1e-3).asDiagonal());
    for (auto _ : state) {
        ekf.predict(OdometryProcessModel(increment, Q));
        const auto report = ekf.update(WallMeasurement(walls.line(0), 1, observation, R));
        benchmark::DoNotOptimize(report.nis);
    }
}
BENCHMARK(BM_EkfPredictAndWallUpdate)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_EkfPredict(benchmark::State& state) {
    const Eigen::Matrix2d Q = Eigen::Vector2d(1e-7, 1e-5).asDiagonal();
    const OdometryIncrement increment = odometry_increment(13, 14, OdometryParams{});
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ekf.reset(StateVector(-0.5, -1.0, 0.0), StateVector(1e-4, 1e-4, 1e-3).asDiagonal());
    for (auto _ : state) {
        benchmark::DoNotOptimize(ekf.predict(OdometryProcessModel(increment, Q)));
        if (ekf.covariance()(0, 0) > 1.0) {  // keep P in its usual range
            ekf.reset(StateVector(-0.5, -1.0, 0.0), StateVector(1e-4, 1e-4, 1e-3).asDiagonal());
        }
    }
}
BENCHMARK(BM_EkfPredict)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_WallAssociation(benchmark::State& state) {
    const LoopConfig config;
    const WallObservation observation = observe_wall(0.151, 0.149, config.ir_mount);
    const PoseBelief belief{{-0.5, -1.0, 0.01}, StateVector(1e-4, 1e-4, 1e-3).asDiagonal()};
    const Eigen::Matrix2d R = Eigen::Vector2d(config.filter.r11, config.filter.r22).asDiagonal();
    for (auto _ : state) {
        const AssociationResult result =
            associate_wall(belief, observation, config.walls, config.ir_mount,
                           config.ir_curve.max_range, R, config.association);
        benchmark::DoNotOptimize(result.wall);
    }
}
BENCHMARK(BM_WallAssociation)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_ChiSquareQuantile(benchmark::State& state) {
    for (auto _ : state) {
        benchmark::DoNotOptimize(average_chi_square_interval(3, 50, 0.95));
    }
}
BENCHMARK(BM_ChiSquareQuantile)->Repetitions(3)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
