#include "placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "legofeup/core/config_issue.hpp"

namespace legofeup::simserver {
namespace {

/// Distance from p to the segment [a, b]: to its nearest point a + t·(b − a), with
/// t = (p − a)·(b − a) / |b − a|² clamped to [0, 1] (a point segment: |p − a|).
double distance_to_segment(const Vector2& p, const Vector2& a, const Vector2& b) {
    const Vector2 along = b - a;
    const double length_squared = along.squaredNorm();
    const double t =
        length_squared > 0.0 ? std::clamp((p - a).dot(along) / length_squared, 0.0, 1.0) : 0.0;
    return (p - (a + t * along)).norm();
}

/// Whether an occupied cell of `grid` comes nearer than `reach` to `point`. In the grid's own
/// frame g (distances are the same there), cell (col, row) is the square
/// [col·s, (col + 1)·s] × [row·s, (row + 1)·s]; its distance to g is the hypotenuse of the
/// gaps along each axis (0 inside). Only the cells of the square of side 2·reach around g
/// can be nearer.
bool occupied_cell_within(const OccupancyGrid& grid, const Vector2& point, double reach) {
    const Vector2 g = grid.to_grid_frame(point);
    const double s = grid.resolution();
    // The cell index of a coordinate, clamped to the grid (in double, so that a point far
    // off the grid cannot overflow the int).
    const auto index = [&](double coordinate, int size) {
        return static_cast<int>(std::clamp(std::floor(coordinate / s), 0.0, size - 1.0));
    };
    const int last_row = index(g.y() + reach, grid.height());
    const int last_col = index(g.x() + reach, grid.width());
    for (int row = index(g.y() - reach, grid.height()); row <= last_row; ++row) {
        for (int col = index(g.x() - reach, grid.width()); col <= last_col; ++col) {
            if (!grid.occupied({col, row})) {
                continue;
            }
            const double gap_x = std::max({col * s - g.x(), 0.0, g.x() - (col + 1) * s});
            const double gap_y = std::max({row * s - g.y(), 0.0, g.y() - (row + 1) * s});
            if (std::hypot(gap_x, gap_y) < reach) {
                return true;
            }
        }
    }
    return false;
}

/// `value` to 9 significant digits (%.9g, at most 16 characters), rounded up (`direction`
/// +1) or down (−1) rather than to the nearest. The box's limits are rounded inwards, so a
/// printed limit is itself accepted (to the nearest, 0.1063014581 would print as 0.106301458,
/// just outside; with %.6g's 6 digits 1.10369854 would be 1.1037), and a refused coordinate
/// outwards, so it never prints inside the printed limits.
std::string format_rounded(double value, double direction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    const double printed = std::strtod(text, nullptr);
    if ((printed - value) * direction < 0.0 && printed != 0.0) {
        // One unit of the 9th significant digit: 10^(⌊log10 |printed|⌋ − 8) (not past the
        // largest double, where the nearest is as good as it gets).
        const double unit = std::pow(10.0, std::floor(std::log10(std::abs(printed))) - 8.0);
        if (const double rounded = printed + direction * unit; std::isfinite(rounded)) {
            std::snprintf(text, sizeof text, "%.9g", rounded);
        }
    }
    return text;
}

/// "<request>: x = 1.2 m: the chassis fits in -1.10369854 … 1.10369854 m": at most 93 bytes.
std::string outside_box(std::string_view request, char axis, double value, double low,
                        double high) {
    return std::string(request) + ": " + axis + " = "
           + format_rounded(value, value < low ? -1.0 : 1.0) + " m: the chassis fits in "
           + format_rounded(low, 1.0) + " … " + format_rounded(high, -1.0) + " m";
}

/// "<request>: pose (x, y) m is nearer than r m to <what>": at most 93 bytes (r, from chassis
/// dimensions validated to 0.02 … 2 m, prints in at most 9).
std::string too_near(std::string_view request, const Pose2& pose, double reach,
                     std::string_view what) {
    return std::string(request) + ": pose (" + format_config_number(pose.x) + ", "
           + format_config_number(pose.y) + ") m is nearer than " + format_config_number(reach)
           + " m to " + std::string(what);
}

}  // namespace

double chassis_reach(const sim::RobotSpec& robot) {
    return std::hypot(std::max(robot.chassis_front, robot.chassis_rear), robot.chassis_half_width);
}

PlacementBox placement_box(const sim::WorldSpec& world, double reach) {
    Vector2 low = Vector2::Constant(std::numeric_limits<double>::infinity());
    Vector2 high = -low;
    for (const Wall& wall : world.walls) {
        low = low.cwiseMin(wall.start).cwiseMin(wall.end);
        high = high.cwiseMax(wall.start).cwiseMax(wall.end);
    }
    // A map's extent counts as well (a world may be a map alone, like the office).
    if (world.map && !world.map->empty()) {
        low = low.cwiseMin(world.map->world_min());
        high = high.cwiseMax(world.map->world_max());
    }
    return {low.x() + reach, high.x() - reach, low.y() + reach, high.y() - reach};
}

std::string placement_problem(const sim::WorldSpec& world, const sim::RobotSpec& robot,
                              const Pose2& pose, std::string_view request) {
    const double reach = chassis_reach(robot);
    const PlacementBox box = placement_box(world, reach);
    if (!(pose.x >= box.low_x && pose.x <= box.high_x)) {
        return outside_box(request, 'x', pose.x, box.low_x, box.high_x);
    }
    if (!(pose.y >= box.low_y && pose.y <= box.high_y)) {
        return outside_box(request, 'y', pose.y, box.low_y, box.high_y);
    }
    const Vector2 axle = position_of(pose);
    for (const Wall& wall : world.walls) {
        if (distance_to_segment(axle, wall.start, wall.end) < reach) {
            return too_near(request, pose, reach, "a wall");
        }
    }
    if (world.map && occupied_cell_within(*world.map, axle, reach)) {
        return too_near(request, pose, reach, "an occupied cell");
    }
    return {};
}

}  // namespace legofeup::simserver
