// The maps that ship in resources/maps (docs/maps.md): the standard arena's map has exactly
// the world file's four walls, and the office has the free lap, features within reach of
// the scanner all along it, door gaps, and two halls that are exact twins (and nothing else
// is). The built-in copies are the files on disk.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/world_file.hpp"

namespace legofeup::lessons {
namespace {

const std::string kMaps = std::string(LEGOFEUP_SOURCE_DIR) + "/resources/maps/";

double distance_to_segment(const Vector2& p, const Vector2& a, const Vector2& b) {
    const Vector2 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * d)).norm();
}

std::vector<Vector2> occupied_centres(const OccupancyGrid& grid) {
    std::vector<Vector2> centres;
    for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
            if (grid.occupied({col, row})) {
                centres.push_back(grid.centre_of({col, row}));
            }
        }
    }
    return centres;
}

TEST(ShippedMaps, TheStandardArenaMapHoldsExactlyTheWorldsFourWalls) {
    const OccupancyGrid grid = load_map_file(kMaps + "standard_arena.yaml");
    EXPECT_EQ(grid.resolution(), 0.01);
    const std::vector<Wall>& walls = built_in_world().walls;
    ASSERT_EQ(walls.size(), 4U);
    const double half_cell = 0.5 * grid.resolution();

    // Every occupied cell's centre lies on a wall (within half a cell)...
    const std::vector<Vector2> centres = occupied_centres(grid);
    for (const Vector2& centre : centres) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Wall& wall : walls) {
            nearest = std::min(nearest, distance_to_segment(centre, wall.start, wall.end));
        }
        EXPECT_LE(nearest, half_cell + 1e-9) << centre.transpose();
    }
    // ... every millimetre of every wall is in an occupied cell ...
    for (const Wall& wall : walls) {
        const double length = (wall.end - wall.start).norm();
        for (double s = 0.0; s <= length; s += 0.001) {
            const Vector2 point = wall.start + (wall.end - wall.start) * (s / length);
            const auto cell = grid.cell_of(point);
            ASSERT_TRUE(cell.has_value()) << wall.name;
            EXPECT_TRUE(grid.occupied(*cell)) << wall.name << " at " << s;
        }
    }
    // ... and each 1 m wall is one line of 1/0.01 + 1 = 101 cells, no more.
    EXPECT_EQ(centres.size(), 4U * 101U);
    // The grid covers the walls with a margin: the arena is ±1.21 m.
    EXPECT_LT(grid.world_min().x(), -1.25);
    EXPECT_GT(grid.world_max().y(), 1.25);
}

// The office's numbers as docs/maps.md gives them.
const Vector2 kLapLow{1.0, 0.8};
const Vector2 kLapHigh{5.0, 3.3};
constexpr double kTwinOffset = 6.0;  // m: the east hall is the west hall moved along +x

std::vector<Vector2> lap_points(double step) {
    const Vector2 corners[] = {
        kLapLow, {kLapHigh.x(), kLapLow.y()}, kLapHigh, {kLapLow.x(), kLapHigh.y()}};
    std::vector<Vector2> points;
    for (int i = 0; i < 4; ++i) {
        const Vector2 a = corners[i];
        const Vector2 b = corners[(i + 1) % 4];
        const int n = static_cast<int>(std::ceil((b - a).norm() / step));
        for (int k = 0; k < n; ++k) {
            points.push_back(a + (b - a) * (static_cast<double>(k) / n));
        }
    }
    return points;
}

TEST(ShippedMaps, TheOfficeIsTwelveByEightMetresAtFiveCentimetres) {
    const OccupancyGrid grid = load_map_file(kMaps + "office.yaml");
    EXPECT_EQ(grid.width(), 240);
    EXPECT_EQ(grid.height(), 160);
    EXPECT_EQ(grid.resolution(), 0.05);
    EXPECT_EQ(grid.origin().x, 0.0);
    EXPECT_EQ(grid.origin().y, 0.0);
    // Closed by its outer walls: every border cell is occupied.
    for (int col = 0; col < grid.width(); ++col) {
        EXPECT_TRUE(grid.occupied({col, 0}));
        EXPECT_TRUE(grid.occupied({col, grid.height() - 1}));
    }
    for (int row = 0; row < grid.height(); ++row) {
        EXPECT_TRUE(grid.occupied({0, row}));
        EXPECT_TRUE(grid.occupied({grid.width() - 1, row}));
    }
}

