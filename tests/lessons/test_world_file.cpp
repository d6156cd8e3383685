#include <gtest/gtest.h>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/world_file.hpp"

namespace legofeup::lessons {
namespace {

TEST(WorldFile, TheShippedStandardArenaIsThePapersArena) {
    // The file (which runs use, built in) and the arena core and sim build from the
    // scenario's numbers must be the same world.
    const sim::WorldSpec file =
        load_world_file(std::string(LEGOFEUP_SOURCE_DIR) + "/resources/worlds/standard_arena.toml");
    const sim::WorldSpec built_in = sim::standard_arena();
    EXPECT_EQ(built_in_world().walls.size(), file.walls.size());
    EXPECT_EQ(built_in_world().name, file.name);
    EXPECT_EQ(file.name, built_in.name);
    EXPECT_EQ(file.start, built_in.start);
    EXPECT_EQ(file.path_side, built_in.path_side);
    EXPECT_EQ(file.path_centre, built_in.path_centre);
    ASSERT_EQ(file.walls.size(), built_in.walls.size());
    for (std::size_t i = 0; i < file.walls.size(); ++i) {
        EXPECT_EQ(file.walls[i].name, built_in.walls[i].name);
        EXPECT_NEAR((file.walls[i].start - built_in.walls[i].start).norm(), 0.0, 1e-12);
        EXPECT_NEAR((file.walls[i].end - built_in.walls[i].end).norm(), 0.0, 1e-12);
    }
}

TEST(WorldFile, ParsesWallsStartAndPath) {
    const sim::WorldSpec world = parse_world(R"(
name = "room"
[start]
x = 0.5
heading_deg = 180
[path]
side = 1.5
centre = [1.0, 2.0]
[[wall]]
name = "north"
from = [0, 3]
to = [2, 3]
)",
                                             "room.toml");
    EXPECT_EQ(world.name, "room");
    EXPECT_EQ(world.start.x, 0.5);
    EXPECT_NEAR(world.start.theta, 3.141592653589793, 1e-15);
    EXPECT_EQ(world.path_side, 1.5);
    ASSERT_EQ(world.walls.size(), 1u);
    EXPECT_EQ(world.walls[0].name, "north");
    EXPECT_EQ(world.walls[0].end, Vector2(2.0, 3.0));
    const auto path = sim::world_square_path(world);
    EXPECT_EQ(std::get<LineSegment>(path[0]).from, Vector2(0.25, 1.25));
}

TEST(WorldFile, ReportsProblemsWithTheirLines) {
    try {
        parse_world(R"(name = "bad"
[[wall]]
from = [0, 0]
[[wall]]
from = [1, 1]
to = [1, 1]
[[wall]]
from = [0, "x"]
to = [1, 0]
colour = "white"
[path]
side = -2
)",
                    "bad.toml");
        FAIL();
    } catch (const InputError& error) {
        std::vector<std::string> messages;
        for (const auto& problem : error.problems()) {
            messages.push_back(problem.message());
        }
        ASSERT_EQ(messages.size(), 5u);
        EXPECT_EQ(messages[0], "bad.toml:2: wall[0]: a wall needs both `from` and `to`");
        EXPECT_EQ(messages[1],
                  "bad.toml:4: wall[1]: `from` and `to` are the same point: a wall needs a length");
        EXPECT_EQ(messages[2].rfind("bad.toml:8: wall[2].from: must be a point", 0), 0u);
        EXPECT_EQ(
            messages[3],
            "bad.toml:10: wall[2].colour = \"white\": unknown key (expected name, from or to)");
        EXPECT_EQ(messages[4],
                  "bad.toml:12: path.side = -2: must be greater than 0 and at most 1000 m");
    }
}

}  // namespace
}  // namespace legofeup::lessons
