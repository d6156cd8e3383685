// The laser lesson's configuration (docs/configuration.md): worlds with an occupancy-grid
// [map] (relative to the world file, errors at their lines), the built-in office world, the
// [laser], [laser_scanner] and [kidnap] sections read and written back, the filter's map
// (the world's, or [laser] map for an outdated one) and the rectangular lap.

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "input_problems_test_support.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/map_file.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/lessons/world_file.hpp"
#include "scratch_dir_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace scratch_testing;

/// A 4 m × 3 m room at 0.5 m per cell (8 × 6 cells) walled all round, origin (−2, −1.5).
void write_room_map(const fs::path& yaml) {
    std::string pgm = "P2\n8 6\n255\n";
    for (int row = 0; row < 6; ++row) {
        for (int col = 0; col < 8; ++col) {
            const bool wall = row == 0 || row == 5 || col == 0 || col == 7;
            pgm += wall ? "0 " : "254 ";
        }
        pgm += '\n';
    }
    write_file(yaml.parent_path() / "room.pgm", pgm);
    write_file(yaml,
               "image: room.pgm\nresolution: 0.5\norigin: [-2.0, -1.5, 0.0]\n"
               "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
}

TEST(WorldMap, AMapIsReadRelativeToTheWorldFile) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "maps" / "room.yaml");
    write_file(dir / "worlds" / "room.toml",
               "name = \"room\"\n[start]\nx = 0.25\ny = 0.25\n[map]\nfile = "
               "\"../maps/room.yaml\"\n");
    const sim::WorldSpec world = load_world_file(dir / "worlds" / "room.toml");
    ASSERT_NE(world.map, nullptr);
    EXPECT_EQ(world.map->width(), 8);
    EXPECT_EQ(world.map->height(), 6);
    EXPECT_EQ(world.map->resolution(), 0.5);
    EXPECT_TRUE(world.walls.empty());
    EXPECT_TRUE(world.map->occupied({0, 0}));
    EXPECT_EQ(world.map->at({3, 2}), CellState::Free);
}

TEST(WorldMap, AnUnusableMapIsReportedInItsFileAndAtTheWorldsLine) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "room.yaml");
    write_file(dir / "bad.yaml",
               "image: room.pgm\nresolution: -2\norigin: [0, 0, 0]\n"
               "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
    write_file(dir / "world.toml", "name = \"w\"\n\n[map]\nfile = \"bad.yaml\"\n");
    const std::vector<InputProblem> problems =
        testing::input_problems_of([&] { load_world_file(dir / "world.toml"); });
    ASSERT_EQ(problems.size(), 2U);
    EXPECT_EQ(problems[0].source, (dir / "bad.yaml").string());
    EXPECT_EQ(problems[0].line, 2);
    EXPECT_EQ(problems[0].key, "resolution");
    EXPECT_EQ(problems[1].source, (dir / "world.toml").string());
    EXPECT_EQ(problems[1].line, 4);
    EXPECT_EQ(problems[1].key, "map.file");
    EXPECT_EQ(problems[1].value, "\"bad.yaml\"");
    EXPECT_EQ(problems[1].reason, "the map file is unusable");

    write_file(dir / "world.toml", "[map]\nfile = \"absent.yaml\"\n");
    const auto absent = testing::input_problems_of([&] { load_world_file(dir / "world.toml"); });
    ASSERT_EQ(absent.size(), 2U);
    EXPECT_NE(absent[0].reason.find("cannot open the map file"), std::string::npos);
    EXPECT_EQ(absent[1].key, "map.file");
}

