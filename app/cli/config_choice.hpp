#pragma once
// How the commands that run the loop choose its configuration: the defaults, the guided
// experiment's preset, a TOML file, then the seed and laps given on the command line.

#include <cstdint>
#include <optional>
#include <string>

#include "legofeup/lessons/run_config.hpp"

namespace CLI {
class App;
}

namespace legofeup::cli {

struct ConfigChoice {
    std::string experiment;  ///< "a" … "f", or empty for the defaults
    std::string config_file;
    std::optional<std::uint64_t> seed;
    std::optional<int> laps;
};

/// Adds --experiment, --config, --laps and (when `seed_option`) --seed to `command`.
void add_config_options(CLI::App& command, ConfigChoice& choice, bool seed_option = true);

/// The configuration `choice` describes, and a title naming its sources ("experiment f: Tuned
/// filter + mine.toml"). Throws lessons::InputError.
lessons::RunConfig compose_cli_config(const ConfigChoice& choice, std::string& title);

}  // namespace legofeup::cli
