#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace legofeup {
namespace {

using testing::GridDrawing;

/// The exact distance along g + t·d to the first occupied cell, by intersecting the ray with
/// every occupied cell's square (slab method) — no grid traversal. Grid frame, origin at 0.
std::optional<double> brute_force_ray(const OccupancyGrid& grid, const Vector2& g, double angle,
                                      double max_range) {
    const Vector2 d(std::cos(angle), std::sin(angle));
    const double r = grid.resolution();
    double best = std::numeric_limits<double>::infinity();
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            if (!grid.occupied({col, row})) {
                continue;
            }
            double t_enter = -std::numeric_limits<double>::infinity();
            double t_exit = std::numeric_limits<double>::infinity();
            const double lo[2] = {col * r, row * r};
            const double start[2] = {g.x(), g.y()};
            const double dir[2] = {d.x(), d.y()};
            for (int axis = 0; axis < 2; ++axis) {
                const double t0 = (lo[axis] - start[axis]) / dir[axis];
                const double t1 = (lo[axis] + r - start[axis]) / dir[axis];
                t_enter = std::max(t_enter, std::min(t0, t1));
                t_exit = std::min(t_exit, std::max(t0, t1));
            }
            if (t_enter <= t_exit && t_exit >= 0.0) {
                best = std::min(best, std::max(t_enter, 0.0));
            }
        }
    }
    if (best > max_range) {
        return std::nullopt;
    }
    return best;
}

TEST(OccupancyGrid, ConstructorRejectsInconsistentData) {
    EXPECT_THROW(OccupancyGrid(3, 2, 0.05, {}, std::vector<CellState>(5)), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(3, 2, 0.0, {}, std::vector<CellState>(6)), std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(3, 2, std::numeric_limits<double>::quiet_NaN(), {},
                               std::vector<CellState>(6)),
                 std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(3, 2, 0.05, {0.0, std::numeric_limits<double>::infinity(), 0.0},
                               std::vector<CellState>(6)),
                 std::invalid_argument);
    EXPECT_THROW(OccupancyGrid(-1, 2, 0.05, {}, {}), std::invalid_argument);
    try {
        OccupancyGrid(3, 2, 0.05, {}, std::vector<CellState>(5));
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("5 cells"), std::string::npos) << error.what();
    }
    EXPECT_NO_THROW(OccupancyGrid(3, 2, 0.05, {}, std::vector<CellState>(6)));
}

TEST(OccupancyGrid, CellsAreRowMajorFromTheBottomRow) {
    std::vector<CellState> cells(6, CellState::Free);
    cells[1 * 3 + 2] = CellState::Occupied;  // row 1, col 2
    cells[0 * 3 + 1] = CellState::Unknown;   // row 0, col 1
    const OccupancyGrid grid(3, 2, 0.5, {}, cells);
    EXPECT_TRUE(grid.occupied({2, 1}));
    EXPECT_EQ(grid.at({1, 0}), CellState::Unknown);
    EXPECT_EQ(grid.at({0, 0}), CellState::Free);
    EXPECT_EQ(grid.at({3, 0}), CellState::Unknown);  // outside
    EXPECT_EQ(grid.at({0, -1}), CellState::Unknown);
    EXPECT_FALSE(grid.contains({-1, 0}));
    // (1.2, 0.7) lies in col ⌊1.2/0.5⌋ = 2, row ⌊0.7/0.5⌋ = 1.
    EXPECT_EQ(grid.cell_of({1.2, 0.7}), (GridCell{2, 1}));
    EXPECT_FALSE(grid.cell_of({1.6, 0.7}).has_value());
    EXPECT_FALSE(grid.cell_of({-0.01, 0.7}).has_value());
}

TEST(OccupancyGrid, OriginYawRotatesTheGridAboutItsCorner) {
    // Origin (1, 2) with yaw 90°: grid (gx, gy) is world (1 − gy, 2 + gx).
    const OccupancyGrid grid(4, 2, 0.5, {1.0, 2.0, 0.5 * kPi}, std::vector<CellState>(8));
    const Vector2 centre = grid.centre_of({1, 0});  // grid (0.75, 0.25)
    EXPECT_NEAR(centre.x(), 0.75, 1e-12);
    EXPECT_NEAR(centre.y(), 2.75, 1e-12);
    const Vector2 g = grid.to_grid_frame({0.75, 2.75});
    EXPECT_NEAR(g.x(), 0.75, 1e-12);
    EXPECT_NEAR(g.y(), 0.25, 1e-12);
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            EXPECT_EQ(grid.cell_of(grid.centre_of({col, row})), (GridCell{col, row}));
        }
    }
    // Corners (0,0), (2,0), (0,1), (2,1) in the grid frame ↦ (1,2), (1,4), (0,2), (0,4).
    EXPECT_NEAR(grid.world_min().x(), 0.0, 1e-12);
    EXPECT_NEAR(grid.world_min().y(), 2.0, 1e-12);
    EXPECT_NEAR(grid.world_max().x(), 1.0, 1e-12);
    EXPECT_NEAR(grid.world_max().y(), 4.0, 1e-12);
}

