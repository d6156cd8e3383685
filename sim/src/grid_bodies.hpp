#pragma once
// The occupancy-grid map of a world (paper 001) as solid static Box2D geometry: its occupied
// cells merged into few axis-aligned rectangles, each a box fixture of one static body that
// sits at the grid's origin. Private to sim/.

#include <box2d/box2d.h>

#include <vector>

#include "legofeup/core/occupancy_grid.hpp"

namespace legofeup::sim {

/// A rectangle of whole cells in the grid's own frame: `width` × `height` cells whose lower
/// left one is (col, row).
struct CellRectangle {
    int col = 0;
    int row = 0;
    int width = 1;   ///< cells along the grid's x axis
    int height = 1;  ///< cells along the grid's y axis

    friend bool operator==(const CellRectangle&, const CellRectangle&) = default;
};

/// The occupied cells of `grid` as rectangles that cover every occupied cell exactly once and
/// nothing else (free and unknown cells stay open). Greedy, in two passes:
///   1. each row splits into maximal runs of consecutive occupied cells;
///   2. a run with the same first column and width as a rectangle ending on the row below
///      extends that rectangle upwards, otherwise it starts a new one.
/// A wall of thickness t and length L becomes one rectangle whichever way it runs. The result
/// is sorted by (row, col) of the lower-left cell: a fixed order, so Box2D creates the
/// fixtures in the same order every time (determinism).
std::vector<CellRectangle> occupied_rectangles(const OccupancyGrid& grid);

/// Creates one static body whose pose is the grid's origin (position and yaw), with one box
/// fixture per rectangle of occupied_rectangles(grid), in that order, at the cells' exact
/// boundaries (a ray reflects on the cell's edge, as the filter's grid ray casting assumes).
/// Returns the body, or nullptr when no cell is occupied (no body is created then).
b2Body* build_grid_body(b2World& world, const OccupancyGrid& grid);

}  // namespace legofeup::sim
