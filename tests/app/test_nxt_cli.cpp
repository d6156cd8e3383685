// The real-robot path end to end, as a teacher rehearses it: legofeup-nxt-emu (an emulated
// NXT on the simulated robot, 30 ms latency each way) and `legofeup-cli run --link …` over
// TCP and over a pseudo-terminal. The run completes the square and localises; pulling the
// plug mid-run stops cleanly, says so, and keeps what was recorded; without the truth port
// the counts are still right and the errors absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <utility>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using legofeup::testing::read_file;
using legofeup::testing::Result;

class NxtCli : public legofeup::testing::ProgramTest {
  protected:
    /// Starts legofeup-nxt-emu in the background (its log is `<name>.log`); returns its
    /// ready file (empty on failure).
    nlohmann::json start_emulator(const std::string& arguments, const std::string& name = "emu") {
        const fs::path ready = dir_ / (name + "-ready.json");
        start_in_background(LEGOFEUP_NXT_EMU,
                            "--latency-ms 30 --duration 600 --quiet --ready-file " + ready.string()
                                + " " + arguments,
                            name);
        if (!wait_for_file(ready, 10s)) {
            return {};
        }
        return nlohmann::json::parse(read_file(ready));
    }

    nlohmann::json summary(const std::string& out) const {
        return nlohmann::json::parse(read_file(dir_ / out / "summary.json"));
    }

    /// The square of experiment f, one lap, through the brick at `link`.
    void expect_square_completed_and_localised(const std::string& link, const std::string& truth,
                                               const std::string& extra) {
        const Result run = run_program(
            LEGOFEUP_CLI, "run -e f --laps 1 --seed 3 --no-plots -o " + (dir_ / "out").string()
                              + " --link " + link + " --truth " + truth + " " + extra);
        ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
        EXPECT_NE(run.out.find("robot link:"), std::string::npos) << run.out;
        const nlohmann::json s = summary("out");
        const nlohmann::json& m = s["metrics"];
        EXPECT_TRUE(m["routine_finished"].get<bool>()) << m.dump(2);
        // Localised: the walls corrected the estimate (odometry alone ends several times
        // farther off in experiment f), and the error stays small all lap.
        EXPECT_GT(m["updates_applied"].get<int>(), 20) << m.dump(2);
        EXPECT_LT(m["final_position_error_m"].get<double>(), 0.10) << m.dump(2);
        EXPECT_LT(m["rms_position_error_m"].get<double>(), 0.10) << m.dump(2);
        EXPECT_LT(m["final_position_error_m"].get<double>(),
                  m["final_odometry_position_error_m"].get<double>())
            << m.dump(2);
        const nlohmann::json& l = s["link"];
        EXPECT_EQ(l["kind"], "nxt");
        EXPECT_EQ(l["address"], link);
        // The stock-firmware cycle at 30 ms per direction: well above the 8 Hz it must reach.
        EXPECT_GT(l["rate_hz"].get<double>(), 8.0) << l.dump(2);
        EXPECT_GT(l["battery_mv"].get<int>(), 0) << l.dump(2);
    }
};

TEST_F(NxtCli, ExperimentFCompletesTheSquareOverTcp) {
    const nlohmann::json ready = start_emulator("--tcp 0 -e f --seed 3");
    ASSERT_TRUE(ready.contains("tcp")) << read_file(dir_ / "emu.log");
    expect_square_completed_and_localised(ready["tcp"], ready["truth"], "");
}

TEST_F(NxtCli, ExperimentFCompletesTheSquareOverAPseudoTerminalWithTheRelay) {
    const nlohmann::json ready = start_emulator("--pty -e f --seed 3");
    ASSERT_TRUE(ready.contains("pty")) << read_file(dir_ / "emu.log");
    expect_square_completed_and_localised("serial:" + ready["pty"].get<std::string>(),
                                          ready["truth"], "--relay");
    EXPECT_EQ(summary("out")["link"]["mode"], "relay");
}

