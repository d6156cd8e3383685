#pragma once
// An occupancy-grid map (paper 001: the pre-acquired map the ray casting runs in), in the
// ROS map_server convention: square cells of `resolution` metres, cell (0, 0) is the lower
// left one and its lower-left corner sits at `origin` (x, y, yaw) in the world. Each cell is
// free, occupied or unknown. Reading the PGM + YAML files is lessons::load_map_file's job;
// this is the map as plain data, used by the filter (ray casting) and the simulator (walls).

#include <cstdint>
#include <optional>
#include <vector>

#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

enum class CellState : std::uint8_t { Free, Occupied, Unknown };

struct GridCell {
    int col = 0;  ///< 0 … width − 1, along the grid's x axis
    int row = 0;  ///< 0 … height − 1, along the grid's y axis (row 0 at the bottom)

    friend bool operator==(const GridCell&, const GridCell&) = default;
};

class OccupancyGrid {
  public:
    OccupancyGrid() = default;
    /// `cells` is row-major, row 0 first (the bottom row), width·height entries.
    /// Throws std::invalid_argument when the sizes disagree, the resolution is not positive
    /// and finite, or the origin is not finite.
    OccupancyGrid(int width, int height, double resolution, const Pose2& origin,
                  std::vector<CellState> cells);

    int width() const { return width_; }
    int height() const { return height_; }
    double resolution() const { return resolution_; }  ///< m per cell
    const Pose2& origin() const { return origin_; }
    bool empty() const { return cells_.empty(); }

    /// The cell's state; cells outside the grid are Unknown.
    CellState at(const GridCell& cell) const;
    bool occupied(const GridCell& cell) const { return at(cell) == CellState::Occupied; }
    bool contains(const GridCell& cell) const;

    /// The cell containing a world point (nullopt outside the grid).
    std::optional<GridCell> cell_of(const Vector2& world) const;
    /// The world position of a cell's centre.
    Vector2 centre_of(const GridCell& cell) const;
    /// A world point in the grid's own frame (metres from the origin along its axes).
    Vector2 to_grid_frame(const Vector2& world) const;

    /// The world-frame corners of the grid's bounding box (for views and validation).
    Vector2 world_min() const;
    Vector2 world_max() const;

    const std::vector<CellState>& cells() const { return cells_; }

  private:
    int width_ = 0;
    int height_ = 0;
    double resolution_ = 0.05;
    Pose2 origin_;
    std::vector<CellState> cells_;
};

/// Distance from `from` along the direction `angle` (world frame) to where the ray enters
/// the first occupied cell, walking the grid cell by cell (Amanatides & Woo); nullopt when
/// nothing occupied lies within `max_range` or the ray leaves the grid. A ray starting inside
/// an occupied cell returns 0. Unknown cells do not stop a ray.
std::optional<double> cast_ray(const OccupancyGrid& grid, const Vector2& from, double angle,
                               double max_range);

/// The scan a scanner at `scanner_pose` (world frame) would measure in a noise-free world
/// that is exactly `grid` (paper 001 Fig. 2): one ray per beam of `geometry`; beams that hit
/// nothing within range_max read kRangeNoEcho, hits nearer than range_min kRangeTooNear.
void expected_scan(const OccupancyGrid& grid, const Pose2& scanner_pose,
                   const ScanGeometry& geometry, LaserScan& out);

}  // namespace legofeup
