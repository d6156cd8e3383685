#include "legofeup/sim/world.hpp"

namespace legofeup::sim {

WorldSpec standard_arena() {
    const ArenaSpec arena;  // L_p = 2 m, L_w = 1.21 m, 1 m walls
    WorldSpec world;
    world.name = "LegoFeup standard arena";
    world.walls = standard_arena_walls(arena).walls();
    world.start = {-0.5 * arena.path_side, -0.5 * arena.path_side, 0.0};
    world.path_side = arena.path_side;
    return world;
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
