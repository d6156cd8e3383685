#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "legofeup/core/likelihood_field.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "scan_worlds.hpp"

namespace legofeup {
namespace {

bool likelihood_field_has_issue(const std::vector<ConfigIssue>& issues, const std::string& field) {
    for (const ConfigIssue& issue : issues) {
        if (issue.field == field) {
            return true;
        }
    }
    return false;
}

/// A grid of random cells: occupied with probability `occupied`, else unknown with
/// probability 0.1 (unknown is not an obstacle), else free.
OccupancyGrid random_likelihood_grid(int width, int height, double resolution, const Pose2& origin,
                                     double occupied, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<CellState> cells(static_cast<std::size_t>(width)
                                 * static_cast<std::size_t>(height));
    for (CellState& cell : cells) {
        const double draw = u(rng);
        cell = draw < occupied ? CellState::Occupied
                               : (draw < occupied + 0.1 ? CellState::Unknown : CellState::Free);
    }
    return OccupancyGrid(width, height, resolution, origin, std::move(cells));
}

/// The distance from a cell's centre to the nearest occupied cell's centre, searching every
/// cell, in world coordinates (through the origin's yaw); ∞ when no cell is occupied.
double brute_force_nearest_occupied(const OccupancyGrid& grid, const GridCell& from) {
    const Vector2 centre = grid.centre_of(from);
    double best = std::numeric_limits<double>::infinity();
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            if (grid.occupied({col, row})) {
                best = std::min(best, (grid.centre_of({col, row}) - centre).norm());
            }
        }
    }
    return best;
}

/// Every cell of the field against the brute-force search, both through the cell and
/// through its centre's world position.
void expect_field_matches_brute_force(const OccupancyGrid& grid, double max_distance,
                                      const std::string& label) {
    const LikelihoodField field(grid, max_distance);
    ASSERT_EQ(field.width(), grid.width());
    ASSERT_EQ(field.height(), grid.height());
    ASSERT_EQ(field.distances().size(), grid.cells().size());
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            const double expected =
                std::min(brute_force_nearest_occupied(grid, {col, row}), max_distance);
            // Stored as float: 1e-7 relative, plus the yawed centres' rounding.
            const double tolerance = 1e-6 * (1.0 + expected);
            ASSERT_NEAR(field.distance_at(GridCell{col, row}), expected, tolerance)
                << label << " cell (" << col << ", " << row << ")";
            ASSERT_NEAR(field.distance_at(grid.centre_of({col, row})), expected, tolerance)
                << label << " centre of (" << col << ", " << row << ")";
        }
    }
}

/// One term of the likelihood field model (Table 6.3), written out as the book does.
double book_term(double d, double sigma, double z_hit, double z_random, double z_max) {
    const double gaussian =
        std::exp(-d * d / (2.0 * sigma * sigma)) / (std::sqrt(2.0 * kPi) * sigma);
    return std::log(z_hit * gaussian + z_random / z_max);
}

TEST(LikelihoodFieldParams, DefaultsAreValidAndEachBadFieldIsNamed) {
    const LikelihoodFieldParams defaults;
    EXPECT_TRUE(validate(defaults, "pf.laser").empty());

    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const auto rejects = [](LikelihoodFieldParams params, const std::string& field) {
        const auto issues = validate(params, "pf.laser");
        EXPECT_TRUE(likelihood_field_has_issue(issues, "pf.laser." + field))
            << field << ": " << join_issue_messages(issues, "; ");
    };
    for (const double bad : {0.0, -0.1, 1e-9, nan, inf}) {
        LikelihoodFieldParams p;
        p.sigma_hit = bad;
        rejects(p, "sigma_hit");
    }
    for (const double bad : {-0.1, 1.5, nan, inf}) {
        LikelihoodFieldParams p;
        p.z_hit = bad;
        rejects(p, "z_hit");
        p = {};
        p.z_random = bad;
        rejects(p, "z_random");
    }
    for (const int bad : {0, -3, kMaxScanBeams + 1}) {
        LikelihoodFieldParams p;
        p.beam_stride = bad;
        rejects(p, "beam_stride");
    }
    for (const double bad : {0.0, -1.0, nan, inf}) {
        LikelihoodFieldParams p;
        p.max_distance = bad;
        rejects(p, "max_distance");
    }
    LikelihoodFieldParams both_zero;
    both_zero.z_hit = 0.0;
    both_zero.z_random = 0.0;
    rejects(both_zero, "z_random");

    // Relative weights: a sum above 1, or either one 0 alone, is fine.
    LikelihoodFieldParams heavy;
    heavy.z_hit = 0.9;
    heavy.z_random = 0.8;
    EXPECT_TRUE(validate(heavy, "pf.laser").empty());
    heavy.z_random = 0.0;
    EXPECT_TRUE(validate(heavy, "pf.laser").empty());
    heavy.z_hit = 0.0;
    heavy.z_random = 1.0;
    EXPECT_TRUE(validate(heavy, "pf.laser").empty());
    LikelihoodFieldParams edges;
    edges.beam_stride = kMaxScanBeams;
    edges.sigma_hit = 1e-6;
    EXPECT_TRUE(validate(edges, "pf.laser").empty());
}

