#pragma once
// A realistic history for GUI tests and benchmarks: an experiment run in lockstep, every
// step collected whole (the samples, for the tests to compare with) and taken into a history
// as the session would have taken it (which keeps every step's record, and whole samples
// only sparsely).

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/ui/run_history.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui::testing {

/// Every step of a run, whole, and its scene.
struct LockstepRun {
    ArenaScene scene;
    std::vector<RunSample> samples;
};

/// Runs experiment `id` ("a" … "f") for `laps` laps of the square (200 s, 4,000 steps each
/// at most).
inline LockstepRun lockstep_run(const std::string& id, int laps) {
    const lessons::Experiment* experiment = lessons::find_experiment(id);
    if (experiment == nullptr) {
        throw std::invalid_argument("no experiment " + id);
    }
    lessons::RunConfig config = experiment->config;
    config.laps = laps;
    const lessons::ResolvedRun run = lessons::resolve(config);
    SampleCollector collector;
    lessons::run_lockstep(run, &collector);
    return {scene_of(run), collector.take()};
}

/// A history holding `run`: a copy of its samples, taken in as a session at 10× speed takes
/// them, three a frame (so that only the recent ones, and one a second, stay whole).
inline RunHistory history_of(const LockstepRun& run) {
    constexpr std::size_t kBatch = 3;
    RunHistory history;
    history.restart(run.scene);
    for (std::size_t first = 0; first < run.samples.size(); first += kBatch) {
        const std::size_t end = std::min(first + kBatch, run.samples.size());
        history.append(
            std::vector<RunSample>(run.samples.begin() + static_cast<std::ptrdiff_t>(first),
                                   run.samples.begin() + static_cast<std::ptrdiff_t>(end)));
    }
    return history;
}

/// Copies of every sample of a history short enough to keep them all whole
/// (RunHistory::kRecentSamples); throws for a longer one.
inline std::vector<RunSample> whole_samples(const RunHistory& history) {
    std::vector<RunSample> samples;
    samples.reserve(history.size());
    for (std::size_t i = 0; i < history.size(); ++i) {
        const RunSample* sample = history.sample(i);
        if (sample == nullptr) {
            throw std::logic_error("the history no longer keeps step " + std::to_string(i));
        }
        samples.push_back(*sample);
    }
    return samples;
}

/// The history of experiment `id` run for `laps` laps.
inline RunHistory lockstep_history(const std::string& id, int laps) {
    return history_of(lockstep_run(id, laps));
}

/// One lap of experiment f, run once per test program and shared by its tests: its samples
/// and its history.
inline const LockstepRun& one_lap_run() {
    static const LockstepRun run = lockstep_run("f", 1);
    return run;
}
inline const std::vector<RunSample>& one_lap_samples() {
    return one_lap_run().samples;
}
inline const RunHistory& one_lap() {
    static const RunHistory history = history_of(one_lap_run());
    return history;
}

}  // namespace legofeup::ui::testing