TEST(CastRay, AxisAlignedWallAtAnalyticDistance) {
    // 5 m × 5 m, 0.05 m cells, column 80 occupied: a wall whose near face is x = 4.0.
    GridDrawing drawing(5.0, 5.0, 0.05);
    for (int row = 0; row < 100; ++row) {
        drawing.cell(80, row, CellState::Occupied);
    }
    const OccupancyGrid grid = drawing.grid();
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> dx(0.0, 0.5);
    std::uniform_real_distribution<double> dy(-0.2, 0.2);
    int rays = 0;
    for (double deg = -35.0; deg <= 35.0; deg += 0.5) {
        const Vector2 from(1.0 + dx(rng), 2.5 + dy(rng));
        const double angle = degrees_to_radians(deg);
        const double analytic = (4.0 - from.x()) / std::cos(angle);
        const std::optional<double> range = cast_ray(grid, from, angle, 10.0);
        ASSERT_TRUE(range.has_value()) << deg << "°";
        EXPECT_NEAR(*range, analytic, 1e-9) << deg << "°";
        ++rays;
    }
    EXPECT_EQ(rays, 141);
    // Pointing away from the wall: the ray leaves the grid.
    EXPECT_FALSE(cast_ray(grid, {1.0, 2.5}, kPi, 10.0).has_value());
    EXPECT_FALSE(cast_ray(grid, {1.0, 2.5}, 0.5 * kPi, 10.0).has_value());
    // max_range: the wall 3 m away is beyond 2.99 m, within 3.01 m.
    EXPECT_FALSE(cast_ray(grid, {1.0, 2.5}, 0.0, 2.99).has_value());
    EXPECT_NEAR(*cast_ray(grid, {1.0, 2.5}, 0.0, 3.01), 3.0, 1e-12);
}

TEST(CastRay, DiagonalLineOfCellsWithinOneCellDiagonal) {
    // Cells (i, i) occupied: a staircase covering the line y = x.
    constexpr double kRes = 0.05;
    GridDrawing drawing(5.0, 5.0, kRes);
    for (int i = 0; i < 100; ++i) {
        drawing.cell(i, i, CellState::Occupied);
    }
    const OccupancyGrid grid = drawing.grid();
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    int rays = 0;
    for (double deg = 0.0; deg < 360.0; deg += 0.25) {
        const Vector2 from(3.5 + jitter(rng), 1.0 + jitter(rng));  // below the line
        const Vector2 d(std::cos(degrees_to_radians(deg)), std::sin(degrees_to_radians(deg)));
        // The ray meets y = x at t = (x₀ − y₀)/(dᵧ − dₓ) if it heads towards the line; keep
        // rays at least 30° off the line, so the staircase's offset from the line (at most
        // half a cell diagonal, res/√2, across it) is at most res·√2 along the ray.
        const double closing = d.y() - d.x();
        const double sin_incidence = closing / std::sqrt(2.0);
        if (sin_incidence < 0.5) {
            continue;
        }
        const double t_line = (from.x() - from.y()) / closing;
        const Vector2 hit = from + t_line * d;
        if (hit.x() < 0.0 || hit.x() > 5.0) {
            continue;  // the line leaves the grid there
        }
        const std::optional<double> range = cast_ray(grid, from, degrees_to_radians(deg), 10.0);
        ASSERT_TRUE(range.has_value()) << deg << "°";
        EXPECT_LE(*range, t_line + 1e-9) << deg << "°";
        EXPECT_GE(*range, t_line - kRes * std::sqrt(2.0)) << deg << "°";
        ++rays;
    }
    EXPECT_GT(rays, 300);
}

