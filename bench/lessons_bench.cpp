// Monte Carlo throughput (Google Benchmark): 1,000 runs of experiment f (two laps each) on
// 1 and 2 jobs, the target being under 30 s with 2 jobs. Run from a release build:
//   build/release/bench/legofeup_lessons_bench
// "runs_per_s" is the rate; the speed-up is the 2-job rate over the 1-job rate. On a machine
// busy with other work, "cpu_ms_per_run" (all threads) shows what a run costs regardless.

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

}  // namespace

BENCHMARK_MAIN();
