#pragma once
// An occupancy-grid map (paper 001) as a picture for the arena view: one pixel per cell,
// occupied cells in the map colour, unknown ones grey, free ones transparent (the floor shows
// through). A map never changes during a run, so the picture is made once per run (and per
// palette) and drawn each frame through image_to_world() ∘ world → widget.
//
// Pixel (u, v) of the picture (v down, as images go) is cell (col, row) = (u, H − 1 − v) of
// the grid (row 0 at the bottom, ROS map_server convention); image_to_world() places it in
// the world with the map's resolution, origin and yaw.

#include <QColor>
#include <QImage>
#include <QTransform>

#include "legofeup/core/occupancy_grid.hpp"

namespace legofeup::ui {

struct MapColors {
    QColor occupied;
    QColor unknown;
    // Free cells are transparent.
};

/// The map as an ARGB32 picture of width × height pixels (empty for an empty map).
QImage map_image(const OccupancyGrid& grid, const MapColors& colors);

/// Picture pixels (u, v) → world metres: the grid frame is x = r·u, y = r·(H − v), then
/// rotated by the origin's yaw and moved to its position.
QTransform image_to_world(const OccupancyGrid& grid);

/// The world rectangle the map covers (its four corners' bounding box).
QRectF map_world_bounds(const OccupancyGrid& grid);

}  // namespace legofeup::ui
