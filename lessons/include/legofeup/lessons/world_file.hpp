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

/// The standard arena, read from resources/worlds/standard_arena.toml as built into the
/// programs: the world every run uses unless its configuration names another.
const sim::WorldSpec& built_in_world();

}  // namespace legofeup::lessons
