// legofeup: the LegoFeup Lab desktop application. Reads the command line (before any display
// is opened), builds the session (ui::initial_config: --config, --experiment, the
// configuration last used, or experiment f) and the window; everything they show is in
// legofeup::ui.
#include <QApplication>
#include <QPointer>
#include <QProcessEnvironment>
#include <QTimer>
#include <cstdio>
#include <optional>

#include "legofeup/ui/calibration/ir_calibration_dialog.hpp"
#include "legofeup/ui/calibration/umbmark_dialog.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/refilter/refilter_dialog.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/appearance.hpp"
#include "legofeup/ui/window/at_run_time.hpp"
#include "legofeup/ui/window/command_line.hpp"
#include "legofeup/ui/window/connect_dialog.hpp"
#include "legofeup/ui/window/display_check.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"
#include "legofeup/ui/window/start_up.hpp"
#include "legofeup/version.hpp"

namespace {

using legofeup::ui::CommandLine;

/// Prints what `command_line` answers by itself — the help or the version (exit 0), or why
/// it is refused (exit 2) — and returns the exit code; nullopt for a start.
std::optional<int> answer(const CommandLine& command_line) {
    switch (command_line.action) {
        case CommandLine::Action::Help:
        case CommandLine::Action::Version:
            std::printf("%s\n", qPrintable(command_line.text));
            return 0;
        case CommandLine::Action::Refuse:
            std::fprintf(stderr, "%s\n", qPrintable(command_line.text));
            return legofeup::ui::kRefusedExitCode;
        case CommandLine::Action::Start:
            break;
    }
    return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
    namespace ui = legofeup::ui;
    QApplication::setOrganizationName(QStringLiteral("LegoFeup"));
    QApplication::setApplicationName(QStringLiteral("LegoFeup Lab"));
    QApplication::setApplicationVersion(QString::fromLatin1(legofeup::kVersion));
    // The command line is read before QApplication opens the display, so that --help,
    // --version and a refused value work without one, and a start without one says what to
    // do instead of Qt aborting in its platform plugin.
    QStringList arguments;
    for (int i = 0; i < argc; ++i) {
        arguments << QString::fromLocal8Bit(argv[i]);
    }
    const CommandLine early = ui::read_command_line(arguments);
    if (early.action == CommandLine::Action::Help || early.action == CommandLine::Action::Version) {
        return *answer(early);
    }
    if (const QString missing =
            ui::missing_display(arguments, QProcessEnvironment::systemEnvironment());
        !missing.isEmpty()) {
        if (const std::optional<int> refused = answer(early)) {
            return *refused;
        }
        std::fprintf(stderr, "%s\n", qPrintable(missing));
        return 1;
    }

    Q_INIT_RESOURCE(legofeup_ui);  // the icon, built into the static ui library
    QApplication app(argc, argv);
    QApplication::setDesktopFileName(QStringLiteral("legofeup-lab"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/legofeup/legofeup-lab.svg")));
    // Again without Qt's own options (-platform, -style, …), which QApplication took.
    const CommandLine command_line = ui::read_command_line(QApplication::arguments());
    if (const std::optional<int> answered = answer(command_line)) {
        return *answered;
    }
    const ui::StartOptions& options = command_line.options;

    const ui::Theme theme = ui::theme_from_name(
        options.theme.isEmpty() ? ui::preferences::kTheme.read() : options.theme);
    if (!options.theme.isEmpty()) {
        ui::preferences::kTheme.write(options.theme);
    }
    ui::apply_appearance(app, theme, 1.0);

    const ui::StartConfig start = ui::initial_config(options);
    if (!start.config) {
        std::fprintf(stderr, "%s\n", qPrintable(start.refusal));
        return ui::kRefusedExitCode;
    }
    ui::Session session(*start.config);
    session.setLinkChoice(ui::initial_link(options));

    ui::MainWindow window(session);
    ui::show_initial_step(window.lessonPanel(), options);
    if (options.large_text) {
        window.setLargeText(true);
    }
    window.setFrameLogInterval(options.frame_log);
    window.show();
    for (const QString& note : start.notes) {
        emit session.problem(note);
    }
    if (options.start) {
        QTimer::singleShot(0, &session, &ui::Session::start);
    }
    QPointer<QWidget> dialog;
    if (options.open_dialog == QLatin1String("connect")) {
        dialog = window.runToolBar().openConnectDialog();
    } else if (options.open_dialog == QLatin1String("ir-calibration")) {
        dialog = window.openIrCalibration();
    } else if (options.open_dialog == QLatin1String("umbmark")) {
        dialog = window.openUmbmark();
    } else if (options.open_dialog == QLatin1String("refilter")) {
        dialog = window.openRefilter();
    }
    if (!options.screenshot.isEmpty()) {
        const auto take_picture = [&] {
            QWidget* shown = dialog ? dialog.data() : &window;
            const bool saved = shown->grab().save(options.screenshot);
            std::fprintf(stderr, "legofeup: %s %s\n", saved ? "saved" : "could not save",
                         qPrintable(options.screenshot));
            std::fprintf(stderr, "legofeup: frame times (mean/p99/max): %s\n",
                         qPrintable(window.frameTimesText()));
            QApplication::exit(saved ? 0 : 2);
        };
        if (options.screenshot_at) {
            // After this turn of the event loop, so the views have drawn the sample reached.
            ui::at_run_time(session, *options.screenshot_at,
                            [&] { QTimer::singleShot(0, &window, take_picture); });
        } else {
            QTimer::singleShot(static_cast<int>(options.screenshot_after * 1000), &window,
                               take_picture);
        }
    }
    return QApplication::exec();
}
