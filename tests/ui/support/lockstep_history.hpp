#pragma once
// A realistic history for GUI tests and benchmarks: an experiment run in lockstep, every
// step kept as the session would have kept it.

#include <stdexcept>
#include <string>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/ui/run_history.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui::testing {

/// Runs experiment `id` ("a" … "f") for `laps` laps of the square (200 s, 4,000 steps each
/// at most) and returns its history.
inline RunHistory lockstep_history(const std::string& id, int laps) {
    const lessons::Experiment* experiment = lessons::find_experiment(id);
    if (experiment == nullptr) {
        throw std::invalid_argument("no experiment " + id);
    }
    lessons::RunConfig config = experiment->config;
    config.laps = laps;
    const lessons::ResolvedRun run = lessons::resolve(config);
    SampleCollector collector;
    lessons::run_lockstep(run, &collector);
    RunHistory history;
    history.restart(scene_of(run));
    history.append(collector.take());
    return history;
}

/// One lap of experiment f, run once per test program and shared by its tests.
inline const RunHistory& one_lap() {
    static const RunHistory history = lockstep_history("f", 1);
    return history;
}

}  // namespace legofeup::ui::testing
