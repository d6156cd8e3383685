// `legofeup-cli run --record` and `legofeup-cli refilter` as a user runs them: a recorded run
// re-filtered with a new R, a broken log reported at file:line, and a run killed mid-way
// (its log cut off) still re-filtered.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

using legofeup::testing::read_file;
using legofeup::testing::Result;

// Experiment f's filter on a short drive past the first wall (about 300 steps): quick under
// the sanitizers, with wall updates all along.
constexpr const char* kShortDrive = R"(duration = 20.0
[control]
routine = "line"
line_from = [-1.0, -1.0]
line_to = [0.2, -1.0]
)";

// Trust the IR sensors a hundred times less.
constexpr const char* kLessTrust = R"(# what if R were larger?
[filter]
r11 = 0.01
r22 = 0.01
)";

class RefilterCli : public legofeup::testing::ProgramTest {
  protected:
    Result cli(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }

    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(dir_ / name, std::ios::binary) << text;
        return dir_ / name;
    }

    /// Records the short drive of experiment f; returns the log's path.
    fs::path record(const std::string& name = "run.log") const {
        const fs::path config = write("short.toml", kShortDrive);
        const Result run = cli("run -e f --seed 4 --no-plots -q -c " + config.string() + " -o "
                               + (dir_ / "run").string() + " --record " + (dir_ / name).string());
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return dir_ / name;
    }

    static std::size_t line_count(const std::string& text) {
        return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    }
};

TEST_F(RefilterCli, ARecordedRunRefilteredWithANewRComparesRecordedAndNew) {
    const fs::path log = record();
    const fs::path less_trust = write("less_trust.toml", kLessTrust);
    const fs::path out = dir_ / "refilter";
    const Result refilter = cli("refilter --log " + log.string() + " --config "
                                + less_trust.string() + " --out " + out.string());
    ASSERT_EQ(refilter.exit_code, 0) << refilter.err;
    EXPECT_TRUE(refilter.err.empty()) << refilter.err;
    EXPECT_NE(refilter.out.find("changed: filter.r11 = 0.01"), std::string::npos) << refilter.out;
    EXPECT_NE(refilter.out.find("reproduces the run exactly"), std::string::npos);
    EXPECT_NE(refilter.out.find("RMS position error (m)"), std::string::npos);

    // The recorded replay's metrics are the run's own, exactly; the new ones differ.
    const nlohmann::json run = nlohmann::json::parse(read_file(dir_ / "run" / "summary.json"));
    const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
    EXPECT_EQ(summary["recorded_replay_reproduces_run"], true);
    EXPECT_EQ(summary["metrics"]["recorded"]["rms_position_error_m"],
              run["metrics"]["rms_position_error_m"]);
    EXPECT_EQ(summary["metrics"]["recorded"]["mean_nis"], run["metrics"]["mean_nis"]);
    EXPECT_NE(summary["metrics"]["new"]["mean_nis"], run["metrics"]["mean_nis"]);
    EXPECT_EQ(summary["changed_settings"].size(), 2U);
    EXPECT_EQ(summary["log_ended"], true);

    // One row per step; the recorded estimate equals the run's trace, the new one does not.
    const std::string csv = read_file(out / "refilter.csv");
    EXPECT_EQ(csv.rfind("t,frame_missing,x_true,y_true,th_true,x_old,", 0), 0U);
    EXPECT_EQ(line_count(csv), line_count(read_file(dir_ / "run" / "trace.csv")));
    EXPECT_EQ(summary["steps"].get<std::size_t>() + 1, line_count(csv));
    for (const char* plot : {"refilter_trajectory", "refilter_errors"}) {
        EXPECT_GT(read_file(out / (std::string(plot) + ".png")).size(), 1000U) << plot;
        EXPECT_NE(read_file(out / (std::string(plot) + ".svg")).find("<svg"), std::string::npos);
    }
}

