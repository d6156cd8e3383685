#include "legofeup/core/walls.hpp"

#include <cmath>
#include <utility>

#include "legofeup/core/angles.hpp"

namespace legofeup {

WallLine make_wall_line(const Wall& wall) {
    WallLine line;
    const Vector2 span = wall.end - wall.start;
    line.start = wall.start;
    line.length = span.norm();
    line.direction = line.length > 0.0 ? Vector2(span / line.length) : Vector2::UnitX();
    // Left normal of the direction, flipped so its dominant component is positive
    // (ties: x positive). Axis-aligned walls therefore get n = +x or n = +y.
    Vector2 normal(-line.direction.y(), line.direction.x());
    const bool x_dominant = std::abs(normal.x()) >= std::abs(normal.y());
    if ((x_dominant && normal.x() < 0.0) || (!x_dominant && normal.y() < 0.0)) {
        normal = -normal;
    }
    line.normal = normal;
    line.offset = normal.dot(wall.start);
    // The sensors look along the robot's −y axis, i.e. at heading − π/2. Looking at the wall
    // from side σ means looking along −σ·n, so heading = ang(−σ·n) + π/2 = ang(σ·n) − π/2.
    line.facing_from_positive_side = wrap_angle(std::atan2(normal.y(), normal.x()) - 0.5 * kPi);
    line.facing_from_negative_side = wrap_angle(line.facing_from_positive_side + kPi);
    return line;
}

WallMap::WallMap(std::vector<Wall> walls) : walls_(std::move(walls)) {
    lines_.reserve(walls_.size());
    for (const Wall& wall : walls_) {
        lines_.push_back(make_wall_line(wall));
    }
}

WallMap standard_arena_walls(const ArenaSpec& arena) {
    const double h = 0.5 * arena.path_side;  // path corners at (±h, ±h)
    const double w = arena.wall_distance;    // L_w
    const double l = arena.wall_length;
    // Each wall starts level with a corner and runs along the side in the driving direction.
    return WallMap({
        {"wall_y-", {-h, -w}, {-h + l, -w}},  // first side, heading +x
        {"wall_x+", {w, -h}, {w, -h + l}},    // second side, heading +y
        {"wall_y+", {h, w}, {h - l, w}},      // third side, heading −x
        {"wall_x-", {-w, h}, {-w, h - l}},    // fourth side, heading −y
    });
}

}  // namespace legofeup
