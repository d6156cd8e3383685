#include "legofeup/lessons/world_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>

#include "built_in_resources.hpp"
#include "config_reader.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

/// Loads the map a world's [map] names (as written there); throws InputError.
using MapLoader = std::function<std::shared_ptr<const OccupancyGrid>(const std::string& file)>;

class WorldReader {
  public:
    WorldReader(std::string source, MapLoader load_map)
        : source_(std::move(source)), load_map_(std::move(load_map)) {}

    sim::WorldSpec read(const toml::table& root) {
        sim::WorldSpec world;
        world.walls.clear();
        for (const auto& [key, node] : root) {
            const std::string name(key.str());
            if (name == "name") {
                if (const auto* text = node.as_string()) {
                    world.name = text->get();
                } else {
                    problem(node, "name", "must be a quoted text");
                }
            } else if (name == "start") {
                read_start(node, world.start);
            } else if (name == "path") {
                read_path(node, world);
            } else if (name == "wall") {
                read_walls(node, world.walls);
            } else if (name == "beacon") {
                read_beacons(node, world.beacons);
            } else if (name == "magnetic") {
                read_magnetic(node, world.magnetic);
            } else if (name == "map") {
                read_map(node, world);
            } else {
                problem(node, name,
                        "unknown key (expected name, [start], [path], [[wall]], [[beacon]], "
                        "[magnetic] or [map])");
            }
        }
        check_beacons_inside_walls(world);
        check_start_is_free(root, world);
        return world;
    }

    const std::vector<InputProblem>& problems() const { return problems_; }

  private:
    void problem(const toml::node& node, std::string key, std::string reason) {
        const bool scalar = !node.is_table() && !node.is_array();
        problems_.push_back({source_, line_of(node), std::move(key),
                             scalar ? node_text(node) : std::string(), std::move(reason)});
    }

    std::optional<double> finite_number(const toml::node& node, const std::string& key) {
        const auto value = number_of(node);
        if (!value || !std::isfinite(*value)) {
            problem(node, key, "must be a finite number");
            return std::nullopt;
        }
        return value;
    }

    std::optional<Vector2> finite_point(const toml::node& node, const std::string& key) {
        const auto value = point_of(node);
        if (!value || !value->allFinite()) {
            problem(node, key, "must be a point [x, y] of finite numbers");
            return std::nullopt;
        }
        return value;
    }

    void read_start(const toml::node& node, Pose2& start) {
        const auto* table = node.as_table();
        if (table == nullptr) {
            problem(node, "start", "must be a table with x, y and heading_deg");
            return;
        }
        for (const auto& [key, value] : *table) {
            const std::string name = "start." + std::string(key.str());
            if (key == "x") {
                start.x = finite_number(value, name).value_or(start.x);
            } else if (key == "y") {
                start.y = finite_number(value, name).value_or(start.y);
            } else if (key == "heading_deg") {
                start.theta = degrees_to_radians(finite_number(value, name).value_or(0.0));
            } else {
                problem(value, name, "unknown key (expected x, y or heading_deg)");
            }
        }
    }

    void read_path(const toml::node& node, sim::WorldSpec& world) {
        const auto* table = node.as_table();
        if (table == nullptr) {
            problem(node, "path", "must be a table with side and centre");
            return;
        }
        for (const auto& [key, value] : *table) {
            const std::string name = "path." + std::string(key.str());
            if (key == "side") {
                const auto side = finite_number(value, name);
                if (side && !(*side > 0.0 && *side <= 1000.0)) {
                    problem(value, name, "must be greater than 0 and at most 1000 m");
                } else if (side) {
                    world.path_side = *side;
                }
            } else if (key == "centre") {
                world.path_centre = finite_point(value, name).value_or(world.path_centre);
            } else {
                problem(value, name, "unknown key (expected side or centre)");
            }
        }
    }

    void read_walls(const toml::node& node, std::vector<Wall>& walls) {
        const auto* array = node.as_array();
        if (array == nullptr || !array->is_array_of_tables()) {
            problem(node, "wall", "walls are written as [[wall]] tables");
            return;
        }
        for (const auto& entry : *array) {
            const std::string prefix = "wall[" + std::to_string(walls.size()) + "]";
            Wall wall;
            wall.name = prefix;
            bool has_from = false;
            bool has_to = false;
            for (const auto& [key, value] : *entry.as_table()) {
                const std::string name = prefix + "." + std::string(key.str());
                if (key == "name") {
                    if (const auto* text = value.as_string()) {
                        wall.name = text->get();
                    } else {
                        problem(value, name, "must be a quoted text");
                    }
                } else if (key == "from") {
                    has_from = true;
                    wall.start = finite_point(value, name).value_or(wall.start);
                } else if (key == "to") {
                    has_to = true;
                    wall.end = finite_point(value, name).value_or(wall.end);
                } else {
                    problem(value, name, "unknown key (expected name, from or to)");
                }
            }
            if (!has_from || !has_to) {
                problem(entry, prefix, "a wall needs both `from` and `to`");
            } else if ((wall.end - wall.start).norm() < 1e-6) {
                const std::string named =
                    wall.name == prefix ? prefix : prefix + " (" + wall.name + ")";
                problem(entry, named, "`from` and `to` are the same point: a wall needs a length");
            }
            walls.push_back(wall);
        }
    }