TEST(LikelihoodField, ConstructorRejectsABadMaxDistance) {
    const OccupancyGrid grid = testing::GridDrawing(1.0, 1.0, 0.1).border(0.1).grid();
    for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(LikelihoodField(grid, bad), std::invalid_argument) << bad;
    }
    EXPECT_NO_THROW(LikelihoodField(grid, 0.01));
}

TEST(LikelihoodField, DistanceTransformEqualsBruteForceOnRandomGrids) {
    struct Case {
        int width;
        int height;
        double resolution;
        Pose2 origin;
        double occupied;
    };
    const std::vector<Case> cases{
        {23, 41, 0.05, {}, 0.05},                  // taller than wide
        {41, 17, 0.1, {-1.3, 2.1, 0.7}, 0.2},      // wider than tall, origin with a yaw
        {1, 37, 0.05, {0.5, -0.2, -2.5}, 0.1},     // one column
        {37, 1, 0.25, {}, 0.1},                    // one row
        {30, 30, 0.05, {2.0, 1.0, kPi / 2}, 0.6},  // dense
        {32, 24, 0.02, {-0.4, 0.3, 3.0}, 0.003},   // sparse: long distances
        {1, 1, 0.1, {}, 1.0},
    };
    for (const unsigned seed : {1U, 2U, 3U, 4U}) {
        std::mt19937 rng(seed);
        for (const Case& c : cases) {
            const OccupancyGrid grid =
                random_likelihood_grid(c.width, c.height, c.resolution, c.origin, c.occupied, rng);
            const std::string label = "seed " + std::to_string(seed) + ", "
                                      + std::to_string(c.width) + "×" + std::to_string(c.height);
            // max_distance far beyond every distance: no clamp.
            expect_field_matches_brute_force(grid, 1000.0, label);
        }
    }
}

TEST(LikelihoodField, ASingleObstacleGivesExactEuclideanDistancesAcrossALargeGrid) {
    // 600 × 400 cells, one occupied cell in a corner: the far corner is √(599² + 399²) cells
    // away, a squared distance (517 402 cells²) far above what a 1-D pass alone gives.
    testing::GridDrawing drawing(30.0, 20.0, 0.05);
    drawing.cell(0, 0, CellState::Occupied);
    const OccupancyGrid grid = drawing.grid();
    const LikelihoodField field(grid, 100.0);
    EXPECT_TRUE(field.has_obstacles());
    for (const GridCell cell : {GridCell{599, 399}, GridCell{599, 0}, GridCell{0, 399},
                                GridCell{300, 17}, GridCell{1, 1}, GridCell{0, 0}}) {
        const double expected = 0.05 * std::hypot(cell.col, cell.row);
        EXPECT_NEAR(field.distance_at(cell), expected, 1e-6 * (1.0 + expected))
            << cell.col << ", " << cell.row;
    }
}

TEST(LikelihoodField, DistancesClampAtMaxDistance) {
    std::mt19937 rng(7);
    const OccupancyGrid grid = random_likelihood_grid(40, 30, 0.05, {0.2, -0.1, 0.4}, 0.01, rng);
    const double max_distance = 0.3;
    expect_field_matches_brute_force(grid, max_distance, "clamped");

    const LikelihoodField field(grid, max_distance);
    int clamped = 0;
    for (const float d : field.distances()) {
        EXPECT_LE(d, static_cast<float>(max_distance));
        clamped += d == static_cast<float>(max_distance) ? 1 : 0;
    }
    EXPECT_GT(clamped, 0) << "the test grid should have cells farther than the clamp";
    EXPECT_DOUBLE_EQ(field.max_distance(), max_distance);
}

