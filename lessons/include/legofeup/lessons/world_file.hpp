#pragma once
// World files (TOML): walls, the start pose and the square path. resources/worlds/ has the
// standard arena; docs/configuration.md describes the format.

#include <filesystem>
#include <string>
#include <string_view>

#include "legofeup/sim/world.hpp"

namespace legofeup::lessons {

/// Parses a world; throws InputError listing every problem with its line.
sim::WorldSpec parse_world(std::string_view text, const std::string& source);

sim::WorldSpec load_world_file(const std::filesystem::path& path);

}  // namespace legofeup::lessons
