#include "legofeup/sim/world.hpp"

#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "legofeup/core/angles.hpp"

namespace legofeup::sim {
namespace {

constexpr double kStandardBeaconInset = 0.1;  // m from each corner of the walls' bounding box
constexpr int kMaxMapCells = 10000;           // a side
constexpr double kMaxMapExtent = 1000.0;      // m a side: Box2D's floats keep µm there

void check_map(const OccupancyGrid& map, const Pose2& start, ConfigChecker& check) {
    check.require(!map.empty(), "world.map", 0.0, "the map has no cells");
    check.in_range("world.map.width", map.width(), 0.0, kMaxMapCells);
    check.in_range("world.map.height", map.height(), 0.0, kMaxMapCells);
    check.in_range("world.map.resolution", map.resolution(), 0.01, 10.0);
    check.in_range("world.map.origin.x", map.origin().x, -1000.0, 1000.0);
    check.in_range("world.map.origin.y", map.origin().y, -1000.0, 1000.0);
    check.in_range("world.map.origin.theta", map.origin().theta, -2.0 * kPi, 2.0 * kPi);
    check.require(!(map.width() * map.resolution() > kMaxMapExtent), "world.map.width", map.width(),
                  "width · resolution must be at most 1000 m");
    check.require(!(map.height() * map.resolution() > kMaxMapExtent), "world.map.height",
                  map.height(), "height · resolution must be at most 1000 m");
    if (map.empty()) {
        return;
    }
    const std::optional<GridCell> cell = map.cell_of(position_of(start));
    check.require(!cell || !map.occupied(*cell), "world.start.x", start.x,
                  "the start pose (" + format_config_number(start.x) + ", "
                      + format_config_number(start.y) + ") m lies in an occupied cell of the map");
}

}  // namespace

WorldSpec standard_arena() {
    const ArenaSpec arena;  // L_p = 2 m, L_w = 1.21 m, 1 m walls
    WorldSpec world;
    world.name = "LegoFeup standard arena";
    world.walls = standard_arena_walls(arena).walls();
    world.start = {-0.5 * arena.path_side, -0.5 * arena.path_side, 0.0};
    world.path_side = arena.path_side;
    // Beacons 0.1 m inside the corners of the walls' bounding box (±L_w), CCW from the
    // lower left: inside the walls, so the walls never hide one from the path.
    const double corner = arena.wall_distance - kStandardBeaconInset;
    world.beacons = {{1, {-corner, -corner}},
                     {2, {corner, -corner}},
                     {3, {corner, corner}},
                     {4, {-corner, corner}}};
    world.magnetic = {12.0, 3.0};
    return world;
}

std::vector<ConfigIssue> validate(const WorldSpec& world) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    std::set<int> ids;
    for (std::size_t i = 0; i < world.beacons.size(); ++i) {
        const Beacon& beacon = world.beacons[i];
        const std::string name = "world.beacon[" + std::to_string(i) + "]";
        check.in_range(name + ".id", beacon.id, 0.0, 255.0);
        check.require(ids.insert(beacon.id).second, name + ".id", beacon.id,
                      "another beacon has this id");
        check.finite(name + ".x", beacon.position.x());
        check.finite(name + ".y", beacon.position.y());
    }
    check.in_range("world.magnetic.amplitude_deg", world.magnetic.amplitude_deg, 0.0, 180.0);
    check.positive("world.magnetic.wavelength", world.magnetic.wavelength, 1e6);
    if (world.map) {
        check_map(*world.map, world.start, check);
    }
    return issues;
}

std::vector<PathSegment> world_square_path(const WorldSpec& world) {
    ArenaSpec arena;
    arena.path_side = world.path_side;
    std::vector<PathSegment> segments = square_path(arena);
    for (PathSegment& segment : segments) {
        auto& line = std::get<LineSegment>(segment);
        line.from += world.path_centre;
        line.to += world.path_centre;
    }
    return segments;
}

}  // namespace legofeup::sim
