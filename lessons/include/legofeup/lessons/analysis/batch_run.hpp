#pragma once
// Many lockstep runs on worker threads: Monte Carlo, sweeps and grading. Each run is
// independent (its own simulator and loop, seeded by its configuration), so results do not
// depend on the number of jobs or on which thread ran what.

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "legofeup/lessons/lockstep_run.hpp"

namespace legofeup::lessons::analysis {

/// Called on the calling thread as runs finish: how many are done out of how many.
using BatchProgress = std::function<void(std::size_t finished, std::size_t total)>;

/// Makes the observer of run `index` (may return nullptr). Called on a worker thread.
using ObserverFactory = std::function<std::unique_ptr<RunObserver>(std::size_t index)>;

/// Called on the calling thread, in index order (0, 1, 2, …) whatever order the runs finish
/// in, with the run's result and the observer made for it. Reductions done here are
/// therefore bit-identical for any number of jobs.
using OrderedConsumer = std::function<void(std::size_t index, const RunResult& result,
                                           std::unique_ptr<RunObserver> observer)>;

/// Hardware threads, at least 1: what `jobs = 0` means.
int available_jobs();

/// Runs `runs` in lockstep on `jobs` threads (0: available_jobs()). Results in the order of
/// `runs`. An exception in any run is rethrown here after the workers have stopped.
std::vector<RunResult> run_batch(const std::vector<ResolvedRun>& runs, int jobs,
                                 const BatchProgress& progress = {});

/// The general form: observers made per run and consumed in order.
void run_batch(const std::vector<ResolvedRun>& runs, int jobs, const ObserverFactory& observers,
               const OrderedConsumer& consume, const BatchProgress& progress = {});

/// `--shard i/n` (1 ≤ i ≤ n): this shard takes items k with k % n == i - 1.
struct Shard {
    int index = 1;
    int count = 1;
    bool takes(std::size_t item) const {
        return static_cast<int>(item % static_cast<std::size_t>(count)) == index - 1;
    }
};

/// Parses "i/n". Throws InputError naming --shard and the value.
Shard parse_shard(const std::string& text);

}  // namespace legofeup::lessons::analysis
