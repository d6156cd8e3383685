#pragma once
// The resource files built into the programs (resources/worlds, resources/maps), by their
// path under resources/, so that a built-in world can name its map by a relative path just
// as a world file on disk does. Private to lessons/.

#include <optional>
#include <string_view>

namespace legofeup::lessons {

/// The contents of resources/<path> as built in ("worlds/office.toml", "maps/office.pgm"),
/// or nullopt when it is not built in. `path` must be in normal form (no "." or "..").
std::optional<std::string_view> built_in_resource(std::string_view path);

}  // namespace legofeup::lessons