TEST(LikelihoodField, AMapWithoutObstaclesIsMaxDistanceEverywhere) {
    testing::GridDrawing drawing(2.0, 1.5, 0.1);
    drawing.cell(3, 4, CellState::Unknown).cell(10, 2, CellState::Unknown);
    const OccupancyGrid grid = drawing.grid({1.0, 2.0, 0.3});
    const LikelihoodField field(grid, 1.5);
    EXPECT_FALSE(field.has_obstacles());
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            EXPECT_DOUBLE_EQ(field.distance_at(GridCell{col, row}), 1.5);
        }
    }
    // Nothing to be near: scoring gives every end point the same, far term.
    const std::vector<Vector2> endpoints{{0.5, 0.1}, {-0.3, 0.4}};
    const LikelihoodFieldParams params;
    EXPECT_NEAR(scan_log_likelihood(field, {1.5, 2.5, 0.2}, endpoints, params, 5.6),
                2.0 * book_term(1.5, 0.1, 0.9, 0.1, 5.6), 1e-9);

    const LikelihoodField empty;
    EXPECT_FALSE(empty.has_obstacles());
    EXPECT_DOUBLE_EQ(empty.distance_at(Vector2(0.0, 0.0)), 2.0);
    EXPECT_TRUE(std::isfinite(scan_log_likelihood(empty, {}, endpoints, params, 5.6)));
}

TEST(LikelihoodField, DistanceAtIsMaxDistanceOutsideTheGrid) {
    // 10 × 6 cells of 0.1 m, yawed origin; the border walls make every inside cell ≤ 0.3 m.
    const Pose2 origin{-0.7, 0.4, 0.9};
    const OccupancyGrid grid = testing::GridDrawing(1.0, 0.6, 0.1).border(0.1).grid(origin);
    const LikelihoodField field(grid, 0.75);
    const auto world = [&](double gx, double gy) { return transform_point(origin, {gx, gy}); };
    for (const Vector2& outside : {world(-0.001, 0.3), world(1.001, 0.3), world(0.5, -0.001),
                                   world(0.5, 0.601), world(-5.0, -5.0), world(30.0, 0.3)}) {
        EXPECT_DOUBLE_EQ(field.distance_at(outside), 0.75) << outside.transpose();
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_DOUBLE_EQ(field.distance_at(Vector2(nan, 0.0)), 0.75);
    EXPECT_DOUBLE_EQ(field.distance_at(GridCell{-1, 0}), 0.75);
    EXPECT_DOUBLE_EQ(field.distance_at(GridCell{10, 0}), 0.75);
    // Just inside, the border wall's own cell, and a cell one step in from it.
    EXPECT_DOUBLE_EQ(field.distance_at(world(0.001, 0.3)), 0.0);
    EXPECT_NEAR(field.distance_at(world(0.15, 0.35)), 0.1, 1e-6);
    EXPECT_NEAR(field.distance_at(world(0.45, 0.25)), 0.2, 1e-6);
    // A point in the grid's frame is not a world point: without the yaw it would be outside.
    EXPECT_DOUBLE_EQ(field.distance_at(Vector2(0.45, 0.25)), 0.75);
}

/// 8 beams, 45° apart from −90°; ranges 0.02 … 4 m.
ScanGeometry eight_beams() {
    ScanGeometry g;
    g.beam_count = 8;
    g.angle_increment = kPi / 4.0;
    g.angle_min = -kPi / 2.0;
    g.range_min = 0.02;
    g.range_max = 4.0;
    return g;
}

LaserScan eight_beam_scan() {
    LaserScan scan;
    scan.beam_count = 8;
    // beam:         0     1             2     3   4    5              6     7
    const std::uint16_t mm[8]{1000, kRangeNoEcho, 2000, 19, 500, kRangeDropout, 4500, 1500};
    for (std::size_t i = 0; i < 8; ++i) {
        scan.range_mm[i] = mm[i];
    }
    return scan;
}

void expect_points(const std::vector<Vector2>& actual, const std::vector<Vector2>& expected) {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(actual[i].x(), expected[i].x(), 1e-12) << i;
        EXPECT_NEAR(actual[i].y(), expected[i].y(), 1e-12) << i;
    }
}

