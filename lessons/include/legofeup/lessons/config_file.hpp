#pragma once
// Run configuration files (TOML). The same format is read by the CLI, saved and loaded by
// the GUI, and used for the experiment presets. See docs/configuration.md.

#include <filesystem>
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

/// Every setting of `config` as a TOML document that load_config_file reads back to the
/// same values, each with its meaning and unit as a comment.
std::string config_to_toml(const RunConfig& config, std::string_view title);

}  // namespace legofeup::lessons
