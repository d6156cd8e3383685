// legofeup-cli built without the NXT (LEGOFEUP_WITH_NXT=OFF): every NXT link and option is bad
// input, refused with the reason and exit code 1 before anything is written; the simulators
// run as in any build.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::Result;

class NoNxtCli : public legofeup::testing::ProgramTest {};

TEST_F(NoNxtCli, NxtLinksAndOptionsAreRefusedAsBadInputWithTheReason) {
    for (const std::string& option :
         {std::string("--link bt:00:16:53:01:02:03"), std::string("--link serial:/dev/rfcomm0"),
          std::string("--link tcp:127.0.0.1:7000"), std::string("--relay"),
          std::string("--truth udp://127.0.0.1:5601")}) {
        const fs::path out = dir_ / "out";
        const Result result =
            run_program(LEGOFEUP_CLI, "run -e f --laps 1 -o " + out.string() + " " + option);
        EXPECT_EQ(result.exit_code, 1) << option;
        EXPECT_NE(result.err.find("error: " + option.substr(0, option.find(' '))),
                  std::string::npos)
            << option << ": " << result.err;
        EXPECT_NE(result.err.find("this build has no NXT support (built with "
                                  "LEGOFEUP_WITH_NXT=OFF)"),
                  std::string::npos)
            << option << ": " << result.err;
        EXPECT_FALSE(fs::exists(out)) << option;
    }
}

TEST_F(NoNxtCli, TheSimulatorRunsAsInAnyBuild) {
    const Result result = run_program(
        LEGOFEUP_CLI, "run -e f --laps 1 --no-plots --quiet -o " + (dir_ / "lockstep").string());
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_TRUE(fs::exists(dir_ / "lockstep" / "summary.json"));
}

}  // namespace
