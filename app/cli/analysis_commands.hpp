#pragma once
// legofeup-cli montecarlo, sweep and merge: many seeded runs of one configuration averaged
// (NEES and NIS against their χ² bounds, error statistics), a grid of Q × R scales, and the
// joining of shards run as a cluster job array (docs/analysis.md). Exit codes as in
// commands.hpp.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "config_choice.hpp"

namespace CLI {
class App;
}

namespace legofeup::cli {

/// The configuration comes from --experiment, --config and --laps (the seeds from the batch).
struct AnalysisOptions : ConfigChoice {
    int runs = 0;  ///< per Monte Carlo (per cell for a sweep)
    std::uint64_t first_seed = 1;
    int jobs = 0;                          ///< 0: all cores
    std::string shard;                     ///< "i/n", or empty: the whole batch
    std::string q;                         ///< sweep: Q scales, "0.1,1,10" or "1e-2:1e2:5"
    std::string r;                         ///< sweep: R scales
    std::vector<std::string> shard_files;  ///< merge
    std::string out;
    bool plots = true;
    bool quiet = false;

    CLI::App* montecarlo_command = nullptr;
    CLI::App* sweep_command = nullptr;
    CLI::App* merge_command = nullptr;

    /// True when the command line chose montecarlo, sweep or merge.
    bool requested() const;
};

/// Adds montecarlo, sweep and merge to `app`, filling `options`.
void add_analysis_subcommands(CLI::App& app, AnalysisOptions& options);

/// Runs the analysis subcommand the command line chose.
int analysis_command(const AnalysisOptions& options);

}  // namespace legofeup::cli
