#pragma once
// Occupancy-grid maps for the simulator's tests, and the distances a ray travels in them
// worked out analytically (not by walking cells, not by Box2D).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <vector>

#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup::sim::test {

/// A room: a `width` × `height` grid whose border, `wall` cells thick, is occupied and whose
/// inside is free, with its origin at `origin`.
inline std::shared_ptr<const OccupancyGrid> room_map(int width, int height, double resolution,
                                                     const Pose2& origin, int wall = 1) {
    std::vector<CellState> cells(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                                 CellState::Free);
    for (int row = 0; row < height; ++row) {
        for (int col = 0; col < width; ++col) {
            const bool border =
                col < wall || col >= width - wall || row < wall || row >= height - wall;
            if (border) {
                cells[static_cast<std::size_t>(row) * static_cast<std::size_t>(width)
                      + static_cast<std::size_t>(col)] = CellState::Occupied;
            }
        }
    }
    return std::make_shared<const OccupancyGrid>(width, height, resolution, origin,
                                                 std::move(cells));
}

/// The free inside of room_map(width, height, resolution, origin, wall), in the grid frame.
struct RoomInside {
    double x0, y0, x1, y1;
};
inline RoomInside room_inside(int width, int height, double resolution, int wall = 1) {
    return {wall * resolution, wall * resolution, (width - wall) * resolution,
            (height - wall) * resolution};
}

/// A world pose in the grid frame of a map whose origin is `origin`: ⊖origin ⊕ pose.
inline Pose2 in_grid_frame(const Pose2& origin, const Pose2& pose) {
    const double c = std::cos(origin.theta);
    const double s = std::sin(origin.theta);
    const double dx = pose.x - origin.x;
    const double dy = pose.y - origin.y;
    return {c * dx + s * dy, -s * dx + c * dy, pose.theta - origin.theta};
}

/// Distance from `from` (inside the box) along the direction `angle` to the box's boundary:
/// the smallest positive t with from + t·(cos, sin) on one of its four sides.
inline double distance_to_box_side(const RoomInside& box, double x, double y, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    double t = std::numeric_limits<double>::infinity();
    if (c > 1e-12) {
        t = std::min(t, (box.x1 - x) / c);
    } else if (c < -1e-12) {
        t = std::min(t, (box.x0 - x) / c);
    }
    if (s > 1e-12) {
        t = std::min(t, (box.y1 - y) / s);
    } else if (s < -1e-12) {
        t = std::min(t, (box.y0 - y) / s);
    }
    return t;
}

}  // namespace legofeup::sim::test
