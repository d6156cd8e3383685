// legofeup-cli montecarlo, sweep and merge as a user runs them: bad options refused with a
// clear message, shards merged to exactly the unsharded output, mismatched shards refused.

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::read_file;
using legofeup::testing::Result;

class AnalysisCli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }
    std::string out(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(AnalysisCli, BadShardOrFactorsExitOneNamingTheOption) {
    const Result shard = run("montecarlo -e f --runs 2 --shard 5/4 -o " + out("x"));
    EXPECT_EQ(shard.exit_code, 1);
    EXPECT_NE(shard.err.find("error: --shard = 5/4: the shard i must be between 1 and n = 4"),
              std::string::npos)
        << shard.err;
    const Result q = run("sweep -e f --runs 1 --q 0.1,x --r 1 -o " + out("y"));
    EXPECT_EQ(q.exit_code, 1);
    EXPECT_NE(q.err.find("error: --q = 0.1,x: \"x\" is not a number"), std::string::npos) << q.err;
    const Result r = run("sweep -e f --runs 1 --q 1 --r 1:10:1 -o " + out("y"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("error: --r = 1:10:1: "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "x" / "summary.json"));
}

TEST_F(AnalysisCli, MonteCarloWritesSummaryTablesAndPlots) {
    const Result result = run("montecarlo -e f --laps 1 --runs 2 --jobs 2 -o " + out("mc"));
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("mean NEES"), std::string::npos);
    EXPECT_NE(result.out.find("2 runs on 2 jobs"), std::string::npos) << result.out;
    const nlohmann::json summary = nlohmann::json::parse(read_file(dir_ / "mc" / "summary.json"));
    EXPECT_EQ(summary["kind"], "montecarlo");
    EXPECT_EQ(summary["runs"], 2);
    EXPECT_EQ(summary["config"]["laps"], 1);
    EXPECT_GT(summary["aggregate"]["mean_nees"].get<double>(), 0.5);
    EXPECT_EQ(read_file(dir_ / "mc" / "steps.csv").rfind("step,time_s,runs,", 0), 0U);
    for (const char* plot : {"nees", "nis", "rms_errors", "final_errors"}) {
        EXPECT_EQ(read_file(dir_ / "mc" / (std::string(plot) + ".png")).substr(1, 3), "PNG");
        EXPECT_NE(read_file(dir_ / "mc" / (std::string(plot) + ".svg")).find("<svg"),
                  std::string::npos);
    }
}

TEST_F(AnalysisCli, MonteCarloShardsMergeToTheUnshardedOutput) {
    const std::string batch = "montecarlo -e f --laps 1 --runs 2 --first-seed 4 --no-plots -q ";
    ASSERT_EQ(run(batch + "--jobs 2 -o " + out("whole")).exit_code, 0);
    for (const char* shard : {"2/2", "1/2"}) {
        const Result part = run(batch + "--jobs 1 --shard " + shard + " -o " + out("shards"));
        ASSERT_EQ(part.exit_code, 0) << part.err;
    }
    const Result merge =
        run("merge --no-plots -o " + out("merged") + " " + out("shards")
            + "/montecarlo-shard-2-of-2.json " + out("shards") + "/montecarlo-shard-1-of-2.json");
    ASSERT_EQ(merge.exit_code, 0) << merge.err;
    EXPECT_NE(merge.out.find("Monte Carlo of experiment f"), std::string::npos);
    for (const char* file : {"summary.json", "steps.csv", "runs.csv"}) {
        const std::string whole = read_file(dir_ / "whole" / file);
        EXPECT_GT(whole.size(), 100U) << file;
        EXPECT_EQ(read_file(dir_ / "merged" / file), whole) << file;
    }
}

TEST_F(AnalysisCli, SweepWritesCellsAndHeatMapsAndItsShardsMerge) {
    const std::string batch = "sweep -e f --laps 1 --runs 1 --q 0.1,10 --r 1 -q ";
    ASSERT_EQ(run(batch + "-o " + out("whole")).exit_code, 0);
    ASSERT_EQ(run(batch + "--no-plots --shard 1/2 -o " + out("shards")).exit_code, 0);
    ASSERT_EQ(run(batch + "--no-plots --shard 2/2 -o " + out("shards")).exit_code, 0);
    const Result merge =
        run("merge -q -o " + out("merged") + " " + out("shards") + "/sweep-shard-1-of-2.json "
            + out("shards") + "/sweep-shard-2-of-2.json");
    ASSERT_EQ(merge.exit_code, 0) << merge.err;
    for (const char* file : {"summary.json", "cells.csv"}) {
        EXPECT_EQ(read_file(dir_ / "merged" / file), read_file(dir_ / "whole" / file)) << file;
    }
    const nlohmann::json summary =
        nlohmann::json::parse(read_file(dir_ / "whole" / "summary.json"));
    ASSERT_EQ(summary["cells"].size(), 2U);
    EXPECT_EQ(summary["cells"][1]["q_scale"], 10.0);
    for (const char* plot : {"sweep_rms_error", "sweep_nees_consistency"}) {
        EXPECT_EQ(read_file(dir_ / "whole" / (std::string(plot) + ".png")).substr(1, 3), "PNG");
        EXPECT_EQ(read_file(dir_ / "merged" / (std::string(plot) + ".png")).substr(1, 3), "PNG");
    }
}

TEST_F(AnalysisCli, MergeRefusesShardsOfDifferentBatchesOrIncomplete) {
    const std::string batch = "montecarlo -e f --laps 1 --no-plots -q --shard ";
    ASSERT_EQ(run(batch + "1/2 --runs 2 -o " + out("a")).exit_code, 0);
    ASSERT_EQ(run(batch + "2/2 --runs 3 -o " + out("b")).exit_code, 0);
    const std::string first = out("a") + "/montecarlo-shard-1-of-2.json";
    const std::string second = out("b") + "/montecarlo-shard-2-of-2.json";
    const Result mismatched = run("merge -o " + out("m") + " " + first + " " + second);
    EXPECT_EQ(mismatched.exit_code, 1);
    EXPECT_NE(
        mismatched.err.find("error: " + second + ": runs = 3: differs from " + first + " (2)"),
        std::string::npos)
        << mismatched.err;
    const Result missing = run("merge -o " + out("m") + " " + first);
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.err.find("error: merge: shard 2/2 is missing"), std::string::npos)
        << missing.err;
    EXPECT_FALSE(fs::exists(dir_ / "m" / "summary.json"));
}

}  // namespace
