// legofeup-nxt-emu as a user runs it: bad options exit 2 with a reason; a running emulator
// writes its ready file, answers over TCP, and prints its counters when stopped.

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/transport.hpp"
#include "support/program_test.hpp"

extern char** environ;

namespace legofeup {
namespace {

namespace nxt = comms::nxt;
using namespace std::chrono_literals;
using testing::ProgramTest;

class NxtEmuProgram : public ProgramTest {
  protected:
    testing::Result emu(const std::string& arguments) const {
        return run_program(LEGOFEUP_NXT_EMU, arguments);
    }
};

TEST_F(NxtEmuProgram, BadOptionsExitWith2AndSayWhy) {
    testing::Result result = emu("--tcp 0 --bogus");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("--bogus"), std::string::npos) << result.err;

    result = emu("--duration 1");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("--tcp"), std::string::npos) << result.err;

    result = emu("--tcp 0 --experiment z");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("unknown experiment"), std::string::npos) << result.err;

    result = emu("--tcp 0 --right-motor B --left-motor b");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("both"), std::string::npos) << result.err;

    EXPECT_EQ(emu("--tcp 0 --latency-ms -3").exit_code, 2);
    EXPECT_EQ(emu("--tcp 0 --battery-mv 100").exit_code, 2);
}

TEST_F(NxtEmuProgram, ServesOverTcpAndPrintsItsCountersOnSigterm) {
    const std::string ready = (dir_ / "ready.json").string();
    const std::string out = (dir_ / "stdout.txt").string();
    const std::vector<std::string> arguments = {LEGOFEUP_NXT_EMU,
                                                "--tcp",
                                                "0",
                                                "--experiment",
                                                "f",
                                                "--seed",
                                                "7",
                                                "--latency-ms",
                                                "5",
                                                "--ready-file",
                                                ready,
                                                "--duration",
                                                "30"};
    std::vector<char*> argv;
    for (const std::string& argument : arguments) {
        argv.push_back(const_cast<char*>(argument.c_str()));
    }
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ), 0);
    posix_spawn_file_actions_destroy(&actions);

    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (!std::filesystem::exists(ready) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(20ms);
    }
    ASSERT_TRUE(std::filesystem::exists(ready));
    const nlohmann::json info = nlohmann::json::parse(testing::read_file(ready));
    const auto port = info.at("tcp_port").get<std::uint16_t>();
    EXPECT_EQ(info.at("tcp").get<std::string>(), "tcp:127.0.0.1:" + std::to_string(port));
    EXPECT_EQ(info.at("truth").get<std::string>(),
              "udp://127.0.0.1:" + std::to_string(info.at("simulator").at("truth").get<int>()));

    {
        const auto stream = nxt::open_transport(nxt::parse_transport_address(info.at("tcp")), 2s);
        nxt::write_telegram(*stream, nxt::encode_get_battery_level());
        const nxt::Telegram reply =
            nxt::read_telegram(*stream, std::chrono::steady_clock::now() + 2s);
        EXPECT_EQ(nxt::decode_battery_level_reply(reply), 7800);
    }
    ::kill(pid, SIGTERM);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0);
    const std::string printed = testing::read_file(out);
    EXPECT_NE(printed.find("experiment f, seed 7"), std::string::npos) << printed;
    EXPECT_NE(printed.find("1 telegrams in"), std::string::npos) << printed;
}

}  // namespace
}  // namespace legofeup
