#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "trace_hash_test_support.hpp"

namespace legofeup::lessons {
namespace {

using hash_testing::fnv1a_64;

std::string trace_of(const char* experiment, std::uint64_t seed, RunResult* result = nullptr) {
    RunConfig config = find_experiment(experiment)->config;
    config.seed = seed;
    config.laps = 1;
    const ResolvedRun run = resolve(config);
    std::ostringstream csv;
    TraceCsvWriter writer(csv, run.loop);
    const RunResult r = run_lockstep(run, &writer);
    if (result != nullptr) {
        *result = r;
    }
    return csv.str();
}

TEST(RunOutputs, SameSeedGivesABitIdenticalTrace) {
    const std::string first = trace_of("f", 7);
    const std::string second = trace_of("f", 7);
    EXPECT_EQ(fnv1a_64(first), fnv1a_64(second));
    EXPECT_EQ(first, second);
    EXPECT_NE(fnv1a_64(first), fnv1a_64(trace_of("f", 8)));  // different noise
}

TEST(RunOutputs, TraceHasTheDocumentedColumnsAndOneRowPerStep) {
    RunResult result;
    const std::string csv = trace_of("f", 3, &result);
    std::istringstream lines(csv);
    std::string header;
    std::getline(lines, header);
    EXPECT_EQ(header.rfind("t,x_true,y_true,th_true,x_est,y_est,th_est,pxx,pxy,pxt,pyy,pyt,ptt,"
                           "x_odo,y_odo,th_odo,ds1,ds2,v1,v2,wall,nis,nees",
                           0),
              0u);
    std::size_t rows = 0;
    std::size_t with_wall = 0;
    for (std::string row; std::getline(lines, row);) {
        ++rows;
        EXPECT_EQ(std::count(row.begin(), row.end(), ','),
                  std::count(header.begin(), header.end(), ','));
        with_wall += row.find(",wall_") != std::string::npos ? 1U : 0U;
    }
    EXPECT_EQ(rows, result.metrics.steps);
    EXPECT_EQ(with_wall, result.metrics.updates_applied);
}

TEST(RunOutputs, SummaryHoldsTheFullConfigurationAndTheMetrics) {
    RunConfig config = find_experiment("c")->config;
    config.seed = 99;
    config.laps = 1;
    const ResolvedRun run = resolve(config);
    const RunResult result = run_lockstep(run);
    const nlohmann::json summary = run_summary(run, result, "c", "test");
    EXPECT_EQ(summary["seed"], 99);
    EXPECT_EQ(summary["config"]["seed"], 99);
    EXPECT_EQ(summary["config"]["filter"]["r11"], config.filter.r11);
    EXPECT_EQ(summary["config"]["simulator"]["ir_noise"], 0.01);
    EXPECT_EQ(summary["world"]["walls"].size(), 4u);
    const auto& metrics = summary["metrics"];
    for (const char* key :
         {"rms_position_error_m", "final_position_error_m", "max_position_error_m",
          "rms_heading_error_rad", "final_heading_error_rad", "updates_applied", "updates_rejected",
          "mean_nees", "nees_inside_fraction", "simulated_time_s", "wall_time_s"}) {
        EXPECT_TRUE(metrics.contains(key)) << key;
    }
    EXPECT_EQ(metrics["updates_applied"], result.metrics.updates_applied);
}

TEST(RunOutputs, ResolveNamesEachBadSettingAndWhereItWasSet) {
    RunConfig config = find_experiment("f")->config;
    apply_config_toml("[filter]\nq11 = 1e12\n[control]\nv_ref = 0\n", "mine.toml", config);
    try {
        resolve(config);
        FAIL();
    } catch (const InputError& error) {
        ASSERT_EQ(error.problems().size(), 2u);
        EXPECT_EQ(error.problems()[0].message(),
                  "mine.toml:2: filter.q11 = 1e+12: must be between 1e-15 and 1e+09");
        EXPECT_EQ(error.problems()[1].message(),
                  "mine.toml:4: control.v_ref = 0: must be greater than 0 and at most 2");
    }
}

TEST(RunOutputs, ResolveReportsAnUnusableWorldFile) {
    RunConfig config;
    apply_config_toml("world = \"/nonexistent/world.toml\"\n", "run.toml", config);
    try {
        resolve(config);
        FAIL();
    } catch (const InputError& error) {
        ASSERT_EQ(error.problems().size(), 2u);
        EXPECT_NE(error.problems()[0].message().find("cannot open the world file"),
                  std::string::npos);
        EXPECT_EQ(error.problems()[1].message(),
                  "run.toml:1: world = \"/nonexistent/world.toml\": the world file is unusable");
    }
}

TEST(RunOutputs, TheBeliefAndTheTruthCanStartApart) {
    RunConfig config;
    config.initial_pose.x = -0.9;
    config.true_start.y = -1.05;
    const ResolvedRun run = resolve(config);
    EXPECT_EQ(run.loop.initial.pose, (Pose2{-0.9, -1.0, 0.0}));
    EXPECT_EQ(run.true_start, (Pose2{-1.0, -1.05, 0.0}));
}

}  // namespace
}  // namespace legofeup::lessons