TEST(LikelihoodFieldScan, EndpointsMatchHandWorkedPoints) {
    const ScanGeometry geometry = eight_beams();
    const LaserScan scan = eight_beam_scan();
    // Scanner 0.1 m ahead, 0.05 m right of the robot's centre, turned 90° left: a scanner
    // point (px, py) is (0.1 − py, −0.05 + px) in the robot frame.
    const Pose2 mount{0.1, -0.05, kPi / 2.0};
    const double h = 1.5 * std::sqrt(0.5);  // beam 7: 1.5 m at 225° is (−h, −h)
    // Valid: beam 0 (1 m at −90°), 2 (2 m at 0°), 4 (0.5 m at 90°), 7. Skipped: 1 (no echo),
    // 3 (19: an error code), 5 (dropout), 6 (4.5 m, beyond range_max).
    std::vector<Vector2> out{{9.0, 9.0}};  // cleared first
    scan_endpoints(scan, geometry, mount, 1, out);
    expect_points(out, {{1.1, -0.05}, {0.1, 1.95}, {-0.4, -0.05}, {0.1 + h, -0.05 - h}});

    scan_endpoints(scan, geometry, mount, 0, out);  // a stride below 1 is 1
    expect_points(out, {{1.1, -0.05}, {0.1, 1.95}, {-0.4, -0.05}, {0.1 + h, -0.05 - h}});
    scan_endpoints(scan, geometry, mount, 2, out);  // beams 0, 2, 4, 6
    expect_points(out, {{1.1, -0.05}, {0.1, 1.95}, {-0.4, -0.05}});
    scan_endpoints(scan, geometry, mount, 3, out);  // beams 0, 3, 6
    expect_points(out, {{1.1, -0.05}});
    scan_endpoints(scan, geometry, mount, 7, out);  // beams 0, 7
    expect_points(out, {{1.1, -0.05}, {0.1 + h, -0.05 - h}});

    // Only the scan's own beams count.
    LaserScan shorter = scan;
    shorter.beam_count = 4;
    scan_endpoints(shorter, geometry, mount, 1, out);
    expect_points(out, {{1.1, -0.05}, {0.1, 1.95}});

    // The identity mount gives the scanner's own points, as scan_to_points does.
    std::vector<Vector2> reference;
    scan_to_points(scan, geometry, Pose2{}, reference);
    scan_endpoints(scan, geometry, Pose2{}, 1, out);
    expect_points(out, reference);
}

TEST(LikelihoodFieldScan, EndpointsDoNotReallocate) {
    const ScanGeometry urg;
    const OccupancyGrid room = testing::room_grid();
    LaserScan scan;
    expected_scan(room, {2.0, 2.0, 0.4}, urg, scan);
    std::vector<Vector2> out;
    out.reserve(kMaxScanBeams);
    const Vector2* storage = out.data();
    scan_endpoints(scan, urg, {0.1, 0.0, 0.0}, 1, out);
    EXPECT_GT(out.size(), 600U);
    EXPECT_EQ(out.data(), storage);
    scan_endpoints(scan, urg, {0.1, 0.0, 0.0}, 8, out);
    EXPECT_EQ(out.size(), 86U);  // beams 0, 8, …, 680 all hit a wall of the room
    EXPECT_EQ(out.data(), storage);
}

/// 10 × 8 cells of 0.1 m at the world origin, occupied: (5, 5) (centre (0.55, 0.55)) and
/// (2, 1) (centre (0.25, 0.15)).
OccupancyGrid two_obstacle_grid() {
    return testing::GridDrawing(1.0, 0.8, 0.1)
        .cell(5, 5, CellState::Occupied)
        .cell(2, 1, CellState::Occupied)
        .grid();
}

