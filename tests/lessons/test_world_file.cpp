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
    ASSERT_EQ(file.beacons.size(), 4u);
    ASSERT_EQ(file.beacons.size(), built_in.beacons.size());
    for (std::size_t i = 0; i < file.beacons.size(); ++i) {
        EXPECT_EQ(file.beacons[i].id, built_in.beacons[i].id);
        EXPECT_EQ(file.beacons[i].id, static_cast<int>(i) + 1);
        EXPECT_NEAR((file.beacons[i].position - built_in.beacons[i].position).norm(), 0.0, 1e-12);
        // 0.1 m inside a corner of the walls' bounding box (±1.21 m).
        EXPECT_NEAR(file.beacons[i].position.cwiseAbs().maxCoeff(), 1.11, 1e-12);
        EXPECT_NEAR(file.beacons[i].position.cwiseAbs().minCoeff(), 1.11, 1e-12);
    }
    EXPECT_EQ(file.magnetic.amplitude_deg, built_in.magnetic.amplitude_deg);
    EXPECT_EQ(file.magnetic.amplitude_deg, 12.0);
    EXPECT_EQ(file.magnetic.wavelength, built_in.magnetic.wavelength);
    EXPECT_EQ(built_in_world().beacons.size(), 4u);
    EXPECT_EQ(built_in_world().magnetic.amplitude_deg, 12.0);
}

// The beacon lesson's world: the standard arena's path, start, beacons and magnetic field,
// with every wall moved from 1.21 m to 1.6 m from the centre (so a robot lost after a
// displacement does not get pinned against one).
TEST(WorldFile, TheBeaconFieldIsTheStandardArenaWithItsWallsMovedOut) {
    const sim::WorldSpec* field = find_built_in_world("beacon_field");
    ASSERT_NE(field, nullptr);
    const sim::WorldSpec& arena = built_in_world();
    EXPECT_EQ(field->start, arena.start);
    EXPECT_EQ(field->path_side, arena.path_side);
    EXPECT_EQ(field->path_centre, arena.path_centre);
    ASSERT_EQ(field->beacons.size(), arena.beacons.size());
    for (std::size_t i = 0; i < arena.beacons.size(); ++i) {
        EXPECT_EQ(field->beacons[i].id, arena.beacons[i].id);
        EXPECT_EQ(field->beacons[i].position, arena.beacons[i].position);
    }
    EXPECT_EQ(field->magnetic.amplitude_deg, arena.magnetic.amplitude_deg);
    ASSERT_EQ(field->walls.size(), arena.walls.size());
    for (std::size_t i = 0; i < arena.walls.size(); ++i) {
        const Wall& moved = field->walls[i];
        const Wall& original = arena.walls[i];
        EXPECT_EQ(moved.name, original.name);
        EXPECT_NEAR(moved.start.cwiseAbs().maxCoeff(), 1.6, 1e-12) << moved.name;
        EXPECT_NEAR(moved.end.cwiseAbs().maxCoeff(), 1.6, 1e-12) << moved.name;
        EXPECT_NEAR((moved.end - moved.start).norm(), (original.end - original.start).norm(), 1e-12)
            << moved.name;
    }
}

TEST(WorldFile, ParsesBeaconsAndTheMagneticDisturbance) {
    const sim::WorldSpec world = parse_world(R"(
[[wall]]
from = [-2, -1]
to = [2, 1]
[[beacon]]
id = 7
x = 1.5
y = -0.25
[[beacon]]
id = 0
x = -2
y = 1
[magnetic]
amplitude_deg = 8.5
wavelength = 2
)",
                                             "beacons.toml");
    ASSERT_EQ(world.beacons.size(), 2u);
    EXPECT_EQ(world.beacons[0].id, 7);
    EXPECT_EQ(world.beacons[0].position, Vector2(1.5, -0.25));
    EXPECT_EQ(world.beacons[1].id, 0);
    EXPECT_EQ(world.beacons[1].position, Vector2(-2.0, 1.0));  // on the bounding box: inside
    EXPECT_EQ(world.magnetic.amplitude_deg, 8.5);
    EXPECT_EQ(world.magnetic.wavelength, 2.0);

    const sim::WorldSpec plain = parse_world("name = \"plain\"\n", "plain.toml");
    EXPECT_TRUE(plain.beacons.empty());
    EXPECT_EQ(plain.magnetic.amplitude_deg, 0.0);
}

TEST(WorldFile, ReportsBeaconAndMagneticProblemsWithTheirLines) {
    try {
        parse_world(R"([[wall]]
from = [-1, -1]
to = [1, 1]
[[beacon]]
id = 3
x = 0
y = 0
[[beacon]]
id = 3
x = 0.5
y = 0.5
[[beacon]]
id = 256
x = 0
y = 0
[[beacon]]
id = 1.5
x = 0
y = 0
colour = "red"
[[beacon]]
id = 4
x = 1.5
y = 0
[[beacon]]
id = 5
x = 0
[magnetic]
amplitude_deg = -3
wavelength = 0
)",
                    "bad.toml");
        FAIL();
    } catch (const InputError& error) {
        std::vector<std::string> messages;
        for (const auto& problem : error.problems()) {
            messages.push_back(problem.message());
        }
        ASSERT_EQ(messages.size(), 8u);
        EXPECT_EQ(
            messages[0],
            "bad.toml:9: beacon[1].id = 3: beacon[0] already has this id: ids must be unique");
        EXPECT_EQ(messages[1],
                  "bad.toml:13: beacon[2].id = 256: must be a whole number from 0 to 255");
        EXPECT_EQ(messages[2],
                  "bad.toml:17: beacon[3].id = 1.5: must be a whole number from 0 to 255");
        EXPECT_EQ(messages[3],
                  "bad.toml:20: beacon[3].colour = \"red\": unknown key (expected id, x or y)");
        EXPECT_EQ(messages[4],
                  "bad.toml:21: beacon[4]: (1.5, 0) is outside the walls' bounding box x -1 to 1, "
                  "y -1 to 1");
        EXPECT_EQ(messages[5], "bad.toml:25: beacon[5]: a beacon needs `id`, `x` and `y`");
        EXPECT_EQ(messages[6],
                  "bad.toml:29: magnetic.amplitude_deg = -3: must be between 0 and 180 degrees");
        EXPECT_EQ(messages[7],
                  "bad.toml:30: magnetic.wavelength = 0: must be greater than 0 and at most 1e6 m");
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