TEST(WorldMap, ASurveyedMapIsReadBesideTheWorldsMapAndGoesToTheFilter) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "room.yaml");
    write_room_map(dir / "survey" / "room.yaml");
    // The survey placed the room 0.1 m further west than it stands.
    write_file(dir / "survey" / "room.yaml",
               "image: room.pgm\nresolution: 0.5\norigin: [-2.1, -1.5, 0.0]\n"
               "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n");
    write_file(dir / "world.toml",
               "[start]\nx = 0.25\ny = 0.25\n[map]\nfile = \"room.yaml\"\n"
               "surveyed = \"survey/room.yaml\"\n");
    const sim::WorldSpec world = load_world_file(dir / "world.toml");
    ASSERT_NE(world.map, nullptr);
    ASSERT_NE(world.surveyed_map, nullptr);
    EXPECT_NE(world.map, world.surveyed_map);  // two files, two maps
    EXPECT_EQ(world.surveyed_map->cells(), world.map->cells());

    RunConfig config;
    config.world_file = (dir / "world.toml").string();
    config.lesson.localisation = Localisation::Laser;
    EXPECT_EQ(world.map->origin().x, -2.0);
    EXPECT_EQ(world.surveyed_map->origin().x, -2.1);
    EXPECT_EQ(resolve(config).loop.map->origin().x, -2.1);  // the survey, not the world

    // Without file, or with an unusable survey: errors at the world's lines.
    auto problems = testing::input_problems_of(
        [&] { parse_world("[map]\nsurveyed = \"room.yaml\"\n", "w.toml", dir); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].key, "map");
    EXPECT_EQ(problems[0].reason, "needs file = \"<map>.yaml\"");
    problems = testing::input_problems_of([&] {
        parse_world("[map]\nfile = \"room.yaml\"\nsurveyed = \"absent.yaml\"\n", "w.toml", dir);
    });
    ASSERT_EQ(problems.size(), 2U);
    EXPECT_EQ(problems[1].key, "map.surveyed");
    EXPECT_EQ(problems[1].line, 3);
    EXPECT_EQ(problems[1].reason, "the map file is unusable");
}

// A setting edit in the GUI re-resolves with the previous run: the world and map files are
// not read again unless named anew or changed. Told apart by rewriting the world with its old
// stamp (size and time kept): taken from the previous run, its old start stays; stamped anew,
// the file is read again.
TEST(WorldMap, ResolvingAgainReusesTheFilesReadUnlessTheyChanged) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "room.yaml");
    const fs::path world_file = dir / "world.toml";
    write_file(world_file, "[start]\nx = 0.25\ny = 0.25\n[map]\nfile = \"room.yaml\"\n");
    RunConfig config;
    config.world_file = world_file.string();
    config.lesson.localisation = Localisation::Laser;
    const ResolvedRun first = resolve(config);
    EXPECT_EQ(first.world.start.x, 0.25);
    ASSERT_TRUE(first.world_stamp.has_value());

    const auto written = fs::last_write_time(world_file);
    write_file(world_file, "[start]\nx = 0.75\ny = 0.25\n[map]\nfile = \"room.yaml\"\n");
    fs::last_write_time(world_file, written);  // same size, same time: "unchanged"
    RunConfig tuned = config;
    tuned.filter.q11 *= 2.0;
    const ResolvedRun again = resolve(tuned, first);
    EXPECT_EQ(again.world.start.x, 0.25);       // not read again
    EXPECT_EQ(again.loop.map, first.loop.map);  // the same map, not decoded again
    EXPECT_EQ(again.config.filter.q11, tuned.filter.q11);
    EXPECT_EQ(resolve(tuned).world.start.x, 0.75);  // what a fresh read gives

    fs::last_write_time(world_file, written + std::chrono::seconds(2));
    const ResolvedRun changed = resolve(tuned, again);
    EXPECT_EQ(changed.world.start.x, 0.75);  // changed on disk: read again
    EXPECT_NE(changed.loop.map, first.loop.map);

    // Another world named: read, whatever the previous run held.
    RunConfig built_in = tuned;
    built_in.world_file.clear();
    built_in.lesson.localisation = Localisation::Walls;  // the arena has no map to localise in
    EXPECT_EQ(resolve(built_in, changed).world.walls.size(), built_in_world().walls.size());
    // A problem in the new configuration is still found.
    RunConfig broken = tuned;
    broken.filter.r11 = -1.0;
    EXPECT_THROW(resolve(broken, changed), InputError);
}

TEST(WorldMap, MapTablesAndStartPosesAreChecked) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "room.yaml");
    auto problems =
        testing::input_problems_of([&] { parse_world("[map]\nfile = 3\n", "w.toml", dir); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].key, "map.file");
    EXPECT_EQ(problems[0].line, 2);
    problems =
        testing::input_problems_of([&] { parse_world("[map]\nimage = \"x\"\n", "w.toml", dir); });
    ASSERT_EQ(problems.size(), 2U);  // the unknown key, and no file
    EXPECT_EQ(problems[0].key, "map");
    EXPECT_EQ(problems[1].key, "map.image");
    // (−1.8, 0) is in the west wall's column of cells (x −2 … −1.5).
    problems = testing::input_problems_of([&] {
        parse_world("[start]\nx = -1.8\ny = 0.0\n[map]\nfile = \"room.yaml\"\n", "w.toml", dir);
    });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].line, 1);
    EXPECT_EQ(problems[0].key, "start");
    EXPECT_EQ(problems[0].reason, "(-1.8, 0) is in an occupied cell of the map");
}

