#include "legofeup/core/occupancy_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace legofeup {

OccupancyGrid::OccupancyGrid(int width, int height, double resolution, const Pose2& origin,
                             std::vector<CellState> cells)
    : width_(width),
      height_(height),
      resolution_(resolution),
      origin_(origin),
      cells_(std::move(cells)) {
    if (width < 0 || height < 0) {
        throw std::invalid_argument("occupancy grid: negative size " + std::to_string(width) + " × "
                                    + std::to_string(height));
    }
    const auto expected = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (cells_.size() != expected) {
        throw std::invalid_argument("occupancy grid: " + std::to_string(cells_.size())
                                    + " cells for a " + std::to_string(width) + " × "
                                    + std::to_string(height) + " grid (expected "
                                    + std::to_string(expected) + ")");
    }
    if (!std::isfinite(resolution) || resolution <= 0.0) {
        throw std::invalid_argument("occupancy grid: resolution = "
                                    + format_config_number(resolution)
                                    + ": must be a positive finite number of metres per cell");
    }
    if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.theta)) {
        throw std::invalid_argument("occupancy grid: origin = (" + format_config_number(origin.x)
                                    + ", " + format_config_number(origin.y) + ", "
                                    + format_config_number(origin.theta) + "): must be finite");
    }
}

bool OccupancyGrid::contains(const GridCell& cell) const {
    return cell.col >= 0 && cell.col < width_ && cell.row >= 0 && cell.row < height_;
}

CellState OccupancyGrid::at(const GridCell& cell) const {
    if (!contains(cell)) {
        return CellState::Unknown;
    }
    return cells_[static_cast<std::size_t>(cell.row) * static_cast<std::size_t>(width_)
                  + static_cast<std::size_t>(cell.col)];
}

Vector2 OccupancyGrid::to_grid_frame(const Vector2& world) const {
    // g = R(yaw)ᵀ (w − o).
    const double c = std::cos(origin_.theta);
    const double s = std::sin(origin_.theta);
    const double dx = world.x() - origin_.x;
    const double dy = world.y() - origin_.y;
    return {c * dx + s * dy, -s * dx + c * dy};
}

std::optional<GridCell> OccupancyGrid::cell_of(const Vector2& world) const {
    const Vector2 g = to_grid_frame(world);
    const double col = std::floor(g.x() / resolution_);
    const double row = std::floor(g.y() / resolution_);
    if (!(col >= 0.0 && col < width_ && row >= 0.0 && row < height_)) {
        return std::nullopt;  // also catches NaN
    }
    return GridCell{static_cast<int>(col), static_cast<int>(row)};
}

Vector2 OccupancyGrid::centre_of(const GridCell& cell) const {
    // w = o + R(yaw) g, with g the centre in the grid frame.
    const double gx = (cell.col + 0.5) * resolution_;
    const double gy = (cell.row + 0.5) * resolution_;
    const double c = std::cos(origin_.theta);
    const double s = std::sin(origin_.theta);
    return {origin_.x + c * gx - s * gy, origin_.y + s * gx + c * gy};
}

namespace {

/// The four corners of the grid in the world frame.
std::array<Vector2, 4> world_corners(const OccupancyGrid& grid) {
    const Pose2& o = grid.origin();
    const double c = std::cos(o.theta);
    const double s = std::sin(o.theta);
    const double w = grid.width() * grid.resolution();
    const double h = grid.height() * grid.resolution();
    std::array<Vector2, 4> corners;
    const std::array<Vector2, 4> local{Vector2(0, 0), Vector2(w, 0), Vector2(0, h), Vector2(w, h)};
    for (std::size_t i = 0; i < 4; ++i) {
        corners[i] = {o.x + c * local[i].x() - s * local[i].y(),
                      o.y + s * local[i].x() + c * local[i].y()};
    }
    return corners;
}

}  // namespace

Vector2 OccupancyGrid::world_min() const {
    Vector2 result = Vector2::Constant(std::numeric_limits<double>::infinity());
    for (const Vector2& corner : world_corners(*this)) {
        result = result.cwiseMin(corner);
    }
    return result;
}

Vector2 OccupancyGrid::world_max() const {
    Vector2 result = Vector2::Constant(-std::numeric_limits<double>::infinity());
    for (const Vector2& corner : world_corners(*this)) {
        result = result.cwiseMax(corner);
    }
    return result;
}

