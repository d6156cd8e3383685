#include "legofeup/ui/window/command_line.hpp"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QObject>
#include <array>
#include <cmath>
#include <optional>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

/// The values a number-valued option takes: [low, high], whole numbers only if `whole`;
/// `expected` says so in its refusal (%1: low, %2: high).
struct NumberRange {
    double low;
    double high;
    bool whole;
    const char* expected;
};

constexpr double kLongestWait = 1000.0;  // s: --screenshot-after, --frame-log

constexpr NumberRange kSpeedRange{
    kMinSimulatorSpeed, kMaxSimulatorSpeed, false,
    QT_TR_NOOP("expected a number from %1 to %2 (simulated seconds per real second)")};
constexpr NumberRange kScreenshotAfterRange{
    0.0, kLongestWait, false, QT_TR_NOOP("expected a number of seconds from %1 to %2")};
constexpr NumberRange kScreenshotAtRange{
    0.0, 86400.0, false, QT_TR_NOOP("expected a run time in seconds from %1 to %2")};
constexpr NumberRange kFrameLogRange{
    1.0, kLongestWait, true, QT_TR_NOOP("expected a whole number of seconds from %1 to %2")};

constexpr std::array kThemes = {"system", "light", "dark"};
constexpr std::array kDialogs = {"connect", "ir-calibration", "umbmark", "refilter"};

template <std::size_t N>
bool one_of(const QString& value, const std::array<const char*, N>& names) {
    for (const char* name : names) {
        if (value == QLatin1String(name)) {
            return true;
        }
    }
    return false;
}

/// "legofeup: --NAME = VALUE: WHY", the refusal of every option.
CommandLine refused(const QCommandLineOption& option, const QString& value, const QString& why) {
    CommandLine refusal;
    refusal.action = CommandLine::Action::Refuse;
    refusal.text = QObject::tr("legofeup: --%1 = %2: %3")
                       .arg(option.names().constLast(),
                            value.isEmpty() ? QObject::tr("(nothing)") : value, why);
    return refusal;
}

CommandLine refused(const QString& why) {
    CommandLine refusal;
    refusal.action = CommandLine::Action::Refuse;
    refusal.text = QObject::tr("legofeup: %1").arg(why);
    return refusal;
}

/// `text` as a number in `range`, or nullopt.
std::optional<double> number_in(const QString& text, const NumberRange& range) {
    bool ok = false;
    const double value = text.toDouble(&ok);
    // Written so that NaN fails: every comparison with it is false.
    if (!ok || !(value >= range.low && value <= range.high)
        || (range.whole && value != std::floor(value))) {
        return std::nullopt;
    }
    return value;
}

}  // namespace

