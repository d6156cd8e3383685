// One pose-filter period of the beacon lesson (paper 002): an odometry prediction and two
// bearing updates, for the EKF and for the UKF (the paper found the UKF ≈ 4× the EKF).
// The particle filter's parts per particle and step (items = particles, so items/s is the
// particle-steps per second): motion sampling, the wall lesson's IR update, four bearing
// updates (PythonRobotics' particle filter, 4 range landmarks and 100 particles, measured
// 22.6 µs a particle-step on this machine kind), a whole wall-lesson period, and the cloud
// the GUI is sent each step (sample_cloud: the live run's worker thins 10,000 particles to
// kParticlesShown).
// Run from a release build:
//   build/release/bench/legofeup_filters_bench
// Each benchmark repeats 10 times and reports mean / median / stddev; quote the median.

#include <benchmark/benchmark.h>

#include <array>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/particle_cloud.hpp"
#include "legofeup/core/particle_filter.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"
#include "legofeup/core/wall_measurement.hpp"
#include "legofeup/core/walls.hpp"

namespace {

using namespace legofeup;

template <class Filter>
void predict_and_two_bearings(benchmark::State& state) {
    Filter filter;
    const StateVector x0(0.2, -0.3, 0.4);
    const StateCovariance P0 = Eigen::Vector3d(1e-2, 1e-2, 1e-2).asDiagonal();
    const OdometryProcessModel model(increment_from_motion(0.005, 0.01, 0.12),
                                     Eigen::Vector2d(1e-6, 1e-5).asDiagonal());
    const std::array<BeaconBearingMeasurement, 2> bearings{
        BeaconBearingMeasurement(Vector2(1.5, 1.5), 0.8, kPi / 8.0),
        BeaconBearingMeasurement(Vector2(-1.5, 1.0), 2.2, kPi / 8.0)};
    for (auto _ : state) {
        filter.reset(x0, P0);  // the same step every iteration
        benchmark::DoNotOptimize(filter.predict(model));
        for (const BeaconBearingMeasurement& bearing : bearings) {
            benchmark::DoNotOptimize(filter.update(bearing).nis);
        }
        benchmark::ClobberMemory();
    }
}

void BM_EkfPredictTwoBearings(benchmark::State& state) {
    predict_and_two_bearings<ExtendedKalmanFilter<PoseStateSpace>>(state);
}
void BM_UkfPredictTwoBearings(benchmark::State& state) {
    predict_and_two_bearings<UnscentedKalmanFilter<PoseStateSpace>>(state);
}
BENCHMARK(BM_EkfPredictTwoBearings)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_UkfPredictTwoBearings)->Repetitions(10)->ReportAggregatesOnly(true);

ParticleFilter particle_filter_of(benchmark::State& state) {
    PoseEstimatorSettings settings;
    settings.particles.particle_count = static_cast<int>(state.range(0));
    ParticleFilter filter;
    filter.configure(settings);
    filter.reset(StateVector(-1.0, -1.0, 0.0), Eigen::Vector3d(1e-4, 1e-4, 1e-3).asDiagonal());
    return filter;
}

const OdometryProcessModel kStep(increment_from_motion(0.005, 0.01, 0.12),
                                 Eigen::Vector2d(1e-7, 1e-5).asDiagonal());

// The standard arena's first wall, seen from inside at 0.21 m by both sensors.
WallMeasurement first_wall() {
    const WallMap walls = standard_arena_walls(ArenaSpec{});
    return WallMeasurement(walls.line(0), -1, observe_wall(0.21, 0.21, IrMount{}),
                           Eigen::Vector2d(1e-4, 1e-4).asDiagonal());
}

void BM_PfMotionSampling(benchmark::State& state) {
    ParticleFilter filter = particle_filter_of(state);
    for (auto _ : state) {
        benchmark::DoNotOptimize(filter.predict(kStep));
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_PfWallUpdate(benchmark::State& state) {
    ParticleFilter filter = particle_filter_of(state);
    const WallMeasurement wall = first_wall();
    for (auto _ : state) {
        benchmark::DoNotOptimize(filter.update(wall).nis);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

void BM_PfFourBearings(benchmark::State& state) {
    ParticleFilter filter = particle_filter_of(state);
    const std::array<BeaconBearingMeasurement, 4> bearings{
        BeaconBearingMeasurement(Vector2(1.5, 1.5), 0.8, kPi / 8.0),
        BeaconBearingMeasurement(Vector2(-1.5, 1.0), 2.2, kPi / 8.0),
        BeaconBearingMeasurement(Vector2(1.5, -1.5), -0.6, kPi / 8.0),
        BeaconBearingMeasurement(Vector2(-1.5, -1.0), -2.4, kPi / 8.0)};
    for (auto _ : state) {
        filter.predict(kStep);
        for (const BeaconBearingMeasurement& bearing : bearings) {
            benchmark::DoNotOptimize(filter.update(bearing).nis);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// One period of the wall lesson near a wall: predict, then the IR update.
void BM_PfWallLessonPeriod(benchmark::State& state) {
    ParticleFilter filter = particle_filter_of(state);
    const WallMeasurement wall = first_wall();
    for (auto _ : state) {
        filter.predict(kStep);
        benchmark::DoNotOptimize(filter.update(wall).nis);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

// The cloud a live run sends with every sample: N particles thinned to kParticlesShown. The
// thinning alone, into a vector reserved once; LiveRun also allocates a fresh vector for each
// sample (16 kB), since the sample is handed to the GUI thread, which keeps it.
void BM_PfSampleCloud(benchmark::State& state) {
    ParticleFilter filter = particle_filter_of(state);
    filter.update(first_wall());  // unequal weights, as after a scan
    std::vector<ParticlePoint> cloud;
    for (auto _ : state) {
        thin_particles(filter.xs(), filter.ys(), filter.thetas(), filter.weights(), kParticlesShown,
                       cloud);
        benchmark::DoNotOptimize(cloud.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(BM_PfMotionSampling)->Arg(1000)->Arg(10000)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PfWallUpdate)->Arg(1000)->Arg(10000)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PfFourBearings)->Arg(100)->Arg(1000)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PfWallLessonPeriod)->Arg(1000)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PfSampleCloud)->Arg(1000)->Arg(10000)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
