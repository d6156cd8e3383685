#pragma once
// Runs the loop against the in-process simulator, step for step: deterministic, headless and
// as fast as the machine allows. The CLI, the grader and the tests all run experiments here.

#include "legofeup/lessons/link_run.hpp"

namespace legofeup::lessons {

/// Runs until the routine is finished (e.g. all laps driven) or the time limit.
RunResult run_lockstep(const ResolvedRun& run, RunObserver* observer = nullptr,
                       const ProgressCallback& progress = {});

}  // namespace legofeup::lessons