TEST(WorldMap, TheOfficeIsABuiltInWorldWithItsMap) {
    const std::vector<std::string>& names = built_in_world_names();
    EXPECT_EQ(names, (std::vector<std::string>{"standard_arena", "office", "beacon_field"}));
    const sim::WorldSpec* office = find_built_in_world("office");
    ASSERT_NE(office, nullptr);
    ASSERT_NE(office->map, nullptr);
    EXPECT_EQ(office->map, find_built_in_map("office_as_built"));  // one copy, shared
    EXPECT_EQ(office->surveyed_map, find_built_in_map("office"));
    EXPECT_EQ(office->start, (Pose2{1.0, 0.8, 0.0}));
    EXPECT_EQ(office->path_side, 2.5);
    EXPECT_EQ(office->path_centre, Vector2(2.25, 2.05));
    EXPECT_TRUE(office->walls.empty());
    EXPECT_EQ(find_built_in_world("standard_arena"), &built_in_world());
    EXPECT_EQ(built_in_world().map, nullptr);
    EXPECT_EQ(find_built_in_world("library"), nullptr);
    // The file on disk is the same world.
    const sim::WorldSpec file =
        load_world_file(std::string(LEGOFEUP_SOURCE_DIR) + "/resources/worlds/office.toml");
    ASSERT_NE(file.map, nullptr);
    EXPECT_EQ(file.map->cells(), office->map->cells());
    ASSERT_NE(file.surveyed_map, nullptr);
    EXPECT_EQ(file.surveyed_map->cells(), office->surveyed_map->cells());
    EXPECT_EQ(file.name, office->name);
    EXPECT_EQ(load_world("office").map, office->map);
}

// --- Settings --------------------------------------------------------------------------------

