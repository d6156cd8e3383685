#pragma once
// Runs the loop against the in-process simulator, step for step: deterministic, headless and
// as fast as the machine allows. The CLI, the grader and the tests all run experiments here.

#include <functional>

#include "legofeup/core/run_metrics.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/sim/ground_truth.hpp"

namespace legofeup::lessons {

/// Sees every step of a run: what the loop computed and what really happened.
class RunObserver {
  public:
    virtual ~RunObserver() = default;
    virtual void on_step(const LoopSnapshot& snapshot, const sim::GroundTruth& truth) = 0;
};

struct RunResult {
    RunMetrics metrics;
    bool routine_finished = false;  ///< false: stopped at the time limit
    double wall_seconds = 0.0;      ///< how long the run took on this machine
};

/// Called now and then with how far the run has got (0 … 1: laps and sides driven for a
/// path, otherwise simulated time over the time limit) and the simulated time in seconds.
using ProgressCallback = std::function<void(double fraction, double simulated)>;

/// Runs until the routine is finished (e.g. all laps driven) or the time limit.
RunResult run_lockstep(const ResolvedRun& run, RunObserver* observer = nullptr,
                       const ProgressCallback& progress = {});

}  // namespace legofeup::lessons
