#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {
namespace {

namespace fs = std::filesystem;

// The problems an InputError carries, as messages.
std::vector<std::string> problem_messages_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        std::vector<std::string> messages;
        for (const InputProblem& problem : error.problems()) {
            messages.push_back(problem.message());
        }
        return messages;
    }
    return {};
}

TEST(ConfigFile, ReadsEverySectionWithUnitsConverted) {
    RunConfig config;
    apply_config_toml(R"(
seed = 42
laps = 3
[filter]
q11 = 2e-7
r22 = 5e-4
wall_updates = false
[initial]
heading_deg = 90
var_theta = 0.01
[control]
routine = "circle"
circle_centre = [0.5, -0.25]
circle_radius = 0.4
heading_tolerance_deg = 5
[robot]
wheel_base = 0.125
[simulator]
ir_noise = 0.02
start_x = -0.9
)",
                      "test.toml", config);
    EXPECT_EQ(config.seed, 42u);
    EXPECT_EQ(config.laps, 3);
    EXPECT_EQ(config.filter.q11, 2e-7);
    EXPECT_EQ(config.filter.r22, 5e-4);
    EXPECT_FALSE(config.filter.wall_updates);
    EXPECT_NEAR(*config.initial_pose.theta, kPi / 2.0, 1e-15);
    EXPECT_FALSE(config.initial_pose.x.has_value());  // not set: the world's start
    EXPECT_EQ(config.initial.var_theta, 0.01);
    EXPECT_EQ(config.routine.kind, RoutineSpec::Kind::Circle);
    EXPECT_EQ(config.routine.circle_centre, Vector2(0.5, -0.25));
    EXPECT_NEAR(config.gains.heading_tolerance, degrees_to_radians(5.0), 1e-15);
    EXPECT_EQ(config.robot.wheel_base, 0.125);
    EXPECT_EQ(config.physical.ir_noise, 0.02);
    EXPECT_EQ(*config.true_start.x, -0.9);
    EXPECT_EQ(config.origins.at("filter.q11").line, 5);
    EXPECT_EQ(config.origins.at("filter.q11").source, "test.toml");
}

TEST(ConfigFile, IntegersAreAcceptedWhereNumbersAreExpected) {
    RunConfig config;
    apply_config_toml("[control]\nv_ref = 1\n", "t.toml", config);
    EXPECT_EQ(config.motion.v_ref, 1.0);
}

TEST(ConfigFile, ReportsEveryProblemWithFileLineKeyAndReason) {
    RunConfig config;
    const RunConfig before = config;
    const auto problems = problem_messages_of([&] {
        apply_config_toml(R"(seed = 1
[filter]
q1 = 1e-7
r11 = "small"
[control]
routine = "spiral"
[camera]
zoom = 2
)",
                          "bad.toml", config);
    });
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_EQ(problems[0], "bad.toml:3: filter.q1: unknown setting (did you mean 'filter.q11'?)");
    EXPECT_EQ(problems[1], "bad.toml:4: filter.r11 = \"small\": must be a number");
    EXPECT_EQ(problems[2],
              "bad.toml:6: control.routine = \"spiral\": must be one of: square, line, circle, "
              "goto, manual, shuttle, piecewise, random, rectangle");
    EXPECT_EQ(problems[3].rfind("bad.toml:7: [camera]: unknown section", 0), 0u) << problems[3];
    // Nothing was applied: the configuration is as it was.
    EXPECT_EQ(config.seed, before.seed);
    EXPECT_EQ(config.filter.q11, before.filter.q11);
}

TEST(ConfigFile, EachSensorsOwnCurveOverridesTheSharedOneInAnyOrder) {
    RunConfig config;
    apply_config_toml("[ir_curve]\nrear_c_m = 2990.5\nc_m = 2900.0\nfront_b = 0.5\n", "c.toml",
                      config);
    const ResolvedRun run = resolve(config);
    EXPECT_EQ(ir_sensor_curve(run.loop, kFrontSensor).c_m, 2900.0);
    EXPECT_EQ(ir_sensor_curve(run.loop, kFrontSensor).b, 0.5);
    EXPECT_EQ(ir_sensor_curve(run.loop, kRearSensor).c_m, 2990.5);
    EXPECT_EQ(ir_sensor_curve(run.loop, kRearSensor).b, 1.0);
    // Without them both sensors read with the shared curve, and the loop has no own one.
    const ResolvedRun plain = resolve(RunConfig{});
    EXPECT_FALSE(plain.loop.ir_sensor_parameters[kFrontSensor].has_value());
    EXPECT_FALSE(plain.loop.ir_sensor_parameters[kRearSensor].has_value());

    RunConfig bad;
    apply_config_toml("seed = 3\n[ir_curve]\nrear_c_m = -1\n", "bad.toml", bad);
    const auto problems = problem_messages_of([&] { resolve(bad); });
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0].rfind("bad.toml:3: ir_curve.rear_c_m = -1: must be greater than 0", 0),
              0u)
        << problems[0];
}