TEST_F(RefilterCli, ABrokenLogOrConfigurationIsExit1AtFileLine) {
    const fs::path log = record();
    std::string text = read_file(log);
    // The 3rd record: its encoder cell becomes a word.
    std::size_t line_start = text.find("\ncolumns: ");
    int line_number = 1
                      + static_cast<int>(std::count(
                          text.begin(), text.begin() + static_cast<long>(line_start), '\n'))
                      + 1;
    for (int i = 0; i < 3; ++i) {
        line_start = text.find('\n', line_start + 1);
        ++line_number;
    }
    std::size_t cell = line_start + 1;
    for (int i = 0; i < 4; ++i) {
        cell = text.find(',', cell) + 1;
    }
    text.replace(cell, text.find(',', cell) - cell, "many");
    const fs::path broken = write("broken.log", text);
    const Result bad = cli("refilter --log " + broken.string());
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_EQ(bad.err, "error: " + broken.string() + ":" + std::to_string(line_number)
                           + ": encoder_right = many: not a valid number\n");
    EXPECT_TRUE(bad.out.empty());

    const Result not_a_log = cli("refilter --log " + (dir_ / "run" / "trace.csv").string());
    EXPECT_EQ(not_a_log.exit_code, 1);
    EXPECT_NE(not_a_log.err.find("trace.csv:1: not a LegoFeup run log"), std::string::npos)
        << not_a_log.err;

    const fs::path typo = write("typo.toml", "[filter]\nr11 = 0.01\nr33 = 0.01\n");
    const Result bad_config = cli("refilter --log " + log.string() + " --config " + typo.string());
    EXPECT_EQ(bad_config.exit_code, 1);
    EXPECT_NE(bad_config.err.find("typo.toml:3: filter.r33"), std::string::npos) << bad_config.err;

    const Result unwritable = cli("run -e f --laps 1 -q --no-plots -o " + (dir_ / "x").string()
                                  + " --record " + (dir_ / "no" / "such" / "run.log").string());
    EXPECT_EQ(unwritable.exit_code, 2);
    EXPECT_NE(unwritable.err.find("cannot create the run log"), std::string::npos)
        << unwritable.err;
}

TEST_F(RefilterCli, ALogCutOffMidLineStillRefiltersWithANote) {
    const std::string text = read_file(record());
    const std::size_t end_line = text.rfind("end: ");
    const std::size_t last_record = text.rfind('\n', end_line - 2) + 1;
    const fs::path cut = write("cut.log", text.substr(0, last_record + 20));
    const fs::path out = dir_ / "refilter";
    const Result refilter =
        cli("refilter --log " + cut.string() + " --out " + out.string() + " --no-plots");
    ASSERT_EQ(refilter.exit_code, 0) << refilter.err;
    EXPECT_NE(refilter.err.find("note: " + cut.string()), std::string::npos) << refilter.err;
    EXPECT_NE(refilter.err.find("cut off"), std::string::npos) << refilter.err;
    EXPECT_NE(refilter.out.find("new configuration: the recorded one"), std::string::npos);
    const nlohmann::json summary = nlohmann::json::parse(read_file(out / "summary.json"));
    EXPECT_EQ(summary["log_truncated"], true);
    EXPECT_EQ(summary["recorded_replay_reproduces_run"], true);
    EXPECT_FALSE(fs::exists(out / "refilter_trajectory.png"));  // --no-plots
}

// A real-time run over UDP killed with SIGKILL: the log on disk holds what was flushed
// (at most half a second old) and refilters.
TEST_F(RefilterCli, ARunKilledMidWayLeavesALogThatRefilters) {
    const fs::path ready = dir_ / "ready";
    start_in_background(
        LEGOFEUP_SIM,
        "--port 0 --ready-file " + ready.string() + " --duration 60 --quiet --time-scale 1", "sim");
    ASSERT_TRUE(wait_for_file(ready, 10s));
    std::istringstream ports(read_file(ready));
    std::string robot, truth, control;
    std::getline(ports, robot);
    std::getline(ports, truth);
    std::getline(ports, control);
    const fs::path log = dir_ / "killed.log";
    start_in_background(LEGOFEUP_CLI,
                        "run -e f -q --no-plots -o " + (dir_ / "run").string()
                            + " --link udp://127.0.0.1:" + robot.substr(6) + " --truth-port "
                            + truth.substr(6) + " --control-port " + control.substr(8)
                            + " --record " + log.string(),
                        "cli");
    // Wait (not a timing assertion) until the flushed log holds 20 records past its header.
    const auto give_up = std::chrono::steady_clock::now() + 30s;
    bool flushed = false;
    while (!flushed && std::chrono::steady_clock::now() < give_up) {
        const std::string text = read_file(log);
        const std::size_t records = text.find("\ncolumns: ");
        flushed = records != std::string::npos
                  && std::count(text.begin() + static_cast<long>(records), text.end(), '\n') > 21;
        std::this_thread::sleep_for(50ms);
    }
    ASSERT_EQ(std::system(("kill -KILL $(cat " + (dir_ / "cli.pid").string() + ")").c_str()), 0);
    std::this_thread::sleep_for(100ms);  // let the kernel reap it before reading
    ASSERT_TRUE(flushed) << "the log on disk never held 20 records while the run went on";

    const Result refilter = cli("refilter --log " + log.string());
    ASSERT_EQ(refilter.exit_code, 0) << refilter.err;
    EXPECT_NE(refilter.err.find("no end line"), std::string::npos) << refilter.err;
    EXPECT_NE(refilter.out.find("reproduces the run exactly"), std::string::npos) << refilter.out;
}

}  // namespace