TEST(LikelihoodFieldScan, LogLikelihoodMatchesAHandCalculation) {
    const LikelihoodField field(two_obstacle_grid(), 0.5);
    // The robot at (0.3, 0.2) facing +y: a robot-frame point (x, y) is (0.3 − y, 0.2 + x).
    const Pose2 pose{0.3, 0.2, kPi / 2.0};
    const std::vector<Vector2> endpoints{
        {0.35, -0.25},   // world (0.55, 0.55): cell (5, 5), the obstacle: d = 0
        {0.05, -0.55},   // world (0.85, 0.25): cell (8, 2), 3 and 3 cells from (5, 5): 0.3√2
        {0.13, 0.03},    // world (0.27, 0.33): cell (2, 3), 2 cells above (2, 1): 0.2
        {0.2, -1.2},     // world (1.5, 0.4): outside the grid: max_distance 0.5
        {-0.13, -0.63},  // world (0.93, 0.07): cell (9, 0), 0.64 from (5, 5): clamped, 0.5
    };
    const std::vector<double> d{0.0, 0.3 * std::sqrt(2.0), 0.2, 0.5, 0.5};
    for (std::size_t i = 0; i < endpoints.size(); ++i) {
        EXPECT_NEAR(field.distance_at(transform_point(pose, endpoints[i])), d[i], 1e-6) << i;
    }
    LikelihoodFieldParams params;
    params.sigma_hit = 0.2;
    params.z_hit = 0.8;
    params.z_random = 0.2;
    const double z_max = 4.0;
    double expected = 0.0;
    for (const double di : d) {
        expected += book_term(di, 0.2, 0.8, 0.2, z_max);
    }
    // Each term by hand: d = 0 gives log(0.8/(√(2π)·0.2) + 0.05) = log(1.645783…).
    EXPECT_NEAR(book_term(0.0, 0.2, 0.8, 0.2, z_max), std::log(1.5957691216057308 + 0.05), 1e-12);
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, params, z_max), expected, 1e-6);

    // The weights are relative: halving both changes nothing; z_max divides the uniform part.
    LikelihoodFieldParams halved = params;
    halved.z_hit = 0.4;
    halved.z_random = 0.1;
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, halved, z_max),
                scan_log_likelihood(field, pose, endpoints, params, z_max), 1e-12);
    double expected_far_scanner = 0.0;
    for (const double di : d) {
        expected_far_scanner += book_term(di, 0.2, 0.8, 0.2, 20.0);
    }
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, params, 20.0), expected_far_scanner,
                1e-6);
    // A sum above 1 is normalised: 0.9 and 0.3 are 0.75 and 0.25.
    LikelihoodFieldParams heavy = params;
    heavy.z_hit = 0.9;
    heavy.z_random = 0.3;
    double expected_heavy = 0.0;
    for (const double di : d) {
        expected_heavy += book_term(di, 0.2, 0.75, 0.25, z_max);
    }
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, heavy, z_max), expected_heavy, 1e-6);

    EXPECT_EQ(scan_log_likelihood(field, pose, {}, params, z_max), 0.0);
}

TEST(LikelihoodFieldScan, LogLikelihoodStaysFiniteWithoutARandomComponent) {
    const LikelihoodField field(two_obstacle_grid(), 0.5);
    const Pose2 pose{0.3, 0.2, kPi / 2.0};
    const std::vector<Vector2> endpoints{{0.35, -0.25}, {0.13, 0.03}, {0.2, -1.2}};
    const std::vector<double> d{0.0, 0.2, 0.5};
    // z_random = 0, σ = 1 mm: 0.5 m is 500 σ away, e^(−125 000) underflows, and the book's
    // formula gives log 0 = −∞. The term is log(z_hit/(√(2π)σ)) − d²/(2σ²) exactly.
    LikelihoodFieldParams params;
    params.sigma_hit = 1e-3;
    params.z_hit = 0.6;  // alone: normalised to 1
    params.z_random = 0.0;
    ASSERT_FALSE(std::isfinite(book_term(0.5, 1e-3, 1.0, 0.0, 4.0)));
    double expected = 0.0;
    for (const double di : d) {
        expected += std::log(1.0 / (std::sqrt(2.0 * kPi) * 1e-3)) - di * di / (2.0 * 1e-6);
    }
    const double actual = scan_log_likelihood(field, pose, endpoints, params, 4.0);
    EXPECT_TRUE(std::isfinite(actual));
    EXPECT_NEAR(actual, expected, 1e-6 * std::abs(expected));

    // A uniform part too small for a product of factors (1e-120 / 4) takes the same path and
    // still agrees with the book where the book's formula is finite.
    params.sigma_hit = 0.2;
    params.z_hit = 1.0;
    params.z_random = 1e-120;
    double expected_tiny = 0.0;
    for (const double di : d) {
        expected_tiny += book_term(di, 0.2, 1.0, 1e-120, 4.0);
    }
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, params, 4.0), expected_tiny, 1e-6);

    // Only the uniform part: every end point scores log(1/z_max) wherever it lies.
    params.z_hit = 0.0;
    params.z_random = 0.3;
    EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, params, 4.0), 3.0 * std::log(0.25),
                1e-12);
}

