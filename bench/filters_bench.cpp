// One pose-filter period of the beacon lesson (paper 002): an odometry prediction and two
// bearing updates, for the EKF and for the UKF (the paper found the UKF ≈ 4× the EKF).
// Run from a release build:
//   build/release/bench/legofeup_filters_bench
// Each benchmark repeats 10 times and reports mean / median / stddev; quote the median.

#include <benchmark/benchmark.h>

#include <array>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"

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

}  // namespace

BENCHMARK_MAIN();
