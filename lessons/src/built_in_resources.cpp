#include "built_in_resources.hpp"

#include <array>
#include <utility>

#include "beacon_field_world_resource.hpp"
#include "office_as_built_map_image_resource.hpp"
#include "office_as_built_map_resource.hpp"
#include "office_map_image_resource.hpp"
#include "office_map_resource.hpp"
#include "office_world_resource.hpp"
#include "standard_arena_map_image_resource.hpp"
#include "standard_arena_map_resource.hpp"
#include "standard_arena_resource.hpp"

namespace legofeup::lessons {

std::optional<std::string_view> built_in_resource(std::string_view path) {
    // The explicit list (lessons/CMakeLists.txt embeds each file).
    const std::array<std::pair<std::string_view, std::string_view>, 9> files{{
        {"worlds/standard_arena.toml", resources::kStandardArenaWorld},
        {"worlds/office.toml", resources::kOfficeWorld},
        {"worlds/beacon_field.toml", resources::kBeaconFieldWorld},
        {"maps/standard_arena.yaml", resources::kStandardArenaMap},
        {"maps/standard_arena.pgm", resources::kStandardArenaMapImage},
        {"maps/office.yaml", resources::kOfficeMap},
        {"maps/office.pgm", resources::kOfficeMapImage},
        {"maps/office_as_built.yaml", resources::kOfficeAsBuiltMap},
        {"maps/office_as_built.pgm", resources::kOfficeAsBuiltMapImage},
    }};
    for (const auto& [name, contents] : files) {
        if (name == path) {
            return contents;
        }
    }
    return std::nullopt;
}

}  // namespace legofeup::lessons