TEST(CastRay, MatchesBruteForceIntersectionOnRandomMaps) {
    std::mt19937 rng(5);
    std::bernoulli_distribution occupied(0.04);
    std::uniform_real_distribution<double> px(-1.0, 5.0);
    std::uniform_real_distribution<double> py(-1.0, 4.0);
    std::uniform_real_distribution<double> heading(-kPi, kPi);
    for (int map = 0; map < 5; ++map) {
        GridDrawing drawing(4.0, 3.0, 0.1);
        for (int row = 0; row < 30; ++row) {
            for (int col = 0; col < 40; ++col) {
                if (occupied(rng)) {
                    drawing.cell(col, row, CellState::Occupied);
                }
            }
        }
        const OccupancyGrid grid = drawing.grid();
        int hits = 0;
        for (int ray = 0; ray < 400; ++ray) {
            // Starts inside and outside the grid, in free and in occupied cells.
            const Vector2 from(px(rng), py(rng));
            const double angle = heading(rng);
            const double max_range = ray % 2 == 0 ? 10.0 : 1.5;
            const std::optional<double> expected = brute_force_ray(grid, from, angle, max_range);
            const std::optional<double> actual = cast_ray(grid, from, angle, max_range);
            ASSERT_EQ(actual.has_value(), expected.has_value())
                << "map " << map << " ray " << ray << " from (" << from.x() << ", " << from.y()
                << ") at " << angle;
            if (expected) {
                EXPECT_NEAR(*actual, *expected, 1e-9) << "map " << map << " ray " << ray;
                ++hits;
            }
        }
        EXPECT_GT(hits, 100) << "map " << map;
    }
}

TEST(CastRay, OriginYawAndOffsetAreHonoured) {
    // Same cells, grid placed at (o, φ): a ray from o + R(φ)·g at angle a + φ sees exactly what
    // a ray from g at angle a sees in the unrotated grid.
    const OccupancyGrid plain = testing::room_grid();
    const Pose2 origin{-1.5, 2.0, 0.7};
    const OccupancyGrid placed(plain.width(), plain.height(), plain.resolution(), origin,
                               plain.cells());
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> gx(0.2, 5.8);
    std::uniform_real_distribution<double> gy(0.2, 3.8);
    std::uniform_real_distribution<double> heading(-kPi, kPi);
    const double c = std::cos(origin.theta);
    const double s = std::sin(origin.theta);
    for (int ray = 0; ray < 500; ++ray) {
        const Vector2 g(gx(rng), gy(rng));
        const double a = heading(rng);
        const Vector2 world(origin.x + c * g.x() - s * g.y(), origin.y + s * g.x() + c * g.y());
        const std::optional<double> expected = cast_ray(plain, g, a, 8.0);
        const std::optional<double> actual = cast_ray(placed, world, a + origin.theta, 8.0);
        ASSERT_EQ(actual.has_value(), expected.has_value()) << ray;
        if (expected) {
            EXPECT_NEAR(*actual, *expected, 1e-9) << ray;
        }
    }
    // Hand-worked: origin (1, 1) at 90°, column 9 of a 10 × 10 grid of 0.1 m cells occupied:
    // grid x ∈ [0.9, 1.0] is world y ∈ [1.9, 2.0]. From world (0.5, 1.2) straight up: 0.7 m.
    GridDrawing drawing(1.0, 1.0, 0.1);
    for (int row = 0; row < 10; ++row) {
        drawing.cell(9, row, CellState::Occupied);
    }
    const OccupancyGrid turned = drawing.grid({1.0, 1.0, 0.5 * kPi});
    EXPECT_NEAR(*cast_ray(turned, {0.5, 1.2}, 0.5 * kPi, 5.0), 0.7, 1e-12);
    // Along world +x the ray leaves the grid (world x = 1 is its edge gy = 0) first.
    EXPECT_FALSE(cast_ray(turned, {0.5, 1.2}, 0.0, 5.0).has_value());
}

TEST(CastRay, StartsOutsideInsideAndThroughUnknownCells) {
    GridDrawing drawing(5.0, 5.0, 0.05);
    for (int row = 0; row < 100; ++row) {
        drawing.cell(80, row, CellState::Occupied);
        drawing.cell(40, row, CellState::Unknown);  // x ∈ [2.0, 2.05]: does not stop rays
    }
    const OccupancyGrid grid = drawing.grid();
    // From 1 m left of the grid: enters at x = 0, hits at x = 4.
    EXPECT_NEAR(*cast_ray(grid, {-1.0, 2.5}, 0.0, 10.0), 5.0, 1e-12);
    EXPECT_FALSE(cast_ray(grid, {-1.0, 2.5}, 0.0, 0.5).has_value());   // grid beyond range
    EXPECT_FALSE(cast_ray(grid, {-1.0, 2.5}, kPi, 10.0).has_value());  // pointing away
    EXPECT_FALSE(cast_ray(grid, {-1.0, 6.0}, 0.0, 10.0).has_value());  // passes above
    // Inside an occupied cell: 0, whatever the direction.
    for (double angle : {0.0, 1.0, 2.0, -2.5}) {
        EXPECT_EQ(*cast_ray(grid, {4.02, 2.5}, angle, 10.0), 0.0);
    }
    // From the far side of the wall, the wall is behind: the ray leaves the grid.
    EXPECT_FALSE(cast_ray(grid, {4.5, 2.5}, 0.0, 10.0).has_value());
    EXPECT_NEAR(*cast_ray(grid, {4.5, 2.5}, kPi, 10.0), 0.45, 1e-12);
    // An empty grid stops nothing.
    EXPECT_FALSE(cast_ray(OccupancyGrid{}, {0.0, 0.0}, 0.0, 10.0).has_value());
}

