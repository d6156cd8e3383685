// The occupancy-grid map as Box2D geometry (sim/src/grid_bodies.hpp): the merge into
// rectangles covers exactly the occupied cells, and rays reflect on the cells' boundaries
// wherever the grid's origin puts them.

#include "grid_bodies.hpp"

#include <gtest/gtest.h>

#include <box2d/box2d.h>

#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "ir_ray.hpp"
#include "legofeup/core/angles.hpp"
#include "map_test_support.hpp"

namespace legofeup::sim {
namespace {

OccupancyGrid grid_from_rows(const std::vector<std::string>& rows_top_first) {
    const auto height = static_cast<int>(rows_top_first.size());
    const auto width = static_cast<int>(rows_top_first.front().size());
    std::vector<CellState> cells;
    for (int row = 0; row < height; ++row) {  // row 0 is the bottom one: the last string
        for (const char c : rows_top_first[static_cast<std::size_t>(height - 1 - row)]) {
            cells.push_back(c == '#' ? CellState::Occupied
                                     : (c == '?' ? CellState::Unknown : CellState::Free));
        }
    }
    return OccupancyGrid(width, height, 0.05, {}, std::move(cells));
}

/// Every occupied cell covered exactly once, every other cell not at all, rectangles inside
/// the grid and sorted by (row, col).
void expect_exact_cover(const OccupancyGrid& grid, const std::vector<CellRectangle>& rectangles) {
    std::vector<int> covered(grid.cells().size(), 0);
    long area = 0;
    for (const CellRectangle& r : rectangles) {
        ASSERT_GE(r.width, 1);
        ASSERT_GE(r.height, 1);
        ASSERT_GE(r.col, 0);
        ASSERT_GE(r.row, 0);
        ASSERT_LE(r.col + r.width, grid.width());
        ASSERT_LE(r.row + r.height, grid.height());
        area += static_cast<long>(r.width) * r.height;
        for (int row = r.row; row < r.row + r.height; ++row) {
            for (int col = r.col; col < r.col + r.width; ++col) {
                ++covered[static_cast<std::size_t>(row * grid.width() + col)];
            }
        }
    }
    long occupied = 0;
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            const bool is_occupied = grid.occupied({col, row});
            occupied += is_occupied ? 1 : 0;
            EXPECT_EQ(covered[static_cast<std::size_t>(row * grid.width() + col)],
                      is_occupied ? 1 : 0)
                << "cell (" << col << ", " << row << ")";
        }
    }
    EXPECT_EQ(area, occupied);  // the area check: the rectangles' cells are the occupied ones
    for (std::size_t i = 1; i < rectangles.size(); ++i) {
        EXPECT_LT(std::tie(rectangles[i - 1].row, rectangles[i - 1].col),
                  std::tie(rectangles[i].row, rectangles[i].col));
    }
}

TEST(GridBodies, AHandWorkedGridMergesIntoItsFourRectangles) {
    const OccupancyGrid grid = grid_from_rows({
        ".##.",  // row 3
        "###?",  // row 2
        "###.",  // row 1
        ".#.#",  // row 0
    });
    const std::vector<CellRectangle> expected{
        {1, 0, 1, 1},  // row 0's two single cells
        {3, 0, 1, 1},
        {0, 1, 3, 2},  // rows 1 and 2 have the same run: one rectangle two rows high
        {1, 3, 2, 1},  // row 3's run differs
    };
    EXPECT_EQ(occupied_rectangles(grid), expected);
    expect_exact_cover(grid, occupied_rectangles(grid));
}

