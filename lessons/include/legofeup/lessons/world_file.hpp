#pragma once
// World files (TOML): walls, the start pose, the square path, bearing-only beacons, the
// compass's magnetic disturbance and an occupancy-grid map ([map] file = "…yaml").
// resources/worlds/ has the standard arena and the office; docs/configuration.md,
// docs/sensors.md and docs/maps.md describe the format.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/sim/world.hpp"

namespace legofeup::lessons {

/// Parses a world; throws InputError listing every problem with its line (a map's problems
/// at their own file and line, then the world's [map] line). A [map] file is relative to
/// `base_directory` (the world file's directory), or a built-in map's name.
sim::WorldSpec parse_world(std::string_view text, const std::string& source,
                           const std::filesystem::path& base_directory = {});

sim::WorldSpec load_world_file(const std::filesystem::path& path);

/// The worlds built into the programs (resources/worlds/<name>.toml): "standard_arena" and
/// "office".
const std::vector<std::string>& built_in_world_names();

/// A built-in world by name, or nullptr.
const sim::WorldSpec* find_built_in_world(std::string_view name);

/// The standard arena, read from resources/worlds/standard_arena.toml as built into the
/// programs: the world every run uses unless its configuration names another.
const sim::WorldSpec& built_in_world();

/// A built-in world's name (see built_in_world_names), or else a world file.
sim::WorldSpec load_world(const std::string& name_or_path);

}  // namespace legofeup::lessons
