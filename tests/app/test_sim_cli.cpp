// legofeup-sim and `legofeup-cli run --link udp://…` as a user runs them: a run against the
// standalone server gives the lockstep run's results; bad input gets a precise message.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "legofeup/comms/udp_socket.hpp"
#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

using legofeup::testing::read_file;
using legofeup::testing::Result;

class SimCli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& program, const std::string& arguments) const {
        return run_program(program, arguments);
    }

    /// Starts legofeup-sim in the background on free ports; returns the legofeup-cli
    /// options that reach it (empty if it did not start).
    std::string start_server(const std::string& arguments, int duration_seconds = 60) {
        const fs::path ready = dir_ / "ready";
        start_in_background(LEGOFEUP_SIM,
                            "--port 0 --ready-file " + ready.string() + " --duration "
                                + std::to_string(duration_seconds) + " --quiet " + arguments,
                            "sim");
        wait_for_file(ready, 5s);
        std::istringstream ports(read_file(ready));
        std::string robot, truth, control;
        std::getline(ports, robot);
        std::getline(ports, truth);
        std::getline(ports, control);
        if (!robot.starts_with("robot=") || !truth.starts_with("truth=")
            || !control.starts_with("control=")) {
            return {};
        }
        return "--link udp://127.0.0.1:" + robot.substr(6) + " --truth-port " + truth.substr(6)
               + " --control-port " + control.substr(8);
    }
};

TEST_F(SimCli, AnExperimentOverUdpInLockstepWritesWhatTheInProcessRunWrites) {
    const std::string link = start_server("--time-scale 0");
    ASSERT_FALSE(link.empty());
    const std::string experiment = "run -e f --laps 1 --no-plots --quiet";
    const Result udp =
        run(LEGOFEUP_CLI, experiment + " " + link + " -o " + (dir_ / "udp").string());
    ASSERT_EQ(udp.exit_code, 0) << udp.err;
    const Result local = run(LEGOFEUP_CLI, experiment + " -o " + (dir_ / "local").string());
    ASSERT_EQ(local.exit_code, 0) << local.err;
    EXPECT_EQ(read_file(dir_ / "udp" / "trace.csv"), read_file(dir_ / "local" / "trace.csv"));
    const std::string summary = read_file(dir_ / "udp" / "summary.json");
    EXPECT_NE(summary.find("\"kind\": \"udp\""), std::string::npos);
    EXPECT_NE(summary.find("\"frames_missing\": 0"), std::string::npos);
}

// The server's encoders count at --counts-per-turn, as the lockstep simulator's count at the
// configuration's robot.counts_per_turn: with 720 on both sides the run over UDP is the
// in-process run, byte for byte (a server counting degrees would halve every distance).
TEST_F(SimCli, AServerCountingAtTheClientsResolutionGivesTheInProcessRun) {
    const std::string link = start_server("--time-scale 0 --counts-per-turn 720");
    ASSERT_FALSE(link.empty());
    const fs::path config = dir_ / "cpt720.toml";
    std::ofstream(config) << "[robot]\ncounts_per_turn = 720\n";
    const std::string experiment =
        "run -e f --laps 1 --no-plots --quiet -c " + config.string() + " ";
    const Result udp = run(LEGOFEUP_CLI, experiment + link + " -o " + (dir_ / "udp").string());
    ASSERT_EQ(udp.exit_code, 0) << udp.err;
    const Result local = run(LEGOFEUP_CLI, experiment + "-o " + (dir_ / "local").string());
    ASSERT_EQ(local.exit_code, 0) << local.err;
    EXPECT_EQ(read_file(dir_ / "udp" / "trace.csv"), read_file(dir_ / "local" / "trace.csv"));
}

TEST_F(SimCli, ALinkThatIsNotAUrlOrHasNoServerIsAClearError) {
    const Result bad = run(LEGOFEUP_CLI, "run -e f -o " + (dir_ / "x").string()
                                             + " --link udp://simulator.local:5600");
    EXPECT_EQ(bad.exit_code, 1);
    EXPECT_NE(bad.err.find("--link"), std::string::npos) << bad.err;
    EXPECT_NE(bad.err.find("udp://a.b.c.d:port"), std::string::npos) << bad.err;

    const legofeup::comms::UdpSocket idle(legofeup::comms::Endpoint{0x7F000001, 0});
    const int port = idle.local_endpoint().port;  // bound by us, so nobody answers there
    const Result silent = run(
        LEGOFEUP_CLI, "run -e f -o " + (dir_ / "y").string() + " --link udp://127.0.0.1:"
                          + std::to_string(port - 2) + " --control-port " + std::to_string(port));
    EXPECT_EQ(silent.exit_code, 3);
    EXPECT_NE(silent.err.find("no reply from the simulator"), std::string::npos) << silent.err;
    EXPECT_FALSE(fs::exists(dir_ / "y" / "trace.csv"));
}

