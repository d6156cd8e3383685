#pragma once
// legofeup-cli refilter: a recorded run (run --record) replayed with a new configuration —
// the same raw readings through a loop with other Q, R, gate or P0 — and the recorded and new
// estimates compared (docs/recording.md). Exit codes as in commands.hpp.

#include <string>

namespace CLI {
class App;
}

namespace legofeup::cli {

struct RefilterOptions {
    std::string log_file;       ///< the run log
    std::string config_file;    ///< TOML applied over the recorded configuration
    std::string out_directory;  ///< "": print the comparison only
    bool plots = true;
    bool quiet = false;

    CLI::App* command = nullptr;

    /// True when the command line chose refilter.
    bool requested() const;
};

/// Adds the refilter subcommand to `app`, filling `options`.
void add_refilter_subcommand(CLI::App& app, RefilterOptions& options);

int refilter_command(const RefilterOptions& options);

}  // namespace legofeup::cli