CommandLine read_command_line(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QObject::tr(
        "LegoFeup Lab: mobile-robot localisation with the Extended Kalman Filter. Without a "
        "display, legofeup-cli runs the same lessons."));
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QObject::tr("Show this help and quit."));
    const QCommandLineOption version({QStringLiteral("v"), QStringLiteral("version")},
                                     QObject::tr("Show the version and quit."));
    const QCommandLineOption experiment(
        QStringLiteral("experiment"),
        QObject::tr("Start with experiment ID: a … h, or <lesson>:<step> (e.g. laser:a)."),
        QStringLiteral("ID"));
    const QCommandLineOption config(
        QStringLiteral("config"),
        QObject::tr("Start with this run configuration (TOML); the Lesson dock shows the step "
                    "it is, or says it is your own."),
        QStringLiteral("FILE"));
    const QCommandLineOption theme(QStringLiteral("theme"), QObject::tr("system, light or dark."),
                                   QStringLiteral("THEME"));
    const QCommandLineOption large(QStringLiteral("large-text"),
                                   QObject::tr("The projector view: larger text."));
    const QCommandLineOption start(QStringLiteral("start"), QObject::tr("Start the run at once."));
    const QCommandLineOption speed(
        QStringLiteral("speed"),
        QObject::tr("Embedded simulator speed: simulated seconds per real second, from %1 to "
                    "%2 (default: the one used last).")
            .arg(kMinSimulatorSpeed)
            .arg(kMaxSimulatorSpeed),
        QStringLiteral("FACTOR"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QObject::tr("Save a picture of the window to FILE (after --screenshot-after seconds) "
                    "and quit."),
        QStringLiteral("FILE"));
    const QCommandLineOption after(QStringLiteral("screenshot-after"),
                                   QObject::tr("Seconds before the screenshot (default 5)."),
                                   QStringLiteral("SECONDS"));
    const QCommandLineOption at(
        QStringLiteral("screenshot-at"),
        QObject::tr("Take the picture when the run reaches SECONDS of run time (the status "
                    "bar's t), or at its end if it ends sooner: the same moment of the run "
                    "however busy the machine is. Needs --start; instead of "
                    "--screenshot-after."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption frame_log(
        QStringLiteral("frame-log"),
        QObject::tr("Log the frame-time statistics every SECONDS to the standard error."),
        QStringLiteral("SECONDS"));
    const QCommandLineOption open_dialog(
        QStringLiteral("open-dialog"),
        QObject::tr("Open a dialog at start: connect, ir-calibration, umbmark or refilter (with "
                    "--screenshot, the picture is of the dialog)."),
        QStringLiteral("NAME"));
    parser.addOptions({help, version, experiment, config, theme, large, start, speed, screenshot,
                       after, at, frame_log, open_dialog});

    const bool parsed = parser.parse(arguments);
    // Help and version whatever else is wrong: they are what a lost user types.
    if (parser.isSet(help)) {
        QString text = parser.helpText();
        text = QObject::tr("Usage: legofeup [options]") + text.mid(text.indexOf(QLatin1Char('\n')));
        return {CommandLine::Action::Help, {}, text};
    }
    if (parser.isSet(version)) {
        return {CommandLine::Action::Version,
                {},
                QCoreApplication::applicationName() + QLatin1Char(' ')
                    + QCoreApplication::applicationVersion()};
    }
    if (!parsed) {
        return refused(
            QObject::tr("%1 (legofeup --help lists the options)").arg(parser.errorText()));
    }
    if (!parser.positionalArguments().isEmpty()) {
        return refused(QObject::tr("unexpected argument %1: legofeup takes options only (a "
                                   "configuration file is given with --config FILE)")
                           .arg(parser.positionalArguments().constFirst()));
    }

    CommandLine command_line;
    StartOptions& options = command_line.options;
    options.experiment = parser.value(experiment);
    options.config = parser.value(config);
    options.theme = parser.value(theme);
    options.large_text = parser.isSet(large);
    options.start = parser.isSet(start);
    options.screenshot = parser.value(screenshot);
    options.open_dialog = parser.value(open_dialog);
    if (parser.isSet(experiment) && parser.isSet(config)) {
        return refused(
            QObject::tr("--experiment and --config both give the configuration to "
                        "start with: give one of them"));
    }
    if (parser.isSet(experiment)
        && lessons::find_experiment(options.experiment.toStdString()) == nullptr) {
        return refused(experiment, options.experiment,
                       QObject::tr("expected a … h or <lesson>:<step> (e.g. beacons:a)"));
    }
    if (parser.isSet(theme) && !one_of(options.theme, kThemes)) {
        return refused(theme, options.theme, QObject::tr("expected system, light or dark"));
    }
    if (parser.isSet(open_dialog) && !one_of(options.open_dialog, kDialogs)) {
        return refused(open_dialog, options.open_dialog,
                       QObject::tr("expected connect, ir-calibration, umbmark or refilter"));
    }
    if (parser.isSet(at) && parser.isSet(after)) {
        return refused(
            QObject::tr("--screenshot-at and --screenshot-after both say when to take "
                        "the picture: give one of them"));
    }
    if (parser.isSet(at) && !parser.isSet(start)) {
        return refused(QObject::tr(
            "--screenshot-at needs --start: without a run, no run time is ever reached"));
    }
    struct NumberOption {
        const QCommandLineOption* option;
        const NumberRange* range;
        double* value;
    };
    double frame_log_seconds = 0.0;
    double screenshot_at = 0.0;
    for (const NumberOption& number :
         {NumberOption{&speed, &kSpeedRange, &options.speed},
          NumberOption{&after, &kScreenshotAfterRange, &options.screenshot_after},
          NumberOption{&at, &kScreenshotAtRange, &screenshot_at},
          NumberOption{&frame_log, &kFrameLogRange, &frame_log_seconds}}) {
        if (!parser.isSet(*number.option)) {
            continue;
        }
        const QString text = parser.value(*number.option);
        const std::optional<double> value = number_in(text, *number.range);
        if (!value) {
            return refused(
                *number.option, text,
                QObject::tr(number.range->expected).arg(number.range->low).arg(number.range->high));
        }
        *number.value = *value;
    }
    options.frame_log = static_cast<int>(frame_log_seconds);
    if (parser.isSet(at)) {
        options.screenshot_at = screenshot_at;
    }
    return command_line;
}

}  // namespace legofeup::ui