namespace {

/// The part [t_enter, t_exit] of the ray g + t·d (t ≥ 0) inside the box [0, w] × [0, h]
/// (slab method); nullopt when the ray misses the box.
std::optional<std::pair<double, double>> clip_to_box(const Vector2& g, const Vector2& d, double w,
                                                     double h) {
    double t_enter = 0.0;
    double t_exit = std::numeric_limits<double>::infinity();
    const std::array<double, 2> start{g.x(), g.y()};
    const std::array<double, 2> direction{d.x(), d.y()};
    const std::array<double, 2> size{w, h};
    for (std::size_t axis = 0; axis < 2; ++axis) {
        if (direction[axis] == 0.0) {
            if (start[axis] < 0.0 || start[axis] > size[axis]) {
                return std::nullopt;  // parallel to this slab and outside it
            }
            continue;
        }
        double t0 = (0.0 - start[axis]) / direction[axis];
        double t1 = (size[axis] - start[axis]) / direction[axis];
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        t_enter = std::max(t_enter, t0);
        t_exit = std::min(t_exit, t1);
    }
    if (t_enter > t_exit) {
        return std::nullopt;
    }
    return std::pair{t_enter, t_exit};
}

}  // namespace

std::optional<double> cast_ray(const OccupancyGrid& grid, const Vector2& from, double angle,
                               double max_range) {
    if (grid.empty() || !std::isfinite(angle) || !(max_range >= 0.0) || !from.allFinite()) {
        return std::nullopt;
    }
    const double res = grid.resolution();
    const int width = grid.width();
    const int height = grid.height();
    // Walk in the grid's own frame (metres from the origin along its axes): the ray starts at
    // g and heads along d, the world direction rotated by −yaw.
    const Vector2 g = grid.to_grid_frame(from);
    const double grid_angle = angle - grid.origin().theta;
    const Vector2 d(std::cos(grid_angle), std::sin(grid_angle));

    // A ray starting outside the grid walks from where it enters it.
    const auto span = clip_to_box(g, d, width * res, height * res);
    if (!span || span->first > max_range) {
        return std::nullopt;
    }
    const double t_start = span->first;
    const Vector2 entry = g + t_start * d;
    // The entry cell; clamped because an entry point on the box's far edge floors to the cell
    // past it.
    int col = std::clamp(static_cast<int>(std::floor(entry.x() / res)), 0, width - 1);
    int row = std::clamp(static_cast<int>(std::floor(entry.y() / res)), 0, height - 1);
    const std::vector<CellState>& cells = grid.cells();
    const auto occupied = [&](int c, int r) {
        return cells[static_cast<std::size_t>(r) * static_cast<std::size_t>(width)
                     + static_cast<std::size_t>(c)]
               == CellState::Occupied;
    };
    if (occupied(col, row)) {
        return t_start;  // 0 when the ray starts inside an occupied cell
    }

    // Amanatides & Woo: t_max_* is the ray parameter (metres) where the ray crosses the next
    // vertical / horizontal cell boundary, t_delta_* the parameter step between two such
    // boundaries. Each step moves into the cell whose boundary comes first.
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const int step_col = d.x() > 0.0 ? 1 : -1;
    const int step_row = d.y() > 0.0 ? 1 : -1;
    const double t_delta_x = d.x() != 0.0 ? res / std::abs(d.x()) : kInfinity;
    const double t_delta_y = d.y() != 0.0 ? res / std::abs(d.y()) : kInfinity;
    double t_max_x = kInfinity;
    if (d.x() != 0.0) {
        const double boundary = (d.x() > 0.0 ? col + 1 : col) * res;
        t_max_x = (boundary - g.x()) / d.x();
    }
    double t_max_y = kInfinity;
    if (d.y() != 0.0) {
        const double boundary = (d.y() > 0.0 ? row + 1 : row) * res;
        t_max_y = (boundary - g.y()) / d.y();
    }
    for (;;) {
        double t = 0.0;
        if (t_max_x < t_max_y) {
            t = t_max_x;
            col += step_col;
            t_max_x += t_delta_x;
        } else {
            t = t_max_y;
            row += step_row;
            t_max_y += t_delta_y;
        }
        if (t > max_range || col < 0 || col >= width || row < 0 || row >= height) {
            return std::nullopt;
        }
        if (occupied(col, row)) {
            return std::max(t, t_start);
        }
    }
}

void expected_scan(const OccupancyGrid& grid, const Pose2& scanner_pose,
                   const ScanGeometry& geometry, LaserScan& out) {
    const int beams = std::clamp(geometry.beam_count, 0, kMaxScanBeams);
    out.beam_count = static_cast<std::uint16_t>(beams);
    const Vector2 from = position_of(scanner_pose);
    // The largest range a 16-bit millimetre value can carry.
    constexpr double kMaxEncodable = 65.535;
    const double max_range = std::min(geometry.range_max, kMaxEncodable);
    for (int beam = 0; beam < beams; ++beam) {
        const std::optional<double> range =
            cast_ray(grid, from, scanner_pose.theta + geometry.angle_of(beam), max_range);
        out.range_mm[static_cast<std::size_t>(beam)] = range_reading(range, geometry);
    }
    // Entries past the beam count are zero, so equal scans compare equal.
    std::fill(out.range_mm.begin() + beams, out.range_mm.end(), std::uint16_t{0});
}

}  // namespace legofeup
