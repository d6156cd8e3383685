// What `legofeup` makes of its command line before any window exists (GoogleTest, no
// QApplication): help and version whatever else is given, every speed the simulator runs at
// taken as given, absurd values refused naming the option and the value, and whether a
// display can be opened.

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "legofeup/simserver/sim_server.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/command_line.hpp"
#include "legofeup/ui/window/display_check.hpp"

namespace legofeup::ui {
namespace {

CommandLine read(std::initializer_list<const char*> arguments) {
    QStringList list{QStringLiteral("/usr/bin/legofeup")};
    for (const char* argument : arguments) {
        list << QString::fromUtf8(argument);
    }
    return read_command_line(list);
}

std::string text(const CommandLine& command_line) {
    return command_line.text.toStdString();
}

const std::string kSpeedExpected =
    ": expected a number from 0.05 to 1000 (simulated seconds per real second)";

TEST(CommandLine, HelpAndVersionAnswerWhateverElseIsGiven) {
    QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab"));
    QCoreApplication::setApplicationVersion(QStringLiteral("9.8.7"));
    for (const CommandLine& help :
         {read({"--help"}), read({"-h"}), read({"--speed", "0", "--help"}), read({"-x", "-h"})}) {
        ASSERT_EQ(help.action, CommandLine::Action::Help) << text(help);
        EXPECT_EQ(text(help).rfind("Usage: legofeup [options]\n", 0), 0U) << text(help);
        for (const char* option : {"--config <FILE>", "--experiment <ID>", "--speed <FACTOR>",
                                   "--screenshot <FILE>", "from 0.05 to 1000"}) {
            EXPECT_NE(text(help).find(option), std::string::npos) << option;
        }
    }
    for (const CommandLine& version : {read({"--version"}), read({"-v", "--speed", "nan"})}) {
        ASSERT_EQ(version.action, CommandLine::Action::Version);
        EXPECT_EQ(text(version), "LegoFeup Lab 9.8.7");
    }
}

TEST(CommandLine, AnySpeedTheSimulatorRunsAtIsTakenAsGiven) {
    EXPECT_EQ(read({}).options.speed, 0.0);  // none given: the one saved
    for (const auto& [given, speed] :
         {std::pair{"0.05", 0.05}, std::pair{"0.5", 0.5}, std::pair{"4", 4.0},
          std::pair{"7.5", 7.5}, std::pair{"1e2", 100.0}, std::pair{"1000", 1000.0}}) {
        const CommandLine command_line = read({"--speed", given});
        ASSERT_EQ(command_line.action, CommandLine::Action::Start) << text(command_line);
        EXPECT_EQ(command_line.options.speed, speed) << given;
    }
    EXPECT_EQ(read({"--speed=4"}).options.speed, 4.0);
}

TEST(CommandLine, AbsurdSpeedsAreRefusedNamingTheOptionAndTheValue) {
    for (const char* given : {"0", "-1", "0.049", "1000.5", "1e9", "1e400", "nan", "inf", "-inf",
                              "fast", "4x", "4,5"}) {
        const CommandLine command_line = read({"--speed", given});
        ASSERT_EQ(command_line.action, CommandLine::Action::Refuse) << given;
        EXPECT_EQ(text(command_line), "legofeup: --speed = " + std::string(given) + kSpeedExpected);
    }
    EXPECT_EQ(text(read({"--speed="})), "legofeup: --speed = (nothing)" + kSpeedExpected);
    EXPECT_EQ(text(read({"--speed"})),
              "legofeup: Missing value after '--speed'. (legofeup "
              "--help lists the options)");
}

TEST(CommandLine, TheSpeedsAreTheOnesTheSimulatorServerAccepts) {
    // The window's range is the server's time scales without lockstep (0): its ends are
    // accepted by simserver::validate, just outside them refused.
    const auto server_accepts = [](double time_scale) {
        simserver::SimServerOptions options;
        options.time_scale = time_scale;
        return simserver::validate(options).empty();
    };
    EXPECT_TRUE(server_accepts(kMinSimulatorSpeed));
    EXPECT_TRUE(server_accepts(kMaxSimulatorSpeed));
    EXPECT_FALSE(server_accepts(kMinSimulatorSpeed * 0.99));
    EXPECT_FALSE(server_accepts(kMaxSimulatorSpeed * 1.01));
    EXPECT_TRUE(server_accepts(0.0));  // lockstep, which the window refuses
    EXPECT_FALSE(is_simulator_speed(0.0));
}

TEST(CommandLine, OtherNumbersChoicesAndWordsAreRefusedWithTheirReason) {
    const std::map<std::vector<const char*>, std::string> refusals = {
        {{"--frame-log", "2.5"},
         "legofeup: --frame-log = 2.5: expected a whole number of seconds from 1 to 1000"},
        {{"--screenshot-after", "-1"},
         "legofeup: --screenshot-after = -1: expected a number of seconds from 0 to 1000"},
        {{"--start", "--screenshot-at", "-1"},
         "legofeup: --screenshot-at = -1: expected a run time in seconds from 0 to 86400"},
        {{"--start", "--screenshot-at", "soon"},
         "legofeup: --screenshot-at = soon: expected a run time in seconds from 0 to 86400"},
        {{"--screenshot-at", "30"},
         "legofeup: --screenshot-at needs --start: without a run, no run time is ever reached"},
        {{"--start", "--screenshot-at", "30", "--screenshot-after", "5"},
         "legofeup: --screenshot-at and --screenshot-after both say when to take the picture: "
         "give one of them"},
        {{"--theme", "blue"}, "legofeup: --theme = blue: expected system, light or dark"},
        {{"--open-dialog", "x"},
         "legofeup: --open-dialog = x: expected connect, ir-calibration, umbmark or refilter"},
        {{"--experiment", "z"},
         "legofeup: --experiment = z: expected a … h or <lesson>:<step> (e.g. beacons:a)"},
        {{"--experiment", "f", "--config", "f.toml"},
         "legofeup: --experiment and --config both give the configuration to start with: give "
         "one of them"},
        {{"laser-config.toml"},
         "legofeup: unexpected argument laser-config.toml: legofeup takes options only (a "
         "configuration file is given with --config FILE)"},
        {{"--sped", "4"}, "legofeup: Unknown option 'sped'. (legofeup --help lists the options)"},
    };
    for (const auto& [arguments, refusal] : refusals) {
        QStringList list{QStringLiteral("legofeup")};
        for (const char* argument : arguments) {
            list << QString::fromUtf8(argument);
        }
        const CommandLine command_line = read_command_line(list);
        EXPECT_EQ(command_line.action, CommandLine::Action::Refuse) << refusal;
        EXPECT_EQ(text(command_line), refusal);
    }
}

TEST(CommandLine, AWholeStartIsReadIntoItsOptions) {
    const CommandLine command_line =
        read({"--experiment", "laser:a", "--theme", "dark", "--large-text", "--start", "--speed",
              "4", "--screenshot", "w.png", "--screenshot-after", "2.5", "--frame-log", "30",
              "--open-dialog", "umbmark"});
    ASSERT_EQ(command_line.action, CommandLine::Action::Start) << text(command_line);
    const StartOptions& options = command_line.options;
    EXPECT_EQ(options.experiment, QStringLiteral("laser:a"));
    EXPECT_TRUE(options.config.isEmpty());
    EXPECT_EQ(options.theme, QStringLiteral("dark"));
    EXPECT_TRUE(options.large_text);
    EXPECT_TRUE(options.start);
    EXPECT_EQ(options.speed, 4.0);
    EXPECT_EQ(options.screenshot, QStringLiteral("w.png"));
    EXPECT_EQ(options.screenshot_after, 2.5);
    EXPECT_EQ(options.frame_log, 30);
    EXPECT_EQ(options.open_dialog, QStringLiteral("umbmark"));
}

TEST(CommandLine, APictureAtARunTimeIsReadWithoutAWait) {
    EXPECT_FALSE(read({}).options.screenshot_at.has_value());
    const CommandLine command_line = read(
        {"--experiment", "laser:d", "--start", "--screenshot", "d.png", "--screenshot-at", "53.5"});
    ASSERT_EQ(command_line.action, CommandLine::Action::Start) << text(command_line);
    ASSERT_TRUE(command_line.options.screenshot_at.has_value());
    EXPECT_EQ(*command_line.options.screenshot_at, 53.5);
    EXPECT_EQ(*read({"--start", "--screenshot-at", "0"}).options.screenshot_at, 0.0);
}

QProcessEnvironment environment(std::initializer_list<std::pair<const char*, const char*>> set) {
    QProcessEnvironment environment;
    environment.insert(QStringLiteral("HOME"), QStringLiteral("/root"));
    for (const auto& [name, value] : set) {
        environment.insert(QString::fromLatin1(name), QString::fromLatin1(value));
    }
    return environment;
}

std::string missing(std::initializer_list<std::pair<const char*, const char*>> set,
                    QStringList arguments = {QStringLiteral("legofeup")}) {
    return missing_display(arguments, environment(set)).toStdString();
}

TEST(DisplayCheck, WithoutADisplayOneSentenceNamesTheWaysOnward) {
    const std::string sentence = missing({});
    EXPECT_EQ(sentence,
              "legofeup: there is no display to open the window on (DISPLAY and WAYLAND_DISPLAY "
              "are unset): run the lessons without a window with legofeup-cli (e.g. "
              "legofeup-cli run --experiment f), or give the window a virtual display with "
              "xvfb-run legofeup.");
    EXPECT_EQ(missing({{"DISPLAY", ""}, {"WAYLAND_DISPLAY", ""}}), sentence);  // set but empty
    // xcb asked for, and only a Wayland display: xcb's variable is the one missing.
    EXPECT_NE(missing({{"QT_QPA_PLATFORM", "xcb"}, {"WAYLAND_DISPLAY", "wayland-0"}})
                  .find("(DISPLAY is unset)"),
              std::string::npos);
}

TEST(DisplayCheck, ADisplayOrAPlatformThatNeedsNoneOpens) {
    EXPECT_EQ(missing({{"DISPLAY", ":0"}}), "");
    EXPECT_EQ(missing({{"WAYLAND_DISPLAY", "wayland-0"}}), "");
    EXPECT_EQ(missing({{"QT_QPA_PLATFORM", "offscreen"}}), "");  // tests and screenshots
    EXPECT_EQ(missing({{"QT_QPA_PLATFORM", "vnc:size=800x600"}}), "");
    EXPECT_EQ(missing({{"QT_QPA_PLATFORM", "xcb;offscreen"}}), "");
    EXPECT_EQ(missing({{"QT_QPA_PLATFORM", "xcb"}, {"DISPLAY", ":99"}}), "");
    // -platform on the command line wins over QT_QPA_PLATFORM, as in QGuiApplication.
    const QStringList offscreen = {QStringLiteral("legofeup"), QStringLiteral("-platform"),
                                   QStringLiteral("offscreen")};
    EXPECT_EQ(missing({{"QT_QPA_PLATFORM", "xcb"}}, offscreen), "");
    EXPECT_NE(
        missing({{"QT_QPA_PLATFORM", "offscreen"}},
                {QStringLiteral("legofeup"), QStringLiteral("-platform"), QStringLiteral("xcb")}),
        "");
}

}  // namespace
}  // namespace legofeup::ui
