#pragma once
// The command line of `legofeup` (docs/gui.md, "Command line"). It is read before any window
// exists — from the program's own arguments, without a QApplication — so --help, --version
// and every refused value work on a machine without a display.

#include <QString>
#include <QStringList>
#include <cstdint>
#include <optional>

namespace legofeup::ui {

/// What the command line asks the window to start with.
struct StartOptions {
    QString experiment;  ///< --experiment: "a" … "f" or "<lesson>:<step>"; empty: none
    QString config;      ///< --config: a run configuration (TOML); empty: none
    QString theme;       ///< --theme: "system", "light" or "dark"; empty: the one saved
    bool large_text = false;
    bool start = false;
    double speed = 0.0;             ///< --speed (is_simulator_speed); 0: the one saved
    QString screenshot;             ///< --screenshot: the picture's file; empty: none
    double screenshot_after = 5.0;  ///< seconds
    /// --screenshot-at: the run time (s, the status bar's t) to take the picture at, instead
    /// of after screenshot_after seconds; nullopt: none.
    std::optional<double> screenshot_at;
    int frame_log = 0;    ///< --frame-log: seconds between logs; 0: none
    QString open_dialog;  ///< connect, ir-calibration, umbmark, refilter; empty: none
};

struct CommandLine {
    enum class Action : std::uint8_t { Start, Help, Version, Refuse };
    Action action = Action::Start;
    StartOptions options;  ///< for Start
    /// Help: the help text; Version: the application's name and version; Refuse: why, as
    /// one line naming the option and its value ("legofeup: --speed = 0: expected …").
    QString text;
};

/// The exit code of a refused command line or start (as getopt's and CLI11's programs).
inline constexpr int kRefusedExitCode = 2;

/// Reads `arguments`, the program's name first (as QCoreApplication::arguments()). The
/// version is QCoreApplication's applicationName() and applicationVersion().
CommandLine read_command_line(const QStringList& arguments);

}  // namespace legofeup::ui