TEST(LaserSettings, EverySectionIsReadWithUnitsConverted) {
    RunConfig config;
    apply_config_toml(R"(
[localisation]
method = "laser"

[laser]
q_x_static = 0.001
q_theta_dynamic = 0.002
r_theta = 0.02
icp_metric = "point_to_point"
icp_max_iterations = 30
icp_max_correspondence_distance = 0.5
icp_trim_fraction = 0.2
icp_translation_epsilon = 1e-4
icp_rotation_epsilon = 2e-4
min_matched_points = 50
kidnap_recovery = false
recovery_after_mismatches = 20
recovery_covariance_factor = 5.0
recovery_correspondence_factor = 0.25
mount_x = 0.05
mount_y = -0.01
mount_heading_deg = 90.0
beam_count = 361
angle_min_deg = -90.0
angle_increment_deg = 0.5
range_min = 0.05
range_max = 4.0
map = "office"

[laser_scanner]
enabled = true
beam_count = 361
angle_min_deg = -90
mount_heading_deg = 180
scan_period = 0.2
sigma_near = 0.02
noise_knee = 2.0
sigma_relative = 0.02
dropout_probability = 0.05

[kidnap]
enabled = true
time = 30.5
x = 7.0
y = 0.8
heading_deg = -90
)",
                      "laser.toml", config);
    const LaserTuning& laser = config.lesson.laser;
    EXPECT_EQ(config.lesson.localisation, Localisation::Laser);
    EXPECT_EQ(laser.q_x_static, 0.001);
    EXPECT_EQ(laser.q_theta_dynamic, 0.002);
    EXPECT_EQ(laser.r_theta, 0.02);
    EXPECT_EQ(laser.icp.metric, IcpMetric::PointToPoint);
    EXPECT_EQ(laser.icp.max_iterations, 30);
    EXPECT_EQ(laser.icp.max_correspondence_distance, 0.5);
    EXPECT_EQ(laser.icp.trim_fraction, 0.2);
    EXPECT_EQ(laser.icp.translation_epsilon, 1e-4);
    EXPECT_EQ(laser.icp.rotation_epsilon, 2e-4);
    EXPECT_EQ(laser.min_matched_points, 50);
    EXPECT_FALSE(laser.kidnap_recovery);
    EXPECT_EQ(laser.recovery_after_mismatches, 20);
    EXPECT_EQ(laser.recovery_covariance_factor, 5.0);
    EXPECT_EQ(laser.recovery_correspondence_factor, 0.25);
    EXPECT_EQ(laser.mount.x, 0.05);
    EXPECT_EQ(laser.mount.y, -0.01);
    EXPECT_DOUBLE_EQ(laser.mount.theta, kPi / 2.0);
    EXPECT_EQ(laser.geometry.beam_count, 361);
    EXPECT_DOUBLE_EQ(laser.geometry.angle_min, -kPi / 2.0);
    EXPECT_DOUBLE_EQ(laser.geometry.angle_increment, kPi / 360.0);
    EXPECT_EQ(laser.geometry.range_min, 0.05);
    EXPECT_EQ(laser.geometry.range_max, 4.0);
    EXPECT_EQ(config.laser_map_file, "office");  // a built-in name stays as written

    const sim::LaserScannerSpec& scanner = config.physical.laser_scanner;
    EXPECT_TRUE(scanner.enabled);
    EXPECT_EQ(scanner.geometry.beam_count, 361);
    EXPECT_DOUBLE_EQ(scanner.geometry.angle_min, -kPi / 2.0);
    EXPECT_EQ(scanner.geometry.angle_increment, ScanGeometry{}.angle_increment);  // not given
    EXPECT_DOUBLE_EQ(scanner.mount.theta, kPi);
    EXPECT_EQ(scanner.scan_period, 0.2);
    EXPECT_EQ(scanner.sigma_near, 0.02);
    EXPECT_EQ(scanner.noise_knee, 2.0);
    EXPECT_EQ(scanner.sigma_relative, 0.02);
    EXPECT_EQ(scanner.dropout_probability, 0.05);

    const auto& kidnap = config.simulator.kidnap;
    EXPECT_TRUE(kidnap.enabled);
    EXPECT_EQ(kidnap.time, 30.5);
    EXPECT_EQ(kidnap.pose.x, 7.0);
    EXPECT_EQ(kidnap.pose.y, 0.8);
    EXPECT_DOUBLE_EQ(kidnap.pose.theta, -kPi / 2.0);
    // Where it was written: the line of "heading_deg = -90" in [kidnap].
    EXPECT_EQ(config.origins.at("simulator.kidnap.pose.theta").key, "kidnap.heading_deg");
    EXPECT_EQ(config.origins.at("simulator.kidnap.pose.theta").source, "laser.toml");
}

TEST(LaserSettings, TheDefaultsAreTheCoresAndTheSimulatorsOwn) {
    // Reading a written default configuration changes nothing, and the URG-04LX geometry's
    // angles (in degrees in files) come back bit for bit.
    const RunConfig defaults;
    RunConfig read;
    apply_config_toml(config_to_toml(defaults, "defaults"), "defaults.toml", read);
    EXPECT_EQ(read.lesson.laser.geometry, ScanGeometry{});
    EXPECT_EQ(read.lesson.laser.icp, IcpParams{});
    EXPECT_EQ(read.physical.laser_scanner.geometry, ScanGeometry{});
    EXPECT_EQ(read.lesson.laser.q_x_dynamic, LaserTuning{}.q_x_dynamic);
    EXPECT_EQ(read.simulator.kidnap.enabled, false);
    EXPECT_EQ(read.laser_map_file, "");
}