TEST(ShippedMaps, TheOfficeLapIsFreeWithFeaturesWithinThreeMetresAllAlong) {
    const OccupancyGrid grid = load_map_file(kMaps + "office.yaml");
    const std::vector<Vector2> occupied = occupied_centres(grid);
    constexpr double kClearance = 0.3;  // m: the robot's half length and some tracking error
    for (const Vector2& point : lap_points(0.05)) {
        // Free around the path...
        const auto centre = grid.cell_of(point);
        ASSERT_TRUE(centre.has_value());
        for (int dr = -8; dr <= 8; ++dr) {
            for (int dc = -8; dc <= 8; ++dc) {
                const GridCell cell{centre->col + dc, centre->row + dr};
                if ((grid.centre_of(cell) - point).norm() <= kClearance) {
                    EXPECT_EQ(grid.at(cell), CellState::Free) << point.transpose();
                }
            }
        }
        // ... and something to see within 3 m in at least three directions (not one wall).
        int quadrants = 0;
        for (int q = 0; q < 4; ++q) {
            const bool seen = std::any_of(occupied.begin(), occupied.end(), [&](const Vector2& c) {
                const Vector2 d = c - point;
                const bool in_quadrant =
                    (q == 0 && d.x() > 0 && d.y() >= 0) || (q == 1 && d.x() <= 0 && d.y() > 0)
                    || (q == 2 && d.x() < 0 && d.y() <= 0) || (q == 3 && d.x() >= 0 && d.y() < 0);
                return in_quadrant && d.norm() <= 3.0;
            });
            quadrants += seen ? 1 : 0;
        }
        EXPECT_GE(quadrants, 3) << point.transpose();
    }
}

