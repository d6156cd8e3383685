// legofeup-cli as a user runs it: exit codes, messages, and what it writes (or not).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::read_file;
using legofeup::testing::Result;

class Cli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }
};

TEST_F(Cli, PrintsItsVersionAndHelp) {
    const Result version = run("--version");
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_EQ(version.out, std::string("legofeup-cli ") + LEGOFEUP_VERSION + "\n");
    const Result help = run("--help");
    EXPECT_EQ(help.exit_code, 0);
    for (const char* word : {"run", "experiments", "config"}) {
        EXPECT_NE(help.out.find(word), std::string::npos) << word;
    }
    const Result run_help = run("run --help");
    EXPECT_NE(run_help.out.find("--experiment"), std::string::npos);
    EXPECT_NE(run_help.out.find("--out"), std::string::npos);
}

TEST_F(Cli, ListsTheExperiments) {
    const Result list = run("experiments");
    EXPECT_EQ(list.exit_code, 0);
    for (const char* line : {"a  Odometry only", "f  Tuned filter"}) {
        EXPECT_NE(list.out.find(line), std::string::npos) << line;
    }
}

TEST_F(Cli, RunWritesTraceSummaryAndPlots) {
    const fs::path out = dir_ / "results";
    const Result result = run("run --experiment f --laps 1 --seed 3 --out " + out.string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;  // no progress bar without a terminal
    EXPECT_NE(result.out.find("Results in " + out.string()), std::string::npos);
    const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
    EXPECT_EQ(summary["experiment"], "f");
    EXPECT_EQ(summary["seed"], 3);
    EXPECT_EQ(summary["config"]["laps"], 1);
    EXPECT_GT(summary["metrics"]["updates_applied"].get<int>(), 100);
    for (const char* plot :
         {"trajectory", "errors", "covariance", "ir_distances", "wheel_speeds"}) {
        const std::string png = read_file(out / (std::string(plot) + ".png"));
        ASSERT_GT(png.size(), 1000u) << plot;
        EXPECT_EQ(png.substr(1, 3), "PNG") << plot;
        EXPECT_NE(read_file(out / (std::string(plot) + ".svg")).find("<svg"), std::string::npos);
    }
    for (const auto& entry : fs::directory_iterator(out)) {
        EXPECT_NE(entry.path().extension(), ".partial") << entry.path();
    }
}

TEST_F(Cli, SameSeedSameTrace) {
    ASSERT_EQ(run("run -e c --laps 1 -s 11 --no-plots -q -o " + (dir_ / "one").string()).exit_code,
              0);
    ASSERT_EQ(run("run -e c --laps 1 -s 11 --no-plots -q -o " + (dir_ / "two").string()).exit_code,
              0);
    ASSERT_EQ(
        run("run -e c --laps 1 -s 12 --no-plots -q -o " + (dir_ / "three").string()).exit_code, 0);
    const std::string one = read_file(dir_ / "one" / "trace.csv");
    EXPECT_GT(one.size(), 10000u);
    EXPECT_EQ(one, read_file(dir_ / "two" / "trace.csv"));
    EXPECT_NE(one, read_file(dir_ / "three" / "trace.csv"));
}

TEST_F(Cli, PrintedConfigurationReproducesTheRun) {
    // `config` prints a TOML file; running from it must give exactly the preset's run.
    const Result config = run("config -e d --seed 21 --laps 1");
    ASSERT_EQ(config.exit_code, 0) << config.err;
    std::ofstream(dir_ / "d.toml") << config.out;
    ASSERT_EQ(run("run --config " + (dir_ / "d.toml").string() + " --no-plots -q -o "
                  + (dir_ / "from_file").string())
                  .exit_code,
              0);
    ASSERT_EQ(
        run("run -e d --seed 21 --laps 1 --no-plots -q -o " + (dir_ / "preset").string()).exit_code,
        0);
    EXPECT_EQ(read_file(dir_ / "from_file" / "trace.csv"),
              read_file(dir_ / "preset" / "trace.csv"));
}

TEST_F(Cli, InvalidConfigurationFailsBeforeWritingAnything) {
    std::ofstream(dir_ / "bad.toml") << "[filter]\nq11 = -1\nr1 = 2\n";
    const fs::path out = dir_ / "never";
    const Result result =
        run("run -e f --config " + (dir_ / "bad.toml").string() + " -o " + out.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(
        result.err.find("bad.toml:3: filter.r1: unknown setting (did you mean 'filter.r11'?)"),
        std::string::npos)
        << result.err;
    EXPECT_FALSE(fs::exists(out));

    std::ofstream(dir_ / "bad_value.toml") << "seed = 4\n[filter]\nq11 = -1\n";
    const Result value =
        run("run -e f --config " + (dir_ / "bad_value.toml").string() + " -o " + out.string());
    EXPECT_EQ(value.exit_code, 1);
    EXPECT_NE(value.err.find("bad_value.toml:3: filter.q11 = -1: must be between 1e-15 and 1e+09"),
              std::string::npos)
        << value.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, FailedRunLeavesEarlierResultsIntact) {
    const fs::path out = dir_ / "results";
    ASSERT_EQ(run("run -e f --laps 1 --no-plots -q -o " + out.string()).exit_code, 0);
    const std::string before = read_file(out / "trace.csv");
    std::ofstream(dir_ / "bad.toml") << "laps = 0\n";
    EXPECT_EQ(
        run("run -e f --config " + (dir_ / "bad.toml").string() + " -o " + out.string()).exit_code,
        1);
    EXPECT_EQ(read_file(out / "trace.csv"), before);
}

TEST_F(Cli, RefusesUnknownExperimentsAndBadOptions) {
    const Result unknown = run("run -e z -o " + (dir_ / "x").string());
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_NE(unknown.err.find(
                  "error: --experiment = z: unknown experiment (choose a … h, or <lesson>:<step>"),
              std::string::npos)
        << unknown.err;
    EXPECT_NE(run("run -e f").exit_code, 0);  // --out is required
    EXPECT_NE(run("run -e f --laps 0 -o " + (dir_ / "x").string()).exit_code, 0);
    EXPECT_NE(run("run -e f --config /no/such/file.toml -o " + (dir_ / "x").string()).exit_code, 0);
    EXPECT_FALSE(fs::exists(dir_ / "x"));
}

TEST_F(Cli, UnwritableOutputIsReportedWithExitCodeTwo) {
    std::ofstream(dir_ / "file") << "in the way";
    const Result result = run("run -e f --laps 1 -o " + (dir_ / "file" / "sub").string());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("cannot create"), std::string::npos) << result.err;
}

}  // namespace