TEST(LaserSettings, WrittenNonDefaultValuesReadBackToTheSameValues) {
    RunConfig config;
    config.lesson.localisation = Localisation::Laser;
    config.lesson.laser.r_x = 0.0123;
    config.lesson.laser.icp.metric = IcpMetric::PointToPoint;
    config.lesson.laser.icp.max_iterations = 17;
    config.lesson.laser.min_matched_points = 42;
    config.lesson.laser.kidnap_recovery = false;
    config.lesson.laser.mount = {0.1, 0.02, 0.3};
    config.lesson.laser.geometry.angle_min = -1.2345678901234567;
    config.laser_map_file = "/somewhere/old.yaml";
    config.physical.laser_scanner.enabled = true;
    config.physical.laser_scanner.dropout_probability = 0.125;
    config.physical.laser_scanner.geometry.beam_count = 100;
    config.simulator.kidnap = {true, 12.5, {3.0, -2.0, 1.0}};
    config.routine.kind = RoutineSpec::Kind::Rectangle;
    config.routine.rectangle_corner = {1.0, 0.8};
    config.routine.rectangle_size = {4.0, 2.5};
    const std::string text = config_to_toml(config, "round trip");
    EXPECT_NE(text.find("\n[laser]\n"), std::string::npos);
    EXPECT_NE(text.find("\n[laser_scanner]\n"), std::string::npos);
    EXPECT_NE(text.find("\n[kidnap]\n"), std::string::npos);
    EXPECT_NE(text.find("method = \"laser\""), std::string::npos);
    RunConfig read;
    apply_config_toml(text, "written.toml", read);
    int laser_settings = 0;
    for (const Setting& setting : run_settings()) {
        EXPECT_EQ(setting.get(read), setting.get(config)) << setting.key;
        const std::string section = setting.section();
        laser_settings += section == "laser" || section == "laser_scanner" || section == "kidnap";
    }
    // [laser]: 9 noise + 6 ICP + 5 gating/recovery + 8 geometry and mount + map; [laser_scanner]:
    // enabled + 8 geometry and mount + 5 noise; [kidnap]: 5.
    EXPECT_EQ(laser_settings, 29 + 14 + 5);
    EXPECT_EQ(read.lesson.laser.geometry.angle_min, config.lesson.laser.geometry.angle_min);
    EXPECT_EQ(read.routine.kind, RoutineSpec::Kind::Rectangle);
}

TEST(LaserSettings, BadValuesAreReportedWithFileLineAndKey) {
    RunConfig config;
    const auto problems = testing::input_problems_of([&] {
        apply_config_toml(
            "[laser]\nicp_metric = \"nearest\"\nbeam_count = -3\n"
            "mount_heading_deg = \"left\"\n[kidnap]\nheading_dg = 3\n",
            "bad.toml", config);
    });
    ASSERT_EQ(problems.size(), 4U);
    EXPECT_EQ(problems[0].message(),
              "bad.toml:2: laser.icp_metric = \"nearest\": must be one of: point_to_point, "
              "point_to_line");
    EXPECT_EQ(problems[1].message(), "bad.toml:3: laser.beam_count = -3: must not be negative");
    EXPECT_EQ(problems[2].line, 4);
    EXPECT_EQ(problems[2].reason, "must be a number");
    EXPECT_EQ(
        problems[3].message(),
        "bad.toml:6: kidnap.heading_dg: unknown setting (did you mean 'kidnap.heading_deg'?)");
}

TEST(LaserSettings, ValidationProblemsPointAtTheSettingsLine) {
    const fs::path dir = temp_dir();
    write_file(dir / "run.toml",
               "world = \"office\"\n[localisation]\nmethod = \"laser\"\n[laser]\n"
               "icp_trim_fraction = 0.95\nq_x_static = -1\n");
    const auto problems =
        testing::input_problems_of([&] { resolve(load_config_file(dir / "run.toml", {})); });
    ASSERT_EQ(problems.size(), 2U);
    EXPECT_EQ(problems[0].line, 5);
    EXPECT_EQ(problems[0].key, "laser.icp_trim_fraction");
    EXPECT_EQ(problems[1].line, 6);
    EXPECT_EQ(problems[1].key, "laser.q_x_static");
}

// --- The filter's map -------------------------------------------------------------------------

TEST(LaserMap, TheFilterUsesTheWorldsSurveyedMapUnlessTheLaserSectionNamesAnother) {
    RunConfig config;
    config.world_file = "office";
    config.lesson.localisation = Localisation::Laser;
    const ResolvedRun run = resolve(config);
    ASSERT_NE(run.world.map, nullptr);
    ASSERT_NE(run.world.surveyed_map, nullptr);
    EXPECT_EQ(run.loop.map, run.world.surveyed_map);  // not the office as built
    EXPECT_EQ(run.world.name, "Office floor");
    EXPECT_EQ(run.loop.initial.pose, (Pose2{1.0, 0.8, 0.0}));

    // An outdated map: the world stays the office, the filter believes the arena's map.
    config.laser_map_file = "standard_arena";
    const ResolvedRun outdated = resolve(config);
    EXPECT_EQ(outdated.world.map, run.world.map);
    EXPECT_EQ(outdated.loop.map, find_built_in_map("standard_arena"));
}

