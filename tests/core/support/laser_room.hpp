#pragma once
// Occupancy-grid rooms and synthetic laser scans for the laser lesson's core tests: grids
// built cell by cell from axis-aligned boxes, and scans ray-cast at the true pose with
// Gaussian range noise in whole millimetres, as the URG-04LX reports them.

#include <memory>
#include <random>
#include <vector>

#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/occupancy_grid.hpp"

namespace legofeup::testing {

/// An axis-aligned box [min, max] of occupied space, world frame.
struct OccupiedBox {
    Vector2 min;
    Vector2 max;
};

/// A grid of `resolution` cells covering [min, max]; a cell is occupied when its centre lies
/// in one of `boxes`, free otherwise.
std::shared_ptr<const OccupancyGrid> grid_of_boxes(const Vector2& min, const Vector2& max,
                                                   double resolution,
                                                   const std::vector<OccupiedBox>& boxes);

/// A 4 m × 4 m room centred on the origin (0.1 m thick walls inside [−2.1, 2.1]²), with four
/// obstacles off the 2 m square path so that no two places look alike; 5 cm cells.
/// `extra` boxes are added (a world that differs from the filter's map).
std::shared_ptr<const OccupancyGrid> laser_test_room(const std::vector<OccupiedBox>& extra = {});

/// A 0.6 m × 0.6 m closet around `centre`, nothing else: a scan taken in it looks like no
/// place of laser_test_room.
std::shared_ptr<const OccupancyGrid> closet_room(const Vector2& centre);

/// The scan a scanner at `scanner_pose` measures in `grid`: the noise-free ray cast plus
/// N(0, sigma²) on every valid range, rounded to whole millimetres.
void synthesize_scan(const OccupancyGrid& grid, const Pose2& scanner_pose,
                     const ScanGeometry& geometry, double sigma, std::mt19937_64& rng,
                     LaserScan& out);

}  // namespace legofeup::testing
