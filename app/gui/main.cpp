// legofeup: the LegoFeup Lab desktop application. Builds the session (the configuration last
// used, or experiment f) and the window; everything they show is in legofeup::ui.
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPointer>
#include <QScreen>
#include <QTimer>
#include <cstdio>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/ui/calibration/ir_calibration_dialog.hpp"
#include "legofeup/ui/calibration/umbmark_dialog.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/refilter/refilter_dialog.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/appearance.hpp"
#include "legofeup/ui/window/connect_dialog.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"
#include "legofeup/version.hpp"

namespace {

using legofeup::ui::Session;

struct Options {
    QString experiment;
    QString config;
    QString theme;
    bool large_text = false;
    bool start = false;
    double speed = 0.0;
    QString screenshot;
    double screenshot_after = 5.0;
    int frame_log = 0;
    QString open_dialog;
};

Options parse(const QApplication& app) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("LegoFeup Lab: mobile-robot localisation with the Extended Kalman Filter"));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption experiment(QStringLiteral("experiment"),
                                        QStringLiteral("Start with experiment ID (a … f)."),
                                        QStringLiteral("ID"));
    const QCommandLineOption config(QStringLiteral("config"),
                                    QStringLiteral("Start with this run configuration (TOML)."),
                                    QStringLiteral("FILE"));
    const QCommandLineOption theme(
        QStringLiteral("theme"), QStringLiteral("system, light or dark."), QStringLiteral("THEME"));
    const QCommandLineOption large(QStringLiteral("large-text"),
                                   QStringLiteral("The projector view: larger text."));
    const QCommandLineOption start(QStringLiteral("start"),
                                   QStringLiteral("Start the run at once."));
    const QCommandLineOption speed(
        QStringLiteral("speed"),
        QStringLiteral("Embedded simulator speed (simulated seconds per second)."),
        QStringLiteral("FACTOR"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QStringLiteral("Save a picture of the window to FILE (after --screenshot-after "
                       "seconds) and quit."),
        QStringLiteral("FILE"));
    const QCommandLineOption after(QStringLiteral("screenshot-after"),
                                   QStringLiteral("Seconds before the screenshot (default 5)."),
                                   QStringLiteral("SECONDS"));
    const QCommandLineOption frame_log(
        QStringLiteral("frame-log"),
        QStringLiteral("Log the frame-time statistics every SECONDS to the standard error."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption open_dialog(
        QStringLiteral("open-dialog"),
        QStringLiteral("Open a dialog at start: connect, ir-calibration, umbmark or refilter "
                       "(with --screenshot, the picture is of the dialog)."),
        QStringLiteral("NAME"));
    parser.addOptions({experiment, config, theme, large, start, speed, screenshot, after, frame_log,
                       open_dialog});
    parser.process(app);

    Options options;
    options.experiment = parser.value(experiment);
    options.config = parser.value(config);
    options.theme = parser.value(theme);
    options.large_text = parser.isSet(large);
    options.start = parser.isSet(start);
    options.screenshot = parser.value(screenshot);
    options.open_dialog = parser.value(open_dialog);
    if (!options.open_dialog.isEmpty() && options.open_dialog != QLatin1String("connect")
        && options.open_dialog != QLatin1String("ir-calibration")
        && options.open_dialog != QLatin1String("umbmark")
        && options.open_dialog != QLatin1String("refilter")) {
        std::fprintf(stderr,
                     "legofeup: --open-dialog = %s: expected connect, ir-calibration, umbmark "
                     "or refilter\n",
                     qPrintable(options.open_dialog));
        std::exit(1);
    }
    const auto number = [&](const QCommandLineOption& option, double fallback) {
        if (!parser.isSet(option)) {
            return fallback;
        }
        bool ok = false;
        const double value = parser.value(option).toDouble(&ok);
        if (!ok || value <= 0.0 || value > 1000.0) {
            std::fprintf(stderr, "legofeup: --%s = %s: expected a number in (0, 1000]\n",
                         qPrintable(option.names().front()), qPrintable(parser.value(option)));
            std::exit(1);
        }
        return value;
    };
    options.speed = number(speed, 0.0);
    options.screenshot_after = number(after, 5.0);
    options.frame_log = static_cast<int>(number(frame_log, 0.0));
    if (!options.theme.isEmpty() && options.theme != QLatin1String("system")
        && options.theme != QLatin1String("light") && options.theme != QLatin1String("dark")) {
        std::fprintf(stderr, "legofeup: --theme = %s: expected system, light or dark\n",
                     qPrintable(options.theme));
        std::exit(1);
    }
    return options;
}

/// The configuration to start with: --config, --experiment, the last one used, or f.
legofeup::lessons::RunConfig initial_config(const Options& options, QStringList& notes) {
    namespace lessons = legofeup::lessons;
    if (!options.experiment.isEmpty()) {
        const lessons::Experiment* experiment =
            lessons::find_experiment(options.experiment.toStdString());
        if (experiment == nullptr) {
            std::fprintf(stderr,
                         "legofeup: --experiment = %s: expected a … f or <lesson>:<step> "
                         "(e.g. beacons:a)\n",
                         qPrintable(options.experiment));
            std::exit(1);
        }
        return experiment->config;
    }
    const lessons::RunConfig fallback = lessons::find_experiment("f")->config;
    const QString path =
        options.config.isEmpty() ? legofeup::ui::last_config_path() : options.config;
    if (!QFileInfo::exists(path)) {
        if (!options.config.isEmpty()) {
            std::fprintf(stderr, "legofeup: --config = %s: no such file\n", qPrintable(path));
            std::exit(1);
        }
        return fallback;
    }
    try {
        lessons::RunConfig config = lessons::load_config_file(path.toStdString(), {});
        lessons::resolve(config);
        return config;
    } catch (const lessons::InputError& error) {
        if (!options.config.isEmpty()) {
            std::fprintf(stderr, "legofeup: %s\n", error.what());
            std::exit(1);
        }
        // The last configuration no longer loads (edited by hand?): keep it for the user to
        // repair, start from experiment f, and say so.
        const QString kept = path + QStringLiteral(".bad");
        QFile::remove(kept);
        QFile::rename(path, kept);
        notes << QObject::tr("The last configuration did not load and was kept as %1:\n%2")
                     .arg(kept, QString::fromUtf8(error.what()));
        return fallback;
    }
}

}  // namespace

int main(int argc, char** argv) {
    Q_INIT_RESOURCE(legofeup_ui);  // the icon, built into the static ui library
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("LegoFeup"));
    QApplication::setApplicationName(QStringLiteral("LegoFeup Lab"));
    QApplication::setApplicationVersion(QString::fromLatin1(legofeup::kVersion));
    QApplication::setDesktopFileName(QStringLiteral("legofeup-lab"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/legofeup/legofeup-lab.svg")));
    const Options options = parse(app);

    namespace ui = legofeup::ui;
    const ui::Theme theme = ui::theme_from_name(
        options.theme.isEmpty() ? ui::preferences::kTheme.read() : options.theme);
    if (!options.theme.isEmpty()) {
        ui::preferences::kTheme.write(options.theme);
    }
    ui::apply_appearance(app, theme, 1.0);

    QStringList notes;
    Session session(initial_config(options, notes));
    ui::LinkChoice link = ui::saved_link_choice();
    if (options.speed > 0.0) {
        link.speed = options.speed;
    }
    session.setLinkChoice(link);

    ui::MainWindow window(session);
    // "<lesson>:<step>" names a step of another built-in lesson: show that lesson first, so
    // the run is credited to its own step.
    QString step = !options.experiment.isEmpty() ? options.experiment
                   : options.config.isEmpty()    ? ui::preferences::kExperiment.read()
                                                 : QStringLiteral("f");
    if (const auto colon = step.indexOf(QLatin1Char(':')); colon > 0) {
        window.lessonPanel().useBuiltInLesson(step.left(colon));
        step = step.mid(colon + 1);
    }
    window.lessonPanel().showStep(step);
    if (options.large_text) {
        window.setLargeText(true);
    }
    window.setFrameLogInterval(options.frame_log);
    window.show();
    for (const QString& note : notes) {
        emit session.problem(note);
    }
    if (options.start) {
        QTimer::singleShot(0, &session, &Session::start);
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
        QTimer::singleShot(static_cast<int>(options.screenshot_after * 1000), &window, [&] {
            QWidget* shown = dialog ? dialog.data() : &window;
            const bool saved = shown->grab().save(options.screenshot);
            std::fprintf(stderr, "legofeup: %s %s\n", saved ? "saved" : "could not save",
                         qPrintable(options.screenshot));
            std::fprintf(stderr, "legofeup: frame times (mean/p99/max): %s\n",
                         qPrintable(window.frameTimesText()));
            QApplication::exit(saved ? 0 : 2);
        });
    }
    return QApplication::exec();
}
