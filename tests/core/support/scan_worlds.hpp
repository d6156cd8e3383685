#pragma once
// Occupancy grids for the scan tests and the scan benchmark, drawn as axis-aligned
// rectangles of occupied cells so the walls' positions are known exactly.

#include <algorithm>
#include <cmath>
#include <vector>

#include "legofeup/core/occupancy_grid.hpp"

namespace legofeup::testing {

/// A free grid of width_m × height_m metres that rectangles of occupied cells are drawn into.
class GridDrawing {
  public:
    GridDrawing(double width_m, double height_m, double resolution)
        : width_(static_cast<int>(std::lround(width_m / resolution))),
          height_(static_cast<int>(std::lround(height_m / resolution))),
          resolution_(resolution),
          cells_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_),
                 CellState::Free) {}

    /// Occupies every cell whose centre lies in [x0, x1] × [y0, y1] (grid-frame metres).
    GridDrawing& rectangle(double x0, double y0, double x1, double y1) {
        for (int row = 0; row < height_; ++row) {
            for (int col = 0; col < width_; ++col) {
                const double x = (col + 0.5) * resolution_;
                const double y = (row + 0.5) * resolution_;
                if (x >= x0 && x <= x1 && y >= y0 && y <= y1) {
                    cells_[index(col, row)] = CellState::Occupied;
                }
            }
        }
        return *this;
    }
    /// Occupies the cells along the grid's border, `thickness` metres wide.
    GridDrawing& border(double thickness) {
        const double w = width_ * resolution_;
        const double h = height_ * resolution_;
        rectangle(0, 0, w, thickness);
        rectangle(0, h - thickness, w, h);
        rectangle(0, 0, thickness, h);
        rectangle(w - thickness, 0, w, h);
        return *this;
    }
    GridDrawing& cell(int col, int row, CellState state) {
        cells_[index(col, row)] = state;
        return *this;
    }

    OccupancyGrid grid(const Pose2& origin = {}) const {
        return OccupancyGrid(width_, height_, resolution_, origin, cells_);
    }

  private:
    std::size_t index(int col, int row) const {
        return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_)
               + static_cast<std::size_t>(col);
    }

    int width_;
    int height_;
    double resolution_;
    std::vector<CellState> cells_;
};

/// A 6 m × 4 m room (0.05 m cells, 0.1 m walls) with a pillar and a cupboard, so no pose
/// inside it looks like another (a bare rectangle is symmetric).
inline OccupancyGrid room_grid() {
    return GridDrawing(6.0, 4.0, 0.05)
        .border(0.1)
        .rectangle(3.8, 1.0, 4.2, 1.4)   // pillar
        .rectangle(0.1, 3.0, 1.2, 3.9)   // cupboard in the top-left corner
        .rectangle(5.0, 0.1, 5.9, 0.45)  // low shelf along the bottom wall
        .grid();
}

/// A 12 m × 8 m office (0.05 m cells): outer walls, two partition walls with doors, pillars
/// and desks.
inline OccupancyGrid office_grid() {
    return GridDrawing(12.0, 8.0, 0.05)
        .border(0.15)
        .rectangle(4.0, 0.15, 4.1, 3.0)  // partition, door from y = 3 to 4
        .rectangle(4.0, 4.0, 4.1, 7.85)
        .rectangle(8.0, 0.15, 8.1, 5.0)  // partition, door from y = 5 to 6
        .rectangle(8.0, 6.0, 8.1, 7.85)
        .rectangle(1.0, 5.5, 2.6, 6.3)  // desks
        .rectangle(5.5, 1.0, 7.0, 1.8)
        .rectangle(9.5, 6.5, 11.0, 7.2)
        .rectangle(6.0, 5.8, 6.3, 6.1)  // pillars
        .rectangle(10.0, 2.0, 10.3, 2.3)
        .grid();
}

}  // namespace legofeup::testing
