// The laser lesson's per-scan cost (paper 001, issue 9): ray casting the expected scan of a
// URG-04LX (682 beams) in a 12 m × 8 m office map of 0.05 m cells, and one ICP match of the
// measured scan against it — kd-tree build, alignment, and both together — for both metrics.
// The target: one ICP match under 2 ms. Also the Monte Carlo localisation's laser
// model: scoring one particle's pose with the likelihood field (per end point: items/s is end
// points/s, so its inverse is the time per end point). Run from a release build:
//   build/release/bench/legofeup_scan_bench
// Each benchmark repeats 10 times and reports mean / median / stddev; quote the median.
// Counters: iterations and matched points of the alignment (per call).

#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/likelihood_field.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace {

using namespace legofeup;

/// Poses in the office's rooms and corridor.
const std::vector<Pose2> kPoses{{2.0, 2.0, 0.3},  {6.0, 3.5, 1.2}, {10.0, 4.0, -2.0},
                                {2.5, 4.5, -0.8}, {6.5, 6.8, 2.9}, {10.5, 1.0, 0.7},
                                {3.0, 7.0, -1.6}, {9.0, 5.5, -0.2}};

/// A scan's points in the scanner's frame, with 10 mm range noise when `rng` is given.
std::vector<Vector2> scan_points(const OccupancyGrid& grid, const Pose2& pose, std::mt19937* rng) {
    const ScanGeometry urg;
    LaserScan scan;
    expected_scan(grid, pose, urg, scan);
    if (rng != nullptr) {
        std::normal_distribution<double> noise(0.0, 10.0);
        for (int beam = 0; beam < urg.beam_count; ++beam) {
            std::uint16_t& mm = scan.range_mm[static_cast<std::size_t>(beam)];
            if (mm >= kRangeFirstValid) {
                mm = static_cast<std::uint16_t>(std::max(20.0, mm + noise(*rng)));
            }
        }
    }
    std::vector<Vector2> points;
    scan_to_points(scan, urg, Pose2{}, points);
    return points;
}

/// One matching problem per pose: the expected scan at the predicted pose (reference) and
/// the measured scan at the true pose, 5 cm / 3 cm / 2° away (source).
struct MatchCase {
    std::vector<Vector2> reference;
    std::vector<Vector2> source;
};
std::vector<MatchCase> match_cases() {
    const OccupancyGrid office = testing::office_grid();
    std::mt19937 rng(1);
    std::vector<MatchCase> cases;
    for (const Pose2& predicted : kPoses) {
        const Pose2 truth = compose(predicted, Pose2{0.05, -0.03, degrees_to_radians(2.0)});
        cases.push_back(
            {scan_points(office, predicted, nullptr), scan_points(office, truth, &rng)});
    }
    return cases;
}

IcpParams params_for(const benchmark::State& state) {
    IcpParams params;
    params.metric = state.range(0) == 0 ? IcpMetric::PointToPoint : IcpMetric::PointToLine;
    params.max_iterations = 100;
    params.max_correspondence_distance = 0.5;
    return params;
}

void BM_ExpectedScan682Beams(benchmark::State& state) {
    const OccupancyGrid office = testing::office_grid();
    const ScanGeometry urg;
    LaserScan scan;
    std::size_t next = 0;
    for (auto _ : state) {
        expected_scan(office, kPoses[next], urg, scan);
        benchmark::DoNotOptimize(scan);
        next = (next + 1) % kPoses.size();
    }
}
BENCHMARK(BM_ExpectedScan682Beams)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_IcpKdTreeBuild(benchmark::State& state) {
    const std::vector<MatchCase> cases = match_cases();
    Icp2d icp;
    std::size_t next = 0;
    for (auto _ : state) {
        icp.set_reference(cases[next].reference);
        benchmark::DoNotOptimize(icp.reference_size());
        next = (next + 1) % cases.size();
    }
}
BENCHMARK(BM_IcpKdTreeBuild)->Repetitions(10)->ReportAggregatesOnly(true);