TEST(LaserMap, ALaserMapFileIsReadRelativeToTheConfiguration) {
    const fs::path dir = temp_dir();
    write_room_map(dir / "maps" / "room.yaml");
    write_file(dir / "run.toml", "world = \"office\"\n[laser]\nmap = \"maps/room.yaml\"\n");
    const RunConfig config = load_config_file(dir / "run.toml", {});
    EXPECT_EQ(fs::path(config.laser_map_file), dir / "maps" / "room.yaml");
    const ResolvedRun run = resolve(config);
    ASSERT_NE(run.loop.map, nullptr);
    EXPECT_EQ(run.loop.map->width(), 8);

    // A map that cannot be read: its own problem, then the configuration's line.
    write_file(dir / "run.toml", "world = \"office\"\n\n[laser]\nmap = \"maps/none.yaml\"\n");
    const auto problems =
        testing::input_problems_of([&] { resolve(load_config_file(dir / "run.toml", {})); });
    ASSERT_EQ(problems.size(), 2U);
    EXPECT_NE(problems[0].reason.find("cannot open the map file"), std::string::npos);
    EXPECT_EQ(problems[1].source, (dir / "run.toml").string());
    EXPECT_EQ(problems[1].line, 4);
    EXPECT_EQ(problems[1].key, "laser.map");
    EXPECT_EQ(problems[1].reason, "the map file is unusable");
}

TEST(LaserMap, LaserLocalisationWithoutAMapIsRefusedAtItsSetting) {
    RunConfig config;
    apply_config_toml("[localisation]\nmethod = \"laser\"\n", "nomap.toml", config);
    const auto problems = testing::input_problems_of([&] { resolve(config); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].key, "laser.map");
    EXPECT_NE(problems[0].reason.find("map"), std::string::npos);
}

TEST(LaserMap, TheFiltersBeamCountMustBeTheSimulatedScanners) {
    RunConfig config;
    config.world_file = "office";
    config.lesson.localisation = Localisation::Laser;
    config.physical.laser_scanner.enabled = true;
    config.lesson.laser.geometry.beam_count = 600;
    config.lesson.laser.geometry.angle_min = -1.5;
    const auto problems = testing::input_problems_of([&] { resolve(config); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].key, "laser.beam_count");
    EXPECT_EQ(problems[0].reason,
              "must equal the simulated scanner's laser_scanner.beam_count (682)");
}

// --- The rectangular lap ----------------------------------------------------------------------

TEST(RectangleRoutine, DrivesTheRectangleCounterClockwiseFromItsCorner) {
    RunConfig config;
    config.world_file = "office";
    config.laps = 2;
    config.routine.kind = RoutineSpec::Kind::Rectangle;
    config.routine.rectangle_corner = {1.0, 0.8};
    config.routine.rectangle_size = {4.0, 2.5};
    const ResolvedRun run = resolve(config);
    const auto* path = std::get_if<FollowPath>(&run.loop.controller);
    ASSERT_NE(path, nullptr);
    EXPECT_EQ(path->laps(), 2);
    const std::vector<Vector2> corners = {{1.0, 0.8}, {5.0, 0.8}, {5.0, 3.3}, {1.0, 3.3}};
    ASSERT_EQ(path->segments().size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& line = std::get<LineSegment>(path->segments()[i]);
        EXPECT_EQ(line.from, corners[i]) << i;
        EXPECT_EQ(line.to, corners[(i + 1) % 4]) << i;
    }
    // A 13 m lap gets 13/8 of the standard 8 m square's 200 s.
    EXPECT_DOUBLE_EQ(run.max_duration, 2 * 200.0 * 13.0 / 8.0);
    // A duration ends a lapped run sooner, never later.
    config.duration = 60.0;
    EXPECT_DOUBLE_EQ(resolve(config).max_duration, 60.0);
    config.duration = 5000.0;
    EXPECT_DOUBLE_EQ(resolve(config).max_duration, 2 * 200.0 * 13.0 / 8.0);
    config.duration = 0.0;

    config.routine.rectangle_size = {0.0, 2.5};
    const auto problems = testing::input_problems_of([&] { resolve(config); });
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].key, "control.rectangle_size");
}

}  // namespace
}  // namespace legofeup::lessons
