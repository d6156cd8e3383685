// Benchmarks of the simulator and of whole headless runs (Google Benchmark). Run from a
// release build:   build/release/bench/legofeup_sim_bench
// "real_time_factor" is simulated seconds per wall-clock second (physics, sensors and the
// loop included); quote the median.

#include <benchmark/benchmark.h>

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
        benchmark::DoNotOptimize(result.metrics.rms_position_error);
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

}  // namespace

BENCHMARK_MAIN();