TEST(ExpectedScan, RangesAndCodesInTheRoom) {
    const OccupancyGrid room = testing::room_grid();  // inner faces at x = 0.1, 5.9, y = 0.1, 3.9
    ScanGeometry g;
    g.beam_count = 4;  // 0°, 90°, 180°, 270°
    g.angle_min = 0.0;
    g.angle_increment = 0.5 * kPi;
    g.range_max = 5.6;
    LaserScan scan;
    scan.range_mm.fill(77);
    expected_scan(room, Pose2{2.0, 2.0, 0.0}, g, scan);
    EXPECT_EQ(scan.beam_count, 4);
    EXPECT_EQ(scan.range_mm[0], 3900);  // right wall
    EXPECT_EQ(scan.range_mm[1], 1900);  // top wall
    EXPECT_EQ(scan.range_mm[2], 1900);  // left wall
    EXPECT_EQ(scan.range_mm[3], 1900);  // bottom wall
    EXPECT_EQ(scan.range_mm[4], 0);     // past the beam count
    EXPECT_EQ(scan.range_mm[kMaxScanBeams - 1], 0);

    // Turned to face +y, beam 0 sees the top wall; the pillar (x ∈ [3.8, 4.2]) at 1.9 m ahead
    // of a scanner at (4.0, 2.9) facing −y: y = 1.4 is 1.5 m away.
    expected_scan(room, Pose2{2.0, 2.0, 0.5 * kPi}, g, scan);
    EXPECT_EQ(scan.range_mm[0], 1900);
    EXPECT_EQ(scan.range_mm[1], 1900);  // left wall
    expected_scan(room, Pose2{4.0, 2.9, -0.5 * kPi}, g, scan);
    EXPECT_EQ(scan.range_mm[0], 1500);

    // No echo beyond range_max; too near within range_min.
    g.range_max = 2.0;
    expected_scan(room, Pose2{2.0, 2.0, 0.0}, g, scan);
    EXPECT_EQ(scan.range_mm[0], kRangeNoEcho);  // 3.9 m > 2 m
    EXPECT_EQ(scan.range_mm[1], 1900);
    g.range_min = 0.05;
    expected_scan(room, Pose2{0.13, 2.0, kPi}, g, scan);  // 3 cm from the left wall
    EXPECT_EQ(scan.range_mm[0], kRangeTooNear);
    expected_scan(room, Pose2{0.05, 2.0, 0.0}, g, scan);  // inside the wall
    EXPECT_EQ(scan.range_mm[0], kRangeTooNear);
}

TEST(ExpectedScan, EveryBeamIsItsRayRoundedToMillimetres) {
    const OccupancyGrid room = testing::room_grid();
    const ScanGeometry urg;
    const Pose2 pose{2.3, 1.7, 0.4};
    LaserScan scan;
    expected_scan(room, pose, urg, scan);
    ASSERT_EQ(scan.beam_count, 682);
    int echoes = 0;
    for (int beam = 0; beam < urg.beam_count; ++beam) {
        const std::optional<double> ray =
            cast_ray(room, position_of(pose), pose.theta + urg.angle_of(beam), urg.range_max);
        const std::uint16_t value = scan.range_mm[static_cast<std::size_t>(beam)];
        if (!ray) {
            EXPECT_EQ(value, kRangeNoEcho) << beam;
            continue;
        }
        EXPECT_NEAR(value, *ray * 1000.0, 0.5) << beam;
        ++echoes;
    }
    // The room is 6 m × 4 m: only the far corner region can lie beyond 5.6 m.
    EXPECT_GT(echoes, 600);
}

}  // namespace
}  // namespace legofeup