TEST(GridBodies, WallsBecomeOneRectangleEachWayTheyRun) {
    // A room with walls one cell thick: bottom, top, and two side walls (whose rows between
    // the top and bottom ones all have the same runs).
    const auto room = test::room_map(30, 20, 0.05, {});
    EXPECT_EQ(
        occupied_rectangles(*room),
        (std::vector<CellRectangle>{{0, 0, 30, 1}, {0, 1, 1, 18}, {29, 1, 1, 18}, {0, 19, 30, 1}}));
    const auto thick = test::room_map(30, 20, 0.05, {}, 3);
    EXPECT_EQ(occupied_rectangles(*thick).size(), 4U);
    expect_exact_cover(*thick, occupied_rectangles(*thick));

    const OccupancyGrid full(7, 5, 0.1, {}, std::vector<CellState>(35, CellState::Occupied));
    EXPECT_EQ(occupied_rectangles(full), (std::vector<CellRectangle>{{0, 0, 7, 5}}));
    const OccupancyGrid none(7, 5, 0.1, {}, std::vector<CellState>(35, CellState::Unknown));
    EXPECT_TRUE(occupied_rectangles(none).empty());
    EXPECT_TRUE(occupied_rectangles(OccupancyGrid{}).empty());
}

TEST(GridBodies, RandomGridsAreCoveredExactly) {
    std::mt19937_64 random(20240601);
    for (const double density : {0.05, 0.3, 0.6, 0.95}) {
        for (int trial = 0; trial < 10; ++trial) {
            std::uniform_int_distribution<int> size(1, 60);
            const int width = size(random);
            const int height = size(random);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            std::vector<CellState> cells;
            for (int i = 0; i < width * height; ++i) {
                const double u = unit(random);
                cells.push_back(u < density
                                    ? CellState::Occupied
                                    : (u < density + 0.1 ? CellState::Unknown : CellState::Free));
            }
            const OccupancyGrid grid(width, height, 0.05, {}, std::move(cells));
            SCOPED_TRACE(testing::Message() << width << " × " << height << " at " << density);
            expect_exact_cover(grid, occupied_rectangles(grid));
        }
    }
}

TEST(GridBodies, TheBodySitsAtTheOriginAndRaysStopAtTheCellBoundaries) {
    // A room 40 × 30 cells of 0.05 m, walls two cells thick, origin rotated by 0.5 rad.
    const Pose2 origin{1.0, -2.0, 0.5};
    const auto room = test::room_map(40, 30, 0.05, origin, 2);
    const test::RoomInside inside = test::room_inside(40, 30, 0.05, 2);
    b2World world(b2Vec2(0.0f, 0.0f));
    const b2Body* body = build_grid_body(world, *room);
    ASSERT_NE(body, nullptr);
    int fixtures = 0;
    for (const b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext()) {
        ++fixtures;
    }
    EXPECT_EQ(fixtures, 4);

    const double c = std::cos(origin.theta);
    const double s = std::sin(origin.theta);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> gx(inside.x0 + 0.01, inside.x1 - 0.01);
    std::uniform_real_distribution<double> gy(inside.y0 + 0.01, inside.y1 - 0.01);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    for (int i = 0; i < 500; ++i) {
        const double x = gx(random);
        const double y = gy(random);
        const double a = angle(random);  // in the grid frame
        const double expected = test::distance_to_box_side(inside, x, y, a);
        // The same ray in the world: p_w = o + R(yaw)·p_g, direction rotated by yaw.
        const b2Vec2 from(static_cast<float>(origin.x + c * x - s * y),
                          static_cast<float>(origin.y + s * x + c * y));
        const b2Vec2 direction(static_cast<float>(std::cos(a + origin.theta)),
                               static_cast<float>(std::sin(a + origin.theta)));
        const auto hit = closest_hit(world, nullptr, from, direction, 5.0);
        ASSERT_TRUE(hit.has_value()) << i;
        EXPECT_NEAR(*hit, expected, 2e-6) << "ray " << i;  // float geometry: µm
    }
    // Nothing within reach: no hit.
    EXPECT_FALSE(closest_hit(world, nullptr, b2Vec2(1.5f, -1.0f), b2Vec2(1.0f, 0.0f), 0.1));
}

TEST(GridBodies, NoOccupiedCellMeansNoBody) {
    b2World world(b2Vec2(0.0f, 0.0f));
    const OccupancyGrid empty_room(10, 10, 0.05, {}, std::vector<CellState>(100, CellState::Free));
    EXPECT_EQ(build_grid_body(world, empty_room), nullptr);
    EXPECT_EQ(world.GetBodyCount(), 0);
}

}  // namespace
}  // namespace legofeup::sim
