#pragma once
// Walls known to the filter: straight segments in the world frame.
//
// Every wall has a canonical unit normal n (its left normal, flipped so that its largest
// component is positive). For the paper's walls n is +x or +y, so the observation
// z₁ = n·p is exactly the x or y coordinate of eq. 4–5.

#include <string>
#include <vector>

#include "legofeup/core/state.hpp"

namespace legofeup {

struct Wall {
    std::string name;
    Vector2 start = Vector2::Zero();
    Vector2 end = Vector2::Zero();
};

/// A wall with the line geometry the association and the observation model need.
struct WallLine {
    Vector2 start = Vector2::Zero();
    Vector2 direction = Vector2::UnitX();  ///< unit vector from start to end
    double length = 0.0;
    Vector2 normal = Vector2::UnitY();  ///< canonical unit normal n
    double offset = 0.0;                ///< c: the wall's line is n·p = c
    /// The robot heading at which the right-side IR sensors look straight at the wall, from
    /// the +n side and from the −n side (ObsAng = 0): ang(±n) − π/2, wrapped.
    double facing_from_positive_side = 0.0;
    double facing_from_negative_side = 0.0;

    /// Signed distance of a point from the wall's line along n.
    double signed_distance(const Vector2& point) const { return normal.dot(point) - offset; }
};

WallLine make_wall_line(const Wall& wall);

class WallMap {
  public:
    WallMap() = default;
    explicit WallMap(std::vector<Wall> walls);

    int size() const { return static_cast<int>(walls_.size()); }
    const Wall& wall(int index) const { return walls_.at(static_cast<std::size_t>(index)); }
    const WallLine& line(int index) const { return lines_.at(static_cast<std::size_t>(index)); }
    const std::vector<Wall>& walls() const { return walls_; }

  private:
    std::vector<Wall> walls_;
    std::vector<WallLine> lines_;
};

/// The standard LegoFeup arena (scenario.md): a square path centred on the origin, driven
/// counter-clockwise from (−s/2, −s/2) heading +x, and one wall along the first
/// `wall_length` metres of each side, parallel to it at `wall_distance` from the centre.
struct ArenaSpec {
    double path_side = 2.0;       ///< L_p, metres
    double wall_distance = 1.21;  ///< L_w, metres
    double wall_length = 1.0;     ///< metres
};

/// The four walls of the standard arena, named as in the paper: wall_y- (first side),
/// wall_x+, wall_y+, wall_x- in driving order.
WallMap standard_arena_walls(const ArenaSpec& arena);

}  // namespace legofeup