TEST(ShippedMaps, TheOfficeHallsAreExactTwinsAndNothingElseIs) {
    const OccupancyGrid grid = load_map_file(kMaps + "office.yaml");
    const int shift = static_cast<int>(std::lround(kTwinOffset / grid.resolution()));
    ASSERT_EQ(shift, 120);
    // The halls with their walls and doors: x 0 … 6, y 0 … 4.1 (82 rows).
    int compared = 0;
    for (int row = 0; row < 82; ++row) {
        for (int col = 0; col < shift; ++col) {
            EXPECT_EQ(grid.at({col, row}), grid.at({col + shift, row})) << col << ", " << row;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 120 * 82);
    // The north rooms (y 5.4 … 7.9) are not twins: a kidnapping there is not ambiguous.
    int differing = 0;
    for (int row = 108; row < 158; ++row) {
        for (int col = 0; col < shift; ++col) {
            differing += grid.at({col, row}) != grid.at({col + shift, row}) ? 1 : 0;
        }
    }
    EXPECT_GT(differing, 100);
    // Inside a hall the furniture breaks the room's 180° symmetry (an empty rectangle would
    // look the same turned round): x 0.1 … 5.9 is columns 2 … 117, y 0.1 … 4.0 rows 2 … 79.
    int asymmetric = 0;
    for (int row = 2; row <= 79; ++row) {
        for (int col = 2; col <= 117; ++col) {
            asymmetric += grid.at({col, row}) != grid.at({119 - col, 81 - row}) ? 1 : 0;
        }
    }
    EXPECT_GT(asymmetric, 200);
}

TEST(ShippedMaps, TheOfficeDoorsAreOpen) {
    const OccupancyGrid grid = load_map_file(kMaps + "office.yaml");
    // Door gaps (x from … to, in the wall at y): halls onto the corridor, rooms onto it.
    struct Door {
        double from, to, y;
    };
    for (const Door& door : {Door{4.2, 5.1, 4.025}, Door{10.2, 11.1, 4.075}, Door{1.0, 1.9, 5.325},
                             Door{3.0, 3.9, 5.375}, Door{9.0, 9.9, 5.325}}) {
        for (double x = door.from + 0.025; x < door.to; x += 0.05) {
            EXPECT_EQ(grid.at(*grid.cell_of({x, door.y})), CellState::Free) << x << ", " << door.y;
        }
        // And the wall beside the door is there.
        EXPECT_TRUE(grid.occupied(*grid.cell_of({door.from - 0.025, door.y})));
        EXPECT_TRUE(grid.occupied(*grid.cell_of({door.to + 0.025, door.y})));
    }
}

// The office as built (the simulator's walls, 0.02 m) and as surveyed (the filter's map,
// 0.05 m): the survey recorded what stands at each of its cell centres, and the building's
// faces stand up to 2 cm further out than the survey's cells (never further in).
TEST(ShippedMaps, TheOfficeAsSurveyedIsTheOfficeAsBuiltSeenAtFiveCentimetres) {
    const OccupancyGrid surveyed = load_map_file(kMaps + "office.yaml");
    const OccupancyGrid built = load_map_file(kMaps + "office_as_built.yaml");
    EXPECT_EQ(built.resolution(), 0.02);
    EXPECT_EQ(built.width(), 600);
    EXPECT_EQ(built.height(), 400);
    for (int row = 0; row < surveyed.height(); ++row) {
        for (int col = 0; col < surveyed.width(); ++col) {
            const Vector2 centre = surveyed.centre_of({col, row});
            ASSERT_EQ(built.at(*built.cell_of(centre)), surveyed.at({col, row}))
                << col << ", " << row;
        }
    }
    // Where the two differ, the building is solid and the survey's cell free, within 2 cm
    // (one fine cell) of a cell the survey has occupied.
    int grown = 0;
    for (int row = 0; row < built.height(); ++row) {
        for (int col = 0; col < built.width(); ++col) {
            const Vector2 centre = built.centre_of({col, row});
            const bool surveyed_occupied = surveyed.occupied(*surveyed.cell_of(centre));
            if (built.occupied({col, row}) == surveyed_occupied) {
                continue;
            }
            ++grown;
            EXPECT_TRUE(built.occupied({col, row})) << centre.transpose();
            bool beside_survey = false;
            for (const Vector2& step :
                 {Vector2{0.02, 0}, Vector2{-0.02, 0}, Vector2{0, 0.02}, Vector2{0, -0.02},
                  Vector2{0.02, 0.02}, Vector2{-0.02, 0.02}, Vector2{0.02, -0.02},
                  Vector2{-0.02, -0.02}}) {
                const auto cell = surveyed.cell_of(centre + step);
                beside_survey = beside_survey || (cell && surveyed.occupied(*cell));
            }
            EXPECT_TRUE(beside_survey) << centre.transpose();
        }
    }
    // Many faces moved: thousands of 2 cm cells, not a handful.
    EXPECT_GT(grown, 2000);
}

TEST(ShippedMaps, TheOfficeWorldIsBuiltFromOneMapAndGivesTheFilterTheOther) {
    const sim::WorldSpec* office = find_built_in_world("office");
    ASSERT_NE(office, nullptr);
    EXPECT_EQ(office->map, find_built_in_map("office_as_built"));
    EXPECT_EQ(office->surveyed_map, find_built_in_map("office"));
}

TEST(ShippedMaps, TheBuiltInMapsAreTheFilesOnDisk) {
    for (const std::string& name : built_in_map_names()) {
        SCOPED_TRACE(name);
        const auto built_in = find_built_in_map(name);
        ASSERT_NE(built_in, nullptr);
        const OccupancyGrid file = load_map_file(kMaps + name + ".yaml");
        EXPECT_EQ(built_in->width(), file.width());
        EXPECT_EQ(built_in->height(), file.height());
        EXPECT_EQ(built_in->resolution(), file.resolution());
        EXPECT_EQ(built_in->cells(), file.cells());
        // Read once and shared.
        EXPECT_EQ(find_built_in_map(name), built_in);
        EXPECT_EQ(load_map(name), built_in);
        EXPECT_EQ(find_built_in_map("maps/" + name + ".yaml"), built_in);
    }
    EXPECT_EQ(find_built_in_map("library"), nullptr);
}

}  // namespace
}  // namespace legofeup::lessons