/// The alignment alone, against a reference (tree and normals) built before the loop.
void BM_IcpAlign(benchmark::State& state) {
    const std::vector<MatchCase> cases = match_cases();
    std::vector<Icp2d> matchers;
    for (const MatchCase& c : cases) {
        matchers.emplace_back(params_for(state));
        matchers.back().set_reference(c.reference);
        matchers.back().align(c.source);  // warm-up: normals, buffers
    }
    std::size_t next = 0;
    double iterations = 0.0;
    double matched = 0.0;
    for (auto _ : state) {
        const IcpResult result = matchers[next].align(cases[next].source);
        benchmark::DoNotOptimize(result);
        iterations += result.iterations;
        matched += result.matched_points;
        next = (next + 1) % cases.size();
    }
    state.counters["iterations"] =
        benchmark::Counter(iterations, benchmark::Counter::kAvgIterations);
    state.counters["matched"] = benchmark::Counter(matched, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_IcpAlign)
    ->ArgName("point_to_line")
    ->Arg(0)
    ->Arg(1)
    ->Repetitions(10)
    ->ReportAggregatesOnly(true);

/// One whole match as the lesson runs it per scan: a new reference (kd-tree, and the normals
/// for point-to-line), then the alignment.
void BM_IcpMatchWithBuild(benchmark::State& state) {
    const std::vector<MatchCase> cases = match_cases();
    Icp2d icp(params_for(state));
    std::size_t next = 0;
    for (auto _ : state) {
        icp.set_reference(cases[next].reference);
        benchmark::DoNotOptimize(icp.align(cases[next].source));
        next = (next + 1) % cases.size();
    }
}
BENCHMARK(BM_IcpMatchWithBuild)
    ->ArgName("point_to_line")
    ->Arg(0)
    ->Arg(1)
    ->Repetitions(10)
    ->ReportAggregatesOnly(true);

/// Everything the localiser does per scan: ray-cast the expected scan at the predicted pose,
/// turn both scans into points, build the reference and align (point-to-line).
void BM_ScanPeriodPointToLine(benchmark::State& state) {
    const OccupancyGrid office = testing::office_grid();
    const ScanGeometry urg;
    std::mt19937 rng(2);
    std::vector<LaserScan> measured(kPoses.size());
    for (std::size_t i = 0; i < kPoses.size(); ++i) {
        const Pose2 truth = compose(kPoses[i], Pose2{0.05, -0.03, degrees_to_radians(2.0)});
        expected_scan(office, truth, urg, measured[i]);
    }
    IcpParams params;
    params.max_correspondence_distance = 0.5;
    Icp2d icp(params);
    LaserScan expected;
    std::vector<Vector2> reference;
    std::vector<Vector2> source;
    reference.reserve(kMaxScanBeams);
    source.reserve(kMaxScanBeams);
    std::size_t next = 0;
    for (auto _ : state) {
        expected_scan(office, kPoses[next], urg, expected);
        scan_to_points(expected, urg, Pose2{}, reference);
        scan_to_points(measured[next], urg, Pose2{}, source);
        icp.set_reference(reference);
        benchmark::DoNotOptimize(icp.align(source));
        next = (next + 1) % kPoses.size();
    }
}
BENCHMARK(BM_ScanPeriodPointToLine)->Repetitions(10)->ReportAggregatesOnly(true);

/// The particle filter's laser update, per particle: the likelihood field's log-likelihood of
/// one scan's end points (every 8th beam of the URG: ~85) at a particle's pose. The scans are
/// ray-cast at the eight office poses; the particles scatter about each (σ 0.1 m, 0.05 rad),
/// so the end points fall near walls and away from them as in a real cloud. Items are end
/// points: the report's items/s inverted is the time per end point.
void BM_LikelihoodFieldScanLogLikelihood(benchmark::State& state) {
    const LikelihoodFieldParams params;
    const LikelihoodField field(testing::office_grid(), params.max_distance);
    const ScanGeometry urg;
    constexpr int kParticlesPerScan = 64;
    std::mt19937 rng(3);
    std::normal_distribution<double> position_noise(0.0, 0.1);
    std::normal_distribution<double> heading_noise(0.0, 0.05);
    std::vector<std::vector<Vector2>> endpoints(kPoses.size());
    std::vector<Pose2> particles;
    for (std::size_t i = 0; i < kPoses.size(); ++i) {
        LaserScan scan;
        expected_scan(field.grid(), kPoses[i], urg, scan);
        scan_endpoints(scan, urg, Pose2{}, params.beam_stride, endpoints[i]);
        for (int k = 0; k < kParticlesPerScan; ++k) {
            particles.push_back({kPoses[i].x + position_noise(rng),
                                 kPoses[i].y + position_noise(rng),
                                 kPoses[i].theta + heading_noise(rng)});
        }
    }
    std::size_t next = 0;
    std::int64_t points = 0;
    for (auto _ : state) {
        const std::vector<Vector2>& scan_points = endpoints[next / kParticlesPerScan];
        benchmark::DoNotOptimize(
            scan_log_likelihood(field, particles[next], scan_points, params, urg.range_max));
        points += static_cast<std::int64_t>(scan_points.size());
        next = (next + 1) % particles.size();
    }
    state.SetItemsProcessed(points);
    state.counters["endpoints"] =
        benchmark::Counter(static_cast<double>(points), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_LikelihoodFieldScanLogLikelihood)->Repetitions(10)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
