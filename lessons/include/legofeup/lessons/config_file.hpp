#pragma once
// Run configuration files (TOML). The same format is read by the CLI, saved and loaded by
// the GUI, and used for the experiment presets. See docs/configuration.md.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// Applies the settings in a TOML document over `config`: keys it does not mention keep
/// their values. `source` names the document in messages; relative paths in it (the world
/// file) are taken relative to `base_directory`. Throws InputError listing every problem
/// (file:line, key, value, reason); `config` is then unchanged.
void apply_config_toml(std::string_view text, const std::string& source, RunConfig& config,
                       const std::filesystem::path& base_directory = {});

/// Reads a configuration file over `base`.
RunConfig load_config_file(const std::filesystem::path& path, const RunConfig& base);

/// Where the programs take a run's configuration from, in order: the defaults, the guided
/// experiment's preset, the configuration file, then the seed given on the command line.
struct ConfigSources {
    std::string experiment;  ///< "a" … "f", or empty for the defaults
    std::filesystem::path config_file;
    std::optional<std::uint64_t> seed;
};

/// The configuration `sources` describe. Throws InputError naming --experiment for an unknown
/// experiment, or listing the file's problems.
RunConfig compose_config(const ConfigSources& sources);

/// Every setting of `config` as a TOML document that load_config_file reads back to the
/// same values, each with its meaning and unit as a comment.
std::string config_to_toml(const RunConfig& config, std::string_view title);

}  // namespace legofeup::lessons
