// The built `legofeup` run as a new user runs it on a machine without a display (DISPLAY,
// WAYLAND_DISPLAY and QT_QPA_PLATFORM unset): --help and --version answer, a start says in
// one sentence what to do instead (no Qt abort: exit 1, not 134), a refused value exits
// with 2 and its reason — also with a display (offscreen), once QApplication exists.

#include <gtest/gtest.h>

#include "support/program_test.hpp"

namespace legofeup::testing {
namespace {

class GuiCli : public ProgramTest {
  protected:
    /// `legofeup arguments` with no display at all, its settings in the test's directory.
    Result without_display(const std::string& arguments) const {
        return run_program("env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM XDG_CONFIG_HOME="
                               + dir_.string() + " " LEGOFEUP_GUI,
                           arguments);
    }
    Result offscreen(const std::string& arguments) const {
        return run_program(
            "env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=offscreen "
            "XDG_CONFIG_HOME="
                + dir_.string() + " " LEGOFEUP_GUI,
            arguments);
    }
};

constexpr int kAborted = 128 + 6;  // what a shell reports for SIGABRT

TEST_F(GuiCli, HelpWorksWithoutADisplay) {
    for (const char* help : {"--help", "-h"}) {
        const Result result = without_display(help);
        EXPECT_EQ(result.exit_code, 0) << result.err;
        EXPECT_EQ(result.out.rfind("Usage: legofeup [options]\n", 0), 0U) << result.out;
        for (const char* option :
             {"--experiment <ID>", "--config <FILE>", "--speed <FACTOR>", "--start"}) {
            EXPECT_NE(result.out.find(option), std::string::npos) << option;
        }
        EXPECT_EQ(result.err, "");
    }
}

TEST_F(GuiCli, VersionWorksWithoutADisplay) {
    const Result result = without_display("--version");
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out, "LegoFeup Lab " LEGOFEUP_VERSION "\n");
    EXPECT_EQ(result.err, "");
}

TEST_F(GuiCli, AStartWithoutADisplaySaysWhatToDoInOneSentence) {
    for (const char* arguments : {"", "--experiment laser:a --start"}) {
        const Result result = without_display(arguments);
        EXPECT_NE(result.exit_code, kAborted);
        EXPECT_EQ(result.exit_code, 1) << result.err;
        EXPECT_EQ(result.err,
                  "legofeup: there is no display to open the window on (DISPLAY and "
                  "WAYLAND_DISPLAY are unset): run the lessons without a window with legofeup-cli "
                  "(e.g. legofeup-cli run --experiment f), or give the window a virtual display "
                  "with xvfb-run legofeup.\n");
        EXPECT_EQ(result.out, "");
    }
}

TEST_F(GuiCli, ARefusedValueExitsWithTwoAndItsReasonWithOrWithoutADisplay) {
    const std::string expected =
        ": expected a number from 0.05 to 1000 (simulated seconds per "
        "real second)\n";
    for (const char* speed : {"0", "-2", "nan", "fast", "1e9"}) {
        const Result result = without_display(std::string("--speed ") + speed);
        EXPECT_EQ(result.exit_code, 2) << speed;
        EXPECT_EQ(result.err, "legofeup: --speed = " + std::string(speed) + expected);
    }
    // With a display the command line is read again after QApplication took Qt's options.
    const Result result = offscreen("--speed 0 --start");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.err.find("legofeup: --speed = 0" + expected), std::string::npos) << result.err;
    const Result missing = offscreen("--config no-such.toml");
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("legofeup: --config = no-such.toml: no such file"),
              std::string::npos)
        << missing.err;
}

}  // namespace
}  // namespace legofeup::testing