TEST(ConfigFile, SyntaxErrorsPointAtTheirLine) {
    RunConfig config;
    const auto problems = problem_messages_of(
        [&] { apply_config_toml("seed = 1\n[filter\nq11 = 1\n", "broken.toml", config); });
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].rfind("broken.toml:2: ", 0), 0u) << problems[0];
}

TEST(ConfigFile, RefusesNegativeSeedsAndLapsOutOfRange) {
    RunConfig config;
    EXPECT_EQ(
        problem_messages_of([&] { apply_config_toml("seed = -3", "s.toml", config); }).front(),
        "s.toml:1: seed = -3: must not be negative");
    EXPECT_EQ(problem_messages_of([&] { apply_config_toml("laps = 0", "s.toml", config); }).front(),
              "s.toml:1: laps = 0: must be between 1 and 1000");
}

// Found by fuzz_config_file: 2147483648 was cut to an int's −2147483648, which the writer
// then wrote and the reader refused.
TEST(ConfigFile, RefusesWholeNumbersTheirSettingCannotHold) {
    RunConfig config;
    const auto problems = problem_messages_of([&] {
        apply_config_toml("[laser]\nmin_matched_points = 2147483648\n", "big.toml", config);
    });
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0],
              "big.toml:2: laser.min_matched_points = 2147483648: must be at most 2147483647");
    EXPECT_EQ(config.lesson.laser.min_matched_points, LaserTuning{}.min_matched_points);
    // The largest int is taken as it is; the seed, a 64-bit number, takes more.
    apply_config_toml("seed = 4294967296\n[laser]\nmin_matched_points = 2147483647\n", "ok.toml",
                      config);
    EXPECT_EQ(config.lesson.laser.min_matched_points, 2147483647);
    EXPECT_EQ(config.seed, 4294967296u);
}

TEST(ConfigFile, WrittenConfigurationReadsBackToTheSameValues) {
    RunConfig config;
    config.seed = 123456789;
    config.filter.q22 = 3.3e-6;
    config.initial_pose.theta = 0.3;
    config.routine.kind = RoutineSpec::Kind::Goto;
    config.routine.goto_target = {0.25, -0.5, 1.0};
    config.physical.wheel_base_ratio = 1.0312345678901234;
    const std::string text = config_to_toml(config, "round trip");
    RunConfig read;
    apply_config_toml(text, "written.toml", read);
    for (const Setting& setting : run_settings()) {
        if (setting.is_set) {
            EXPECT_EQ(setting.is_set(read), setting.is_set(config)) << setting.key;
        }
        EXPECT_EQ(setting.get(read), setting.get(config)) << setting.key;
    }
}

TEST(ConfigFile, LoadsFilesAndResolvesTheWorldRelativeToThem) {
    const fs::path dir = fs::temp_directory_path() / "legofeup_config_test";
    fs::create_directories(dir);
    { std::ofstream(dir / "run.toml") << "world = \"my_world.toml\"\nlaps = 4\n"; }
    const RunConfig config = load_config_file(dir / "run.toml", RunConfig{});
    EXPECT_EQ(config.laps, 4);
    EXPECT_EQ(fs::path(config.world_file), dir / "my_world.toml");
    const auto missing =
        problem_messages_of([&] { load_config_file(dir / "absent.toml", RunConfig{}); });
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_NE(missing[0].find("cannot open the configuration file"), std::string::npos);
    fs::remove_all(dir);
}

TEST(ConfigSchema, EveryFieldNameMapsBackToOneSetting) {
    for (const Setting& setting : run_settings()) {
        EXPECT_EQ(find_setting_by_key(setting.key), &setting);
        EXPECT_EQ(find_setting_by_field(setting.field), &setting) << setting.field;
        EXPECT_FALSE(setting.help.empty()) << setting.key;
    }
}

TEST(ConfigSchema, FormatsValuesAsTomlReadsThem) {
    EXPECT_EQ(format_setting_value(1e-7), "1e-07");
    EXPECT_EQ(format_setting_value(2.0), "2.0");
    EXPECT_EQ(format_setting_value(std::int64_t{12}), "12");
    EXPECT_EQ(format_setting_value(std::string("a\"b")), "\"a\\\"b\"");
    EXPECT_EQ(format_setting_value(Vector2(0.5, -1.0)), "[0.5, -1.0]");
}

}  // namespace
}  // namespace legofeup::lessons
