// Benchmarks of the simulator and of whole headless runs (Google Benchmark). Run from a
// release build:   build/release/bench/legofeup_sim_bench
// "real_time_factor" is simulated seconds per wall-clock second (physics, sensors and the
// loop included); quote the median.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/sim/simulator.hpp"

namespace {

using namespace legofeup;

// The standard scenario: experiment f (IR noise, slip, systematic errors), two laps.
void BM_StandardScenarioTwoLaps(benchmark::State& state) {
    const lessons::ResolvedRun run = lessons::resolve(lessons::find_experiment("f")->config);
    double simulated = 0.0;
    for (auto _ : state) {
        const lessons::RunResult result = lessons::run_lockstep(run);
        simulated += result.metrics.duration;
        benchmark::DoNotOptimize(result.metrics.truth);
    }
    state.counters["real_time_factor"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_StandardScenarioTwoLaps)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// Experiments a to f, two laps each, one after the other.
void BM_AllSixExperimentsTwoLaps(benchmark::State& state) {
    std::vector<lessons::ResolvedRun> runs;
    for (const lessons::Experiment& experiment : lessons::legofeup_experiments()) {
        runs.push_back(lessons::resolve(experiment.config));
    }
    for (auto _ : state) {
        for (const lessons::ResolvedRun& run : runs) {
            benchmark::DoNotOptimize(lessons::run_lockstep(run).metrics.steps);
        }
    }
}
BENCHMARK(BM_AllSixExperimentsTwoLaps)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// The simulator alone: one 50 ms control period (5 physics steps, IR sampling).
void BM_SimulatorControlPeriod(benchmark::State& state) {
    sim::RobotSpec robot;
    robot.ir_noise = 0.01;
    robot.slip_noise = 0.001;
    sim::Simulator simulator(sim::standard_arena(), robot, {}, 1);
    simulator.set_wheel_command({0.1, 0.1});
    int periods = 0;
    for (auto _ : state) {
        simulator.step_control_period();
        if (++periods == 200) {  // stay on the arena's first side
            state.PauseTiming();
            simulator.reset(sim::standard_arena().start, 1);
            simulator.set_wheel_command({0.1, 0.1});
            periods = 0;
            state.ResumeTiming();
        }
    }
}
BENCHMARK(BM_SimulatorControlPeriod)->Repetitions(5)->ReportAggregatesOnly(true);

// An office of 12 m × 8 m at 0.05 m per cell (240 × 160 cells), built here from code: outer
// walls 0.1 m thick, three rooms and a corridor with doors, desks, and a round pillar (a
// staircase of cells, the merge's worst case). World frame centred on the office.
std::shared_ptr<const OccupancyGrid> office_map() {
    constexpr int kWidth = 240;
    constexpr int kHeight = 160;
    constexpr double kCell = 0.05;
    std::vector<CellState> cells(kWidth * kHeight, CellState::Free);
    const auto fill = [&](double x0, double y0, double x1, double y1) {  // metres, grid frame
        const auto cell = [](double metres) {
            return static_cast<int>(std::lround(metres / kCell));
        };
        for (int row = cell(y0); row < cell(y1); ++row) {
            for (int col = cell(x0); col < cell(x1); ++col) {
                cells[static_cast<std::size_t>(row * kWidth + col)] = CellState::Occupied;
            }
        }
    };
    fill(0.0, 0.0, 12.0, 0.1);  // outer walls
    fill(0.0, 7.9, 12.0, 8.0);
    fill(0.0, 0.0, 0.1, 8.0);
    fill(11.9, 0.0, 12.0, 8.0);
    fill(4.0, 0.0, 4.1, 1.5);  // a wall at x = 4 m with a door at 1.5–2.5 m
    fill(4.0, 2.5, 4.1, 8.0);
    fill(8.0, 0.0, 8.1, 5.0);  // a wall at x = 8 m with a door at 5–6 m
    fill(8.0, 6.0, 8.1, 8.0);
    fill(0.0, 4.0, 2.5, 4.1);  // a wall at y = 4 m, left room, door at 2.5–3.5 m
    fill(3.5, 4.0, 4.0, 4.1);
    for (const double x : {1.0, 5.0, 9.5}) {  // desks 1.2 m × 0.6 m
        fill(x, 1.0, x + 1.2, 1.6);
        fill(x, 6.0, x + 1.2, 6.6);
    }
    for (int row = 0; row < kHeight; ++row) {  // a pillar of radius 0.3 m at (6, 4) m
        for (int col = 0; col < kWidth; ++col) {
            if (std::hypot((col + 0.5) * kCell - 6.0, (row + 0.5) * kCell - 4.0) <= 0.3) {
                cells[static_cast<std::size_t>(row * kWidth + col)] = CellState::Occupied;
            }
        }
    }
    return std::make_shared<const OccupancyGrid>(kWidth, kHeight, kCell, Pose2{-6.0, -4.0, 0.0},
                                                 std::move(cells));
}

// The simulator in the office, one 50 ms control period, with the laser scanner (682 beams
// every 100 ms, so a scan every other period) on (argument 1) or off (0): twice the
// difference of the two is what one scan costs.
void BM_OfficeControlPeriod(benchmark::State& state) {
    sim::WorldSpec world;
    world.name = "office";
    world.map = office_map();
    world.start = {-4.0, -2.0, 0.3};
    sim::RobotSpec robot;
    robot.laser_scanner.enabled = state.range(0) != 0;
    robot.laser_scanner.dropout_probability = 0.01;
    sim::Simulator simulator(world, robot, {}, 1);
    simulator.set_wheel_command({0.12, 0.1});  // a wide circle inside the first room
    int periods = 0;
    for (auto _ : state) {
        simulator.step_control_period();
        benchmark::DoNotOptimize(simulator.sensor_frame().laser.range_mm[0]);
        if (++periods == 400) {
            state.PauseTiming();
            simulator.reset(world.start, 1);
            simulator.set_wheel_command({0.12, 0.1});
            periods = 0;
            state.ResumeTiming();
        }
    }
}
BENCHMARK(BM_OfficeControlPeriod)
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
