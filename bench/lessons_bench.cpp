// Monte Carlo throughput (Google Benchmark): 1,000 runs of experiment f (two laps each) on
// 1 and 2 jobs, the target being under 30 s with 2 jobs. Run from a release build:
//   build/release/bench/legofeup_lessons_bench
// "runs_per_s" is the rate; the speed-up is the 2-job rate over the 1-job rate. On a machine
// busy with other work, "cpu_ms_per_run" (all threads) shows what a run costs regardless.
// BM_ParticleFilterRun: whole headless runs with the particle filter on one core (simulator,
// loop and filter), "x_real_time" the simulated seconds per second of CPU time: the standard
// experiment f with the walls model, and the office laser tracking of mcl:b (the PF alone,
// without the EKF beside it), each with the particle count of the second argument.

#include <benchmark/benchmark.h>

#include <ctime>

#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"

namespace {

using namespace legofeup;

void BM_MonteCarloStepF(benchmark::State& state) {
    const lessons::analysis::MonteCarloSpec spec{lessons::find_experiment("f")->config,
                                                 static_cast<std::size_t>(state.range(0)), 1};
    const int jobs = static_cast<int>(state.range(1));
    std::size_t runs = 0;
    const std::clock_t cpu_start = std::clock();  // CPU time of every thread of the process
    for (auto _ : state) {
        const lessons::analysis::MonteCarloSums sums =
            lessons::analysis::run_monte_carlo(spec, jobs);
        runs += sums.runs.size();
        benchmark::DoNotOptimize(sums.steps.size());
    }
    const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    state.counters["runs_per_s"] =
        benchmark::Counter(static_cast<double>(runs), benchmark::Counter::kIsRate);
    // CPU seconds per run over all threads: equal for 1 and 2 jobs when the threads cost
    // nothing extra, so the wall-clock speed-up on free cores is then the number of jobs.
    state.counters["cpu_ms_per_run"] = 1e3 * cpu / static_cast<double>(runs);
}
BENCHMARK(BM_MonteCarloStepF)
    ->ArgNames({"runs", "jobs"})
    ->Args({1000, 1})
    ->Args({1000, 2})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

// One run alone, bare and with the Monte Carlo's per-step recorder: what recording costs.
void BM_OneRunStepF(benchmark::State& state) {
    const lessons::ResolvedRun run = lessons::resolve(lessons::find_experiment("f")->config);
    for (auto _ : state) {
        lessons::analysis::StepRecorder recorder;
        const lessons::RunResult result =
            lessons::run_lockstep(run, state.range(0) != 0 ? &recorder : nullptr);
        benchmark::DoNotOptimize(result.metrics.truth);
    }
}
BENCHMARK(BM_OneRunStepF)->ArgName("recorded")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The run of `which` (0: experiment f, walls; 1: mcl:b, the office laser) with the PF alone.
lessons::ResolvedRun particle_filter_run(int which, int particles) {
    lessons::RunConfig config = lessons::find_experiment(which == 0 ? "f" : "mcl:b")->config;
    config.lesson.kind = FilterKind::Pf;
    config.lesson.compare_kinds = false;
    config.lesson.particles.particle_count = particles;
    return lessons::resolve(config);
}

void BM_ParticleFilterRun(benchmark::State& state) {
    const lessons::ResolvedRun run =
        particle_filter_run(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
    double simulated = 0.0;
    const std::clock_t cpu_start = std::clock();
    for (auto _ : state) {
        const lessons::RunResult result = lessons::run_lockstep(run, nullptr);
        simulated += result.metrics.duration;
        benchmark::DoNotOptimize(result.metrics.truth);
    }
    const double cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    state.counters["x_real_time"] = simulated / cpu;
}
BENCHMARK(BM_ParticleFilterRun)
    ->ArgNames({"office", "particles"})
    ->Args({0, 1000})
    ->Args({1, 1000})
    ->Args({1, 10000})
    ->Iterations(1)
    ->Repetitions(3)
    ->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
