#pragma once
// World files (TOML): walls, the start pose, the square path, bearing-only beacons and the
// compass's magnetic disturbance. resources/worlds/ has the standard arena;
// docs/configuration.md and docs/sensors.md describe the format.

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
