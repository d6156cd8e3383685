#include "legofeup/lessons/world_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#include "config_reader.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "standard_arena_resource.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

class WorldReader {
  public:
    explicit WorldReader(std::string source) : source_(std::move(source)) {}

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
            } else {
                problem(node, name,
                        "unknown key (expected name, [start], [path], [[wall]], [[beacon]] or "
                        "[magnetic])");
            }
        }
        check_beacons_inside_walls(world);
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

    std::string source_;
    std::vector<InputProblem> problems_;
    std::vector<const toml::node*> beacon_entries_;  // where each beacon was written
};

}  // namespace

sim::WorldSpec parse_world(std::string_view text, const std::string& source) {
    const toml::table root = parse_toml(text, source);
    WorldReader reader(source);
    sim::WorldSpec world = reader.read(root);
    if (!reader.problems().empty()) {
        throw InputError(reader.problems());
    }
    if (world.name.empty()) {
        world.name = source;
    }
    return world;
}

sim::WorldSpec load_world_file(const std::filesystem::path& path) {
    return parse_world(read_text_file(path, "world"), path.string());
}

const sim::WorldSpec& built_in_world() {
    static const sim::WorldSpec world =
        parse_world(resources::kStandardArenaWorld, "worlds/standard_arena.toml (built in)");
    return world;
}

}  // namespace legofeup::lessons