    // [[beacon]] id = 1  x = ..  y = ..: ids whole numbers 0–255, unique.
    void read_beacons(const toml::node& node, BeaconMap& beacons) {
        const auto* array = node.as_array();
        if (array == nullptr || !array->is_array_of_tables()) {
            problem(node, "beacon", "beacons are written as [[beacon]] tables");
            return;
        }
        std::map<std::int64_t, std::size_t> first_with_id;
        for (const auto& entry : *array) {
            const std::size_t index = beacon_entries_.size();
            const std::string prefix = "beacon[" + std::to_string(index) + "]";
            Beacon beacon;
            bool has_id = false;
            bool has_x = false;
            bool has_y = false;
            for (const auto& [key, value] : *entry.as_table()) {
                const std::string name = prefix + "." + std::string(key.str());
                if (key == "id") {
                    has_id = true;
                    const auto* id = value.as_integer();
                    if (id == nullptr || id->get() < 0 || id->get() > 255) {
                        problem(value, name, "must be a whole number from 0 to 255");
                        continue;
                    }
                    const auto [first, inserted] = first_with_id.emplace(id->get(), index);
                    if (!inserted) {
                        problem(value, name,
                                "beacon[" + std::to_string(first->second)
                                    + "] already has this id: ids must be unique");
                    }
                    beacon.id = static_cast<int>(id->get());
                } else if (key == "x") {
                    has_x = true;
                    beacon.position.x() = finite_number(value, name).value_or(0.0);
                } else if (key == "y") {
                    has_y = true;
                    beacon.position.y() = finite_number(value, name).value_or(0.0);
                } else {
                    problem(value, name, "unknown key (expected id, x or y)");
                }
            }
            if (!has_id || !has_x || !has_y) {
                problem(entry, prefix, "a beacon needs `id`, `x` and `y`");
            }
            beacons.push_back(beacon);
            beacon_entries_.push_back(&entry);
        }
    }

    // Beacons stand inside the world: within the bounding box of its walls (when it has any).
    void check_beacons_inside_walls(const sim::WorldSpec& world) {
        if (world.walls.empty()) {
            return;
        }
        Vector2 low = world.walls.front().start;
        Vector2 high = low;
        for (const Wall& wall : world.walls) {
            low = low.cwiseMin(wall.start).cwiseMin(wall.end);
            high = high.cwiseMax(wall.start).cwiseMax(wall.end);
        }
        for (std::size_t i = 0; i < world.beacons.size(); ++i) {
            const Vector2& at = world.beacons[i].position;
            if ((at.array() < low.array()).any() || (at.array() > high.array()).any()) {
                problem(
                    *beacon_entries_[i], "beacon[" + std::to_string(i) + "]",
                    "(" + format_config_number(at.x()) + ", " + format_config_number(at.y())
                        + ") is outside the walls' bounding box x " + format_config_number(low.x())
                        + " to " + format_config_number(high.x()) + ", y "
                        + format_config_number(low.y()) + " to " + format_config_number(high.y()));
            }
        }
    }

    // [magnetic] amplitude_deg = ..  wavelength = ..
    void read_magnetic(const toml::node& node, sim::MagneticDisturbance& magnetic) {
        const auto* table = node.as_table();
        if (table == nullptr) {
            problem(node, "magnetic", "must be a table with amplitude_deg and wavelength");
            return;
        }
        for (const auto& [key, value] : *table) {
            const std::string name = "magnetic." + std::string(key.str());
            if (key == "amplitude_deg") {
                const auto amplitude = finite_number(value, name);
                if (amplitude && !(*amplitude >= 0.0 && *amplitude <= 180.0)) {
                    problem(value, name, "must be between 0 and 180 degrees");
                } else if (amplitude) {
                    magnetic.amplitude_deg = *amplitude;
                }
            } else if (key == "wavelength") {
                const auto wavelength = finite_number(value, name);
                if (wavelength && !(*wavelength > 0.0 && *wavelength <= 1e6)) {
                    problem(value, name, "must be greater than 0 and at most 1e6 m");
                } else if (wavelength) {
                    magnetic.wavelength = *wavelength;
                }
            } else {
                problem(value, name, "unknown key (expected amplitude_deg or wavelength)");
            }
        }
    }

