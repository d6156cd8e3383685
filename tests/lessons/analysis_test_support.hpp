#pragma once
// Short, realistic runs for the analysis tests: experiment f (noise, slip, tuned filter)
// driving a straight line for a few seconds, so a batch of runs takes a fraction of a second
// even in a Debug build under a sanitizer.

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons::testing {

inline RunConfig short_run_config(double seconds = 8.0) {
    RunConfig config = find_experiment("f")->config;
    config.routine.kind = RoutineSpec::Kind::Line;
    config.duration = seconds;
    return config;
}

inline std::vector<ResolvedRun> seeded_runs(const RunConfig& config, std::uint64_t first_seed,
                                            std::size_t count) {
    std::vector<ResolvedRun> runs;
    const ResolvedRun base = resolve(config);
    for (std::size_t k = 0; k < count; ++k) {
        runs.push_back(base);
        runs.back().config.seed = first_seed + k;
    }
    return runs;
}

}  // namespace legofeup::lessons::testing