TEST(LikelihoodFieldScan, ALongScanDoesNotUnderflow) {
    // 1024 end points outside the map, each e^(−…)·… + 0.1/5.6 ≈ 0.0179: their product,
    // 0.0179^1024 ≈ 1e-1790, is far below a double's range; the log of it is not.
    const LikelihoodField field(two_obstacle_grid(), 2.0);
    const std::vector<Vector2> far_away(kMaxScanBeams, Vector2(50.0, 50.0));
    const LikelihoodFieldParams params;
    const double actual = scan_log_likelihood(field, {}, far_away, params, 5.6);
    EXPECT_NEAR(actual, kMaxScanBeams * book_term(2.0, 0.1, 0.9, 0.1, 5.6), 1e-9);
    // … and as many at the obstacle, each factor ≈ 3.6: 3.6^1024 overflows.
    const std::vector<Vector2> at_obstacle(kMaxScanBeams, Vector2(0.55, 0.55));
    EXPECT_NEAR(scan_log_likelihood(field, {}, at_obstacle, params, 5.6),
                kMaxScanBeams * book_term(0.0, 0.1, 0.9, 0.1, 5.6), 1e-9);
}

TEST(LikelihoodFieldScan, LogLikelihoodAgreesWithDistanceAtOnAYawedMap) {
    std::mt19937 rng(11);
    const Pose2 origin{-2.0, 1.0, -0.6};
    const LikelihoodField field(random_likelihood_grid(60, 45, 0.05, origin, 0.02, rng), 1.0);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    std::vector<Vector2> endpoints(200);
    for (Vector2& p : endpoints) {
        p = {coordinate(rng), coordinate(rng)};
    }
    LikelihoodFieldParams params;
    params.sigma_hit = 0.15;
    // Poses about the grid's centre, (−0.13, 1.08) in the world.
    for (const Pose2& pose :
         {Pose2{-0.5, 1.5, 0.3}, Pose2{0.2, 1.2, 2.8}, Pose2{-0.6, 0.7, -1.9}}) {
        double expected = 0.0;
        int inside = 0;
        for (const Vector2& p : endpoints) {
            const Vector2 world = transform_point(pose, p);
            inside += field.grid().cell_of(world) ? 1 : 0;
            expected += book_term(field.distance_at(world), 0.15, 0.9, 0.1, 5.6);
        }
        EXPECT_GT(inside, 60);
        EXPECT_NEAR(scan_log_likelihood(field, pose, endpoints, params, 5.6), expected, 1e-9);
    }
}

TEST(LikelihoodFieldScan, TheTruePoseScoresAboveAPoseThirtyCentimetresOff) {
    // A 4 m × 3 m room with a pillar and a cupboard, its origin turned and moved, so the
    // world and grid frames differ.
    const Pose2 origin{-1.0, 0.5, 0.25};
    const OccupancyGrid room = testing::GridDrawing(4.0, 3.0, 0.05)
                                   .border(0.1)
                                   .rectangle(2.5, 0.8, 2.8, 1.1)
                                   .rectangle(0.1, 2.2, 0.9, 2.9)
                                   .grid(origin);
    const LikelihoodField field(room, 2.0);
    const ScanGeometry urg;
    const Pose2 mount{0.08, 0.02, 0.1};
    const Pose2 truth = compose(origin, Pose2{1.6, 1.4, 0.5});  // 1.6, 1.4 in the room
    LaserScan scan;
    expected_scan(room, compose(truth, mount), urg, scan);
    std::vector<Vector2> endpoints;
    scan_endpoints(scan, urg, mount, 8, endpoints);
    ASSERT_GT(endpoints.size(), 70U);

    // At the true pose every end point lies on a wall: in an occupied cell or a neighbour.
    for (const Vector2& p : endpoints) {
        EXPECT_LE(field.distance_at(transform_point(truth, p)), 0.05 * std::sqrt(2.0) + 1e-6);
    }
    const LikelihoodFieldParams params;
    const double at_truth = scan_log_likelihood(field, truth, endpoints, params, urg.range_max);
    for (int k = 0; k < 8; ++k) {
        const double direction = k * kPi / 4.0;
        const Pose2 off{truth.x + 0.3 * std::cos(direction), truth.y + 0.3 * std::sin(direction),
                        truth.theta};
        const double at_off = scan_log_likelihood(field, off, endpoints, params, urg.range_max);
        // σ_hit = 0.1 m: most end points move ≥ 1σ from their wall, a few nats each.
        EXPECT_GT(at_truth - at_off, 20.0) << "offset towards " << radians_to_degrees(direction)
                                           << "°: " << at_truth << " vs " << at_off;
    }
    const double turned = scan_log_likelihood(field, {truth.x, truth.y, truth.theta + 0.3},
                                              endpoints, params, urg.range_max);
    EXPECT_GT(at_truth - turned, 20.0);
}

}  // namespace
}  // namespace legofeup