    // [map] file = "../maps/office_as_built.yaml": an occupancy grid whose occupied cells are
    // solid; surveyed = "../maps/office.yaml" (optional): the map the robot's filter is given.
    void read_map(const toml::node& node, sim::WorldSpec& world) {
        const auto* table = node.as_table();
        if (table == nullptr) {
            problem(node, "map", "must be a table with file (and optionally surveyed)");
            return;
        }
        bool has_file = false;
        for (const auto& [key, value] : *table) {
            const std::string name = "map." + std::string(key.str());
            std::shared_ptr<const OccupancyGrid>* target = nullptr;
            if (key == "file") {
                has_file = true;
                target = &world.map;
            } else if (key == "surveyed") {
                target = &world.surveyed_map;
            } else {
                problem(value, name, "unknown key (expected file or surveyed)");
                continue;
            }
            const auto* file = value.as_string();
            if (file == nullptr || file->get().empty()) {
                problem(value, name,
                        "must be a quoted path to a map's YAML file, relative to this world "
                        "file");
                continue;
            }
            try {
                *target = load_map_(file->get());
            } catch (const InputError& error) {
                // The map's own problems (at their lines), then where this world names it.
                problems_.insert(problems_.end(), error.problems().begin(), error.problems().end());
                problem(value, name, "the map file is unusable");
            }
        }
        if (!has_file) {
            problem(node, "map", "needs file = \"<map>.yaml\"");
        }
    }

    // The robot cannot start inside a wall or a piece of furniture of the map.
    void check_start_is_free(const toml::table& root, const sim::WorldSpec& world) {
        if (!world.map) {
            return;
        }
        const auto cell = world.map->cell_of({world.start.x, world.start.y});
        if (cell && world.map->occupied(*cell)) {
            const toml::node* start = root.get("start");
            problems_.push_back({source_, start != nullptr ? line_of(*start) : 0, "start", "",
                                 "(" + format_config_number(world.start.x) + ", "
                                     + format_config_number(world.start.y)
                                     + ") is in an occupied cell of the map"});
        }
    }

    std::string source_;
    MapLoader load_map_;
    std::vector<InputProblem> problems_;
    std::vector<const toml::node*> beacon_entries_;  // where each beacon was written
};

sim::WorldSpec read_world(std::string_view text, const std::string& source,
                          const MapLoader& load_map) {
    const toml::table root = parse_toml(text, source);
    WorldReader reader(source, load_map);
    sim::WorldSpec world = reader.read(root);
    if (!reader.problems().empty()) {
        throw InputError(reader.problems());
    }
    if (world.name.empty()) {
        world.name = source;
    }
    return world;
}

/// The built-in worlds, read once: resources/worlds/<name>.toml, their maps built in too.
const std::map<std::string, sim::WorldSpec>& built_in_worlds() {
    static const std::map<std::string, sim::WorldSpec> worlds = [] {
        std::map<std::string, sim::WorldSpec> all;
        for (const std::string& name : built_in_world_names()) {
            const std::string path = "worlds/" + name + ".toml";
            const auto text = built_in_resource(path);
            // A map named relative to the world, e.g. "../maps/office.yaml" → maps/office.yaml.
            const MapLoader built_in_map = [](const std::string& file) {
                const std::string resource =
                    (std::filesystem::path("worlds") / file).lexically_normal().generic_string();
                auto map = find_built_in_map(resource);
                if (!map) {
                    throw InputError({{"", 0, "map.file", "\"" + file + "\"",
                                       "not among the built-in maps (resources/maps)"}});
                }
                return map;
            };
            all.emplace(name, read_world(text.value_or(""), path + " (built in)", built_in_map));
        }
        return all;
    }();
    return worlds;
}

}  // namespace

sim::WorldSpec parse_world(std::string_view text, const std::string& source,
                           const std::filesystem::path& base_directory) {
    return read_world(text, source, [&base_directory](const std::string& file) {
        if (const auto& names = built_in_map_names();
            std::find(names.begin(), names.end(), file) != names.end()) {
            return find_built_in_map(file);
        }
        const std::filesystem::path path(file);
        return std::make_shared<const OccupancyGrid>(
            load_map_file(path.is_relative() ? base_directory / path : path));
    });
}

sim::WorldSpec load_world_file(const std::filesystem::path& path) {
    return parse_world(read_text_file(path, kWorldFile), path.string(), path.parent_path());
}

const std::vector<std::string>& built_in_world_names() {
    static const std::vector<std::string> names = {"standard_arena", "office", "beacon_field"};
    return names;
}

const sim::WorldSpec* find_built_in_world(std::string_view name) {
    const auto& worlds = built_in_worlds();
    const auto it = worlds.find(std::string(name));
    return it == worlds.end() ? nullptr : &it->second;
}

const sim::WorldSpec& built_in_world() {
    return *find_built_in_world("standard_arena");
}

sim::WorldSpec load_world(const std::string& name_or_path) {
    if (const sim::WorldSpec* world = find_built_in_world(name_or_path)) {
        return *world;
    }
    return load_world_file(name_or_path);
}

}  // namespace legofeup::lessons
