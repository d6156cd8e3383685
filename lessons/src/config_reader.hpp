#pragma once
// Shared by the readers of lessons/: TOML parsing with located errors, and applying a
// configuration table that is part of a larger document (the experiment presets).

#include <toml++/toml.h>
#include <filesystem>
#include <string>
#include <string_view>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// Parses TOML; a syntax error becomes an InputError at its line.
toml::table parse_toml(std::string_view text, const std::string& source);

/// apply_config_toml for an already parsed table (line numbers refer to its document).
void apply_config_table(const toml::table& root, const std::string& source, RunConfig& config,
                        const std::filesystem::path& base_directory);

}  // namespace legofeup::lessons