TEST_F(SimCli, ServerRefusesBadOptionsWithAPreciseMessage) {
    const Result remote = run(LEGOFEUP_SIM, "--bind 0.0.0.0 --duration 1");
    EXPECT_EQ(remote.exit_code, 1);
    EXPECT_NE(remote.err.find("--allow-remote"), std::string::npos) << remote.err;

    const Result scale = run(LEGOFEUP_SIM, "--port 0 --time-scale -3 --duration 1");
    EXPECT_EQ(scale.exit_code, 1);
    EXPECT_NE(scale.err.find("server.time_scale = -3"), std::string::npos) << scale.err;

    const Result noise = run(LEGOFEUP_SIM, "--port 0 --slip-noise -1 --duration 1");
    EXPECT_EQ(noise.exit_code, 1);
    EXPECT_NE(noise.err.find("slip_noise = -1"), std::string::npos) << noise.err;

    const Result counts = run(LEGOFEUP_SIM, "--port 0 --counts-per-turn 0 --duration 1");
    EXPECT_EQ(counts.exit_code, 1);
    EXPECT_NE(counts.err.find("simulator.counts_per_turn = 0"), std::string::npos) << counts.err;

    const Result absent = run(LEGOFEUP_SIM, "--port 0 --duration 1 --world offce");
    EXPECT_NE(absent.exit_code, 0);  // CLI11's validation exit code
    EXPECT_NE(absent.err.find("--world: 'offce': neither a built-in world"), std::string::npos)
        << absent.err;

    const fs::path world = dir_ / "bad_world.toml";
    std::ofstream(world) << "name = \"broken\"\n[[walls]]\nname = \"w\"\nfrom = [0.0, 0.0]\n"
                            "to = \"nowhere\"\n";
    const Result broken = run(LEGOFEUP_SIM, "--port 0 --duration 1 --world " + world.string());
    EXPECT_EQ(broken.exit_code, 1);
    EXPECT_NE(broken.err.find(world.string() + ":"), std::string::npos) << broken.err;

    const legofeup::comms::UdpSocket taken(legofeup::comms::Endpoint{0x7F000001, 0});
    const Result busy =
        run(LEGOFEUP_SIM, "--duration 1 --port " + std::to_string(taken.local_endpoint().port));
    EXPECT_EQ(busy.exit_code, 1);
    EXPECT_NE(busy.err.find("Address already in use"), std::string::npos) << busy.err;
}

// The server stops 3 s into a 2-minute lap: the run ends, says why, and keeps what it had
// recorded (the trace's rows are the steps summary.json says were recorded), as a run whose
// NXT loses its link does (test_nxt_cli.cpp).
TEST_F(SimCli, AServerThatStopsMidRunEndsTheRunAndWhatWasRecordedIsKept) {
    const std::string link = start_server("--time-scale 1", 3);
    ASSERT_FALSE(link.empty());
    const Result cut = run(
        LEGOFEUP_CLI, "run -e f --laps 1 --no-plots " + link + " -o " + (dir_ / "cut").string());
    EXPECT_EQ(cut.exit_code, 3) << cut.err;
    EXPECT_NE(cut.err.find("stopped after"), std::string::npos) << cut.err;
    EXPECT_NE(cut.err.find("delivered no frame"), std::string::npos) << cut.err;
    EXPECT_NE(cut.err.find("Is the simulator still running?"), std::string::npos) << cut.err;
    const std::string trace = read_file(dir_ / "cut" / "trace.csv");
    const auto rows = std::count(trace.begin(), trace.end(), '\n') - 1;
    EXPECT_GT(rows, 20) << trace.substr(0, 300);  // 3 s at 20 steps a second, less a start
    const std::string summary = read_file(dir_ / "cut" / "summary.json");
    EXPECT_NE(summary.find("\"steps_recorded\": " + std::to_string(rows)), std::string::npos)
        << summary;
    EXPECT_NE(summary.find("\"kind\": \"udp\""), std::string::npos) << summary;
    EXPECT_NE(summary.find("\"routine_finished\": false"), std::string::npos) << summary;
}

TEST_F(SimCli, ServerPrintsWhereItListensAndStopsAfterItsDuration) {
    const Result result = run(LEGOFEUP_SIM, "--port 0 --duration 0.3");
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("robot   udp://127.0.0.1:"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("LegoFeup standard arena"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("encoders 360 counts a turn"), std::string::npos) << result.out;
}

TEST_F(SimCli, ServerRunsABuiltInWorldByItsName) {
    const Result result = run(LEGOFEUP_SIM, "--port 0 --duration 0.3 --world office");
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("world 'Office floor'"), std::string::npos) << result.out;
}

}  // namespace
