// The window as `legofeup` starts it from its command line (QtTest, offscreen), built the way
// app/gui/main.cpp builds it: --speed 4 is the toolbar's speed and the simulator's, and
// --config is credited to the step the configuration is — a laser configuration never to
// LegoFeup step f, step f's own configuration to step f — or, being no step's, to none.

#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <fstream>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/lesson/step_run_tracker.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/command_line.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"
#include "legofeup/ui/window/start_up.hpp"
#include "support/short_run.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr int kPatienceMs = 30000;

using testing::short_run;

/// Least-squares slope of y over x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const auto n = static_cast<double>(x.size());
    double sx = 0.0;
    double sy = 0.0;
    double sxx = 0.0;
    double sxy = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

class StartUpTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;
    QTemporaryDir files_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<MainWindow> window_;

    /// Starts the window as main.cpp does with `arguments` (after the program's name).
    void startWith(const QStringList& arguments) {
        const CommandLine command_line =
            read_command_line(QStringList{QStringLiteral("legofeup")} + arguments);
        QCOMPARE(command_line.action, CommandLine::Action::Start);
        const StartConfig start = initial_config(command_line.options);
        QVERIFY2(start.config.has_value(), qPrintable(start.refusal));
        session_ = std::make_unique<Session>(*start.config);
        session_->setLinkChoice(initial_link(command_line.options));
        window_ = std::make_unique<MainWindow>(*session_);
        shown_as_a_step_ = show_initial_step(window_->lessonPanel(), command_line.options);
        window_->resize(1400, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }
    bool shown_as_a_step_ = false;

    /// Writes `config` as `legofeup-cli config` would, to `name`, and starts the window with
    /// `--config name --speed 10`.
    void startWithConfig(const char* name, const lessons::RunConfig& config) {
        const QString path = files_.filePath(QString::fromLatin1(name));
        std::ofstream(path.toStdString()) << lessons::config_to_toml(config, name);
        startWith(
            {QStringLiteral("--config"), path, QStringLiteral("--speed"), QStringLiteral("10")});
    }

    /// The dock shows `step` of `lesson`, the configuration being its.
    void verifyShown(const char* lesson, const char* step) {
        QCOMPARE(progress().lesson().id, std::string(lesson));
        QCOMPARE(panel().currentStep(), QString::fromLatin1(step));
        QVERIFY(ownerNote().isHidden());
    }

    LessonPanel& panel() { return window_->lessonPanel(); }
    const LessonProgress& progress() { return panel().progress(); }
    QLabel& ownerNote() {
        return *window_->findChild<QLabel*>(QStringLiteral("configurationOwner"));
    }

    void verifyShownAsOwn() {
        QVERIFY(ownerNote().isVisible());
        QVERIFY2(ownerNote().text().startsWith(QStringLiteral("Own configuration")),
                 qPrintable(ownerNote().text()));
    }

    /// Runs the configuration to its routine's end, counted for no step: none running from
    /// the start (the tracker takes the run's step at Connecting), none judged at Finished
    /// (where the tracker would judge it at once).
    void runCountedForNoStep() {
        session_->start();
        QCOMPARE(session_->phase(), RunPhase::Connecting);
        QVERIFY(panel().tracker().runningStep().empty());
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Finished, kPatienceMs);
        for (const lessons::LessonStep& step : progress().lesson().steps) {
            QCOMPARE(progress().state(step.id), StepState::NotRun);
            QVERIFY(progress().outcome(step.id) == nullptr);
        }
    }

    /// Runs the configuration to its end, counted for `step`: running, then done.
    void runCountedFor(const char* step) {
        QSignalSpy outcome(&panel(), &LessonPanel::stepOutcomeShown);
        session_->start();
        QCOMPARE(session_->phase(), RunPhase::Connecting);
        QCOMPARE(progress().state(step), StepState::Running);
        QTRY_VERIFY_WITH_TIMEOUT(!outcome.isEmpty(), kPatienceMs);
        QCOMPARE(outcome.front().front().toString(), QString::fromLatin1(step));
        QCOMPARE(progress().state(step), StepState::Done);
        QVERIFY(progress().outcome(step) != nullptr);
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        QVERIFY(files_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Start-up Test"));
    }

    void init() { QSettings().clear(); }

    void cleanup() {
        window_.reset();
        session_.reset();
    }

    void aSpeedOutsideTheToolbarsListIsAddedSelectedAndRunAt() {
        startWith({QStringLiteral("--speed"), QStringLiteral("4")});
        QComboBox& speeds = *window_->runToolBar().speedChoice();
        QCOMPARE(speeds.currentText(), QStringLiteral("4×"));
        QCOMPARE(speeds.currentData().toDouble(), 4.0);
        QStringList offered;
        for (int i = 0; i < speeds.count(); ++i) {
            offered << speeds.itemText(i);
        }
        QCOMPARE(offered,
                 (QStringList{QStringLiteral("0.5×"), QStringLiteral("1×"), QStringLiteral("2×"),
                              QStringLiteral("4×"), QStringLiteral("5×"), QStringLiteral("10×")}));
        // The toolbar, built after the link was chosen, left the session at 4 (it once put
        // every speed it did not list back to its first, 0.5).
        QCOMPARE(session_->linkChoice().speed, 4.0);

        // The simulator runs at it: simulated time over real time, fitted over 2 s of the
        // run, is 4 — not 0.5, 1, 2, 5 or 10. A busy machine only slows it, hence the
        // wider margin below.
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(session_->status().time > 0.5, kPatienceMs);
        std::vector<double> real;
        std::vector<double> simulated;
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 2000) {
            QTest::qWait(20);
            real.push_back(static_cast<double>(clock.elapsed()) / 1000.0);
            simulated.push_back(session_->status().time);
        }
        session_->stop();
        const double speed = slope(real, simulated);
        qInfo("simulated seconds per real second: %.3f", speed);
        QVERIFY2(speed > 2.8 && speed < 4.5, qPrintable(QString::number(speed)));
    }

    void aSpeedTheToolbarListsIsSelectedAndNothingAdded() {
        startWith({QStringLiteral("--speed"), QStringLiteral("5")});
        QComboBox& speeds = *window_->runToolBar().speedChoice();
        QCOMPARE(speeds.count(), 5);
        QCOMPARE(speeds.currentText(), QStringLiteral("5×"));
        QCOMPARE(session_->linkChoice().speed, 5.0);
    }

    void aLaserConfigurationIsNeverCreditedToLegoFeupStepF() {
        startWithConfig("laser-config.toml",
                        short_run(lessons::find_experiment("laser:a")->config));
        // The step it came from is shown: the laser lesson's a.
        QVERIFY(shown_as_a_step_);
        verifyShown("laser", "a");

        // Showing LegoFeup step f by hand: the dock says the configuration is not its, and
        // a run counts for no step — not running, not checked, no outcome.
        panel().useBuiltInLesson(QStringLiteral("legofeup"));
        QVERIFY(panel().showStep(QStringLiteral("f")));
        verifyShownAsOwn();
        for (const char* key : {"world", "localisation.method", "laser_scanner.enabled"}) {
            QVERIFY2(ownerNote().text().contains(QLatin1String(key)), key);
        }
        runCountedForNoStep();

        // In its own lesson, step b (a kidnapping) is another experiment: the note names
        // the step it is. Step a is credited with the run.
        panel().useBuiltInLesson(QStringLiteral("laser"));
        QVERIFY(panel().showStep(QStringLiteral("b")));
        QVERIFY(ownerNote().isVisible());
        QCOMPARE(ownerNote().text(),
                 QStringLiteral("The configuration is step a's, not step b's (it differs from "
                                "its preset in kidnap.enabled): its runs count for no step "
                                "while step b is shown."));
        QVERIFY(panel().showStep(QStringLiteral("a")));
        QVERIFY(ownerNote().isHidden());
        runCountedFor("a");
    }

    void stepFsOwnConfigurationIsCreditedToStepF() {
        // The same start with step f's configuration (the other case the test must tell
        // apart), the laser lesson shown last: LegoFeup step f shown, running, then done.
        preferences::kLessonFile.write(QStringLiteral("builtin:laser"));
        startWithConfig("f-config.toml", short_run(lessons::find_experiment("f")->config));
        QVERIFY(shown_as_a_step_);
        verifyShown("legofeup", "f");
        runCountedFor("f");
    }

    void aConfigurationOfNoStepIsShownAsOwnAndCreditedToNone() {
        lessons::RunConfig own = short_run(lessons::find_experiment("laser:a")->config);
        own.world_file.clear();  // the laser scanner, but the arena and its walls
        own.lesson.localisation = Localisation::Walls;
        startWithConfig("own.toml", own);
        QVERIFY(!shown_as_a_step_);
        verifyShownAsOwn();
        runCountedForNoStep();
    }

    void anExperimentOfTheLegoFeupLessonShowsThatLessonWhicheverWasShownLast() {
        preferences::kLessonFile.write(QStringLiteral("builtin:beacons"));
        startWith({QStringLiteral("--experiment"), QStringLiteral("c")});
        verifyShown("legofeup", "c");
    }
};

QTEST_MAIN(StartUpTest)
#include "test_start_up.moc"