TEST_F(NxtCli, PullingThePlugMidRunStopsCleanlyAndKeepsTheTrace) {
    const nlohmann::json ready = start_emulator("--tcp 0 -e f --seed 3 --drop-after 4");
    ASSERT_TRUE(ready.contains("tcp")) << read_file(dir_ / "emu.log");
    const auto started = std::chrono::steady_clock::now();
    const Result run =
        run_program(LEGOFEUP_CLI, "run -e f --laps 1 --no-plots -o " + (dir_ / "out").string()
                                      + " --link " + ready["tcp"].get<std::string>() + " --truth "
                                      + ready["truth"].get<std::string>());
    EXPECT_EQ(run.exit_code, 3) << run.err;
    EXPECT_LT(std::chrono::steady_clock::now() - started, 30s);  // noticed, not hung
    EXPECT_NE(run.err.find("closed the link"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("A stop was sent to the motors"), std::string::npos) << run.err;
    // What was recorded before the plug came out is on disk, complete.
    const std::string trace = read_file(dir_ / "out" / "trace.csv");
    const auto rows = std::count(trace.begin(), trace.end(), '\n') - 1;
    EXPECT_GT(rows, 20) << trace.substr(0, 300);
    const nlohmann::json s = summary("out");
    EXPECT_EQ(s["steps_recorded"].get<long>(), rows);
    EXPECT_NE(s["interrupted"].get<std::string>().find("closed the link"), std::string::npos);
    EXPECT_FALSE(s["metrics"]["routine_finished"].get<bool>());
}

/// The trace's rows and the rows whose wall update was applied, counted from the file.
std::pair<long, long> rows_and_applied_updates(const std::string& trace) {
    std::istringstream lines(trace);
    std::string header;
    std::getline(lines, header);
    const std::string before_update = header.substr(0, header.find(",update,") + 1);
    const auto update_column = std::count(before_update.begin(), before_update.end(), ',');
    long rows = 0;
    long applied = 0;
    for (std::string row; std::getline(lines, row); ++rows) {
        std::size_t at = 0;
        for (long comma = 0; comma < update_column; ++comma) {
            at = row.find(',', at) + 1;
        }
        applied += row.compare(at, 8, "applied,") == 0 ? 1 : 0;
    }
    return {rows, applied};
}

TEST_F(NxtCli, WithoutTruthTheCountsAreTheTracesAndTheErrorsAreAbsentNotZero) {
    // 25 s of experiment f through two emulated bricks, side by side: one driven without the
    // truth port (as a real robot), one with it.
    const fs::path short_run = dir_ / "short.toml";
    std::ofstream(short_run) << "duration = 25\n";
    const nlohmann::json blind = start_emulator("--tcp 0 -e f --seed 3", "blind");
    const nlohmann::json seen = start_emulator("--tcp 0 -e f --seed 3", "seen");
    ASSERT_TRUE(blind.contains("tcp")) << read_file(dir_ / "blind.log");
    ASSERT_TRUE(seen.contains("tcp")) << read_file(dir_ / "seen.log");
    // The two runs drive their own bricks at the same time (they spend it waiting on the
    // link's 30 ms latency, not computing).
    const std::string run = "run -e f --no-plots -c " + short_run.string() + " --link ";
    auto run_with_truth = std::async(std::launch::async, [&] {
        return run_program(LEGOFEUP_CLI,
                           run + seen["tcp"].get<std::string>() + " --truth "
                               + seen["truth"].get<std::string>() + " -o "
                               + (dir_ / "seen").string(),
                           "seen-");
    });
    const Result without = run_program(
        LEGOFEUP_CLI, run + blind["tcp"].get<std::string>() + " -o " + (dir_ / "blind").string(),
        "blind-");
    const Result with = run_with_truth.get();
    ASSERT_EQ(without.exit_code, 0) << without.err << without.out;
    ASSERT_EQ(with.exit_code, 0) << with.err << with.out;

    // The counts need no truth: they are the trace's, counted here from the file.
    const auto [rows, applied] = rows_and_applied_updates(read_file(dir_ / "blind" / "trace.csv"));
    const nlohmann::json blind_summary = summary("blind");
    const nlohmann::json& m = blind_summary["metrics"];
    EXPECT_GT(rows, 200) << m.dump(2);
    EXPECT_GT(applied, 20) << m.dump(2);
    EXPECT_EQ(m["steps"].get<long>(), rows);
    EXPECT_EQ(m["updates_applied"].get<long>(), applied);
    EXPECT_EQ(m["steps_without_truth"].get<long>(), rows);
    // What needs the truth is absent (null), never 0; with the truth it has values.
    const nlohmann::json seen_summary = summary("seen");
    const nlohmann::json& t = seen_summary["metrics"];
    EXPECT_EQ(t["steps_without_truth"].get<long>(), 0) << t.dump(2);
    for (const char* key : {"rms_position_error_m", "final_position_error_m", "mean_nees",
                            "nees_inside_fraction", "final_heading_error_rad", "kidnappings"}) {
        EXPECT_TRUE(m[key].is_null()) << key << " = " << m[key];
        EXPECT_TRUE(t[key].is_number()) << key << " = " << t[key];
    }
    EXPECT_LT(t["final_position_error_m"].get<double>(), 0.10) << t.dump(2);
    // The printed summary says which is which.
    EXPECT_NE(without.out.find("position error: — (no ground truth on this link)"),
              std::string::npos)
        << without.out;
    EXPECT_NE(without.out.find(std::to_string(applied) + " applied"), std::string::npos)
        << without.out;
    EXPECT_EQ(with.out.find("no ground truth"), std::string::npos) << with.out;
}

TEST_F(NxtCli, BadNxtAddressesAndOptionsAreClearErrors) {
    const Result bad = run_program(
        LEGOFEUP_CLI, "run -e f -o " + (dir_ / "x").string() + " --link bt:00:16:53:0G:00:01");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("--link"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("bt:00:16:53:0G:00:01"), std::string::npos) << bad.err;

    const Result relay_on_sim =
        run_program(LEGOFEUP_CLI, "run -e f -o " + (dir_ / "y").string() + " --relay");
    EXPECT_EQ(relay_on_sim.exit_code, 1);
    EXPECT_NE(relay_on_sim.err.find("only applies to an NXT link"), std::string::npos)
        << relay_on_sim.err;

    const Result bad_truth = run_program(
        LEGOFEUP_CLI, "run -e f -o " + (dir_ / "z").string() + " --link tcp:127.0.0.1:9 --truth x");
    EXPECT_EQ(bad_truth.exit_code, 1);
    EXPECT_NE(bad_truth.err.find("--truth"), std::string::npos) << bad_truth.err;

    // Nobody listens: a clear link error naming the address, quickly.
    const Result nobody = run_program(
        LEGOFEUP_CLI, "run -e f -o " + (dir_ / "w").string() + " --link tcp:127.0.0.1:9");
    EXPECT_EQ(nobody.exit_code, 3);
    EXPECT_NE(nobody.err.find("tcp:127.0.0.1:9"), std::string::npos) << nobody.err;
}

TEST_F(NxtCli, ARobotProfileSetsTheFiltersGeometryAndABrokenOneIsRefused) {
    const fs::path profile = dir_ / "robot.toml";
    std::ofstream(profile) << read_file(LEGOFEUP_DEFAULT_PROFILE);
    const Result good = run_program(LEGOFEUP_CLI, "run -e f --laps 1 --no-plots --quiet -o "
                                                      + (dir_ / "good").string() + " --profile "
                                                      + profile.string());
    ASSERT_EQ(good.exit_code, 0) << good.err;
    EXPECT_NE(summary("good")["title"].get<std::string>().find("robot.toml"), std::string::npos);

    std::ofstream(profile) << read_file(LEGOFEUP_DEFAULT_PROFILE) << "\nwheel_base = -1\n";
    const Result bad = run_program(
        LEGOFEUP_CLI, "run -e f -o " + (dir_ / "bad").string() + " --profile " + profile.string());
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find(profile.string() + ":"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("wheel_base"), std::string::npos) << bad.err;
}

}  // namespace
