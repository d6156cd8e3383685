// The Lesson dock in the window, driven as students drive it (QtTest, offscreen): the steps
// and their states, a step's conclusion hidden until its run finished (the checks then judged
// on the run shown, even one tuned half-way, not on a re-run), answers saved, reopened and kept
// across restarts, the report exported, a teacher's lesson opened and a broken one refused.

#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "legofeup/lessons/grading.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/submission.hpp"
#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/lesson/lesson_actions.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/lesson/shown_run.hpp"
#include "legofeup/ui/lesson/step_view.hpp"
#include "legofeup/ui/session/run_samples.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "support/modal.hpp"
#include "support/screenshot.hpp"
#include "support/short_run.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr int kPatienceMs = 30000;

using testing::short_run;

/// A run long enough to be tuned half-way by a test polling every few milliseconds.
constexpr double kTunedRunSeconds = 8.0;
/// Shares of steps that differ by more than this are told apart (one step in 160 is 0.006).
constexpr double kDistinct = 0.1;

/// √(mean |x̂ − x|²) over the steps with a truth: the position error, by hand.
double rms_position_error(const std::vector<StepRecord>& steps_shown) {
    double sum = 0.0;
    int steps = 0;
    for (const StepRecord& step : steps_shown) {
        if (step.has_truth) {
            const double dx = step.estimate.x - step.truth.x;
            const double dy = step.estimate.y - step.truth.y;
            sum += dx * dx + dy * dy;
            ++steps;
        }
    }
    return std::sqrt(sum / steps);
}

/// Share of the steps with a truth whose NEES lies in χ²(3)'s 95 % interval, by hand.
double inside_fraction(const std::vector<StepRecord>& steps_shown) {
    constexpr double kLower = 0.2158;  // χ²(3) at 2.5 % and 97.5 % (tables)
    constexpr double kUpper = 9.3484;
    int inside = 0;
    int steps = 0;
    for (const StepRecord& step : steps_shown) {
        if (step.has_truth) {
            inside += step.nees >= kLower && step.nees <= kUpper ? 1 : 0;
            ++steps;
        }
    }
    return static_cast<double>(inside) / steps;
}

void write_file(const QString& path, const QByteArray& text) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

QByteArray read_file(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// A teacher's two-step lesson.
const char* kTeacherLesson =
    "id = \"teacher\"\n"
    "title = \"A teacher's lesson\"\n"
    "goals = \"See R at work.\"\n"
    "\n"
    "[[step]]\n"
    "id = \"one\"\n"
    "title = \"Trust the walls\"\n"
    "instructions = \"Set **R** very low.\"\n"
    "observe = \"The estimate jumps.\"\n"
    "expectation = \"It follows every reading.\"\n"
    "[[step.question]]\n"
    "id = \"q1\"\n"
    "text = \"What happens at the walls?\"\n"
    "[[step.check]]\n"
    "expression = \"updates_applied > 0\"\n"
    "description = \"The walls were used.\"\n"
    "[step.config.filter]\n"
    "r11 = 1e-8\n"
    "\n"
    "[[step]]\n"
    "id = \"two\"\n"
    "title = \"Ignore the walls\"\n"
    "instructions = \"Set R very high.\"\n"
    "observe = \"Nothing happens.\"\n"
    "expectation = \"It behaves like odometry.\"\n";

}  // namespace

class LessonPanelTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<MainWindow> window_;

    LessonPanel& panel() { return window_->lessonPanel(); }
    QListWidget& steps() {
        return *window_->findChild<QListWidget*>(QStringLiteral("lessonSteps"));
    }

    void openWindow() {
        session_ = std::make_unique<Session>(lessons::legofeup_lesson().steps.back().config);
        LinkChoice fast;
        fast.speed = 10.0;
        session_->setLinkChoice(fast);
        window_ = std::make_unique<MainWindow>(*session_);
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    /// Runs step `id` from its preset, cut short, and waits until its outcome is shown.
    void runShortStep(const QString& id) {
        QVERIFY(panel().showStep(id));
        const lessons::LessonStep* step = panel().progress().lesson().find_step(id.toStdString());
        QVERIFY(session_->setConfig(short_run(step->config)).isEmpty());
        QSignalSpy shown(&panel(), &LessonPanel::stepOutcomeShown);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(!shown.isEmpty(), kPatienceMs);
        QCOMPARE(shown.front().front().toString(), id);
    }

    void type(QWidget* field, const QString& text) {
        QVERIFY(field != nullptr);
        field->setFocus();
        QTest::keyClicks(field, text);
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Lesson Test"));
    }

    void init() {
        QSettings().clear();
        openWindow();
    }

    void cleanup() {
        window_.reset();
        session_.reset();
    }

    void theBuiltInLessonsStepsAreListedAsNotRun() {
        const lessons::Lesson& lesson = lessons::legofeup_lesson();
        QCOMPARE(steps().count(), static_cast<int>(lesson.steps.size()));
        QCOMPARE(steps().count(), 8);  // a–f and the bump of g–h
        for (int row = 0; row < steps().count(); ++row) {
            const lessons::LessonStep& step = lesson.steps[static_cast<std::size_t>(row)];
            const QString text = steps().item(row)->text();
            QCOMPARE(text, QString::fromStdString("○  " + step.id + ") " + step.title));
            QCOMPARE(steps().item(row)->toolTip(), QStringLiteral("○ not run"));
        }
        QCOMPARE(panel().progress().lesson().id, std::string("legofeup"));
        // Picking a step shows its texts and questions without touching the configuration.
        const double r11 = session_->config().filter.r11;
        steps().setCurrentRow(1);
        QCOMPARE(panel().currentStep(), QStringLiteral("b"));
        QCOMPARE(session_->config().filter.r11, r11);
        QVERIFY(panel().instructions().contains(QStringLiteral("uses the walls")));
        QVERIFY(panel().stepView().answerBox("q1") != nullptr);
        QVERIFY(!panel().stepView().expectationShown());
    }

    void theConclusionIsHiddenUntilTheRunFinishesThenShownWithTheRunsOwnNumbers() {
        const lessons::Lesson& lesson = lessons::legofeup_lesson();
        const lessons::LessonStep& step = *lesson.find_step("b");
        QVERIFY(panel().showStep(QStringLiteral("b")));
        auto* expectation = window_->findChild<QLabel*>(QStringLiteral("stepExpectation"));
        auto* locked = window_->findChild<QLabel*>(QStringLiteral("stepExpectationLocked"));
        QVERIFY(!panel().stepView().expectationShown());
        QVERIFY(expectation->isHidden());
        QVERIFY(locked->isVisible());
        save_screenshot_of_panel("lesson-panel-before", locked);

        // A run stopped before its routine's end does not count.
        QVERIFY(session_->setConfig(step.config).isEmpty());
        session_->start();
        QTRY_COMPARE_WITH_TIMEOUT(panel().progress().state("b"), StepState::Running, kPatienceMs);
        QVERIFY(steps().item(1)->text().startsWith(QStringLiteral("▶")));
        QCOMPARE(steps().item(1)->toolTip(), QStringLiteral("▶ running…"));
        session_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        QCOMPARE(panel().progress().state("b"), StepState::NotRun);
        QVERIFY(!panel().stepView().expectationShown());

        runShortStep(QStringLiteral("b"));
        QCOMPARE(panel().progress().state("b"), StepState::Done);
        QVERIFY(panel().stepView().expectationShown());
        QVERIFY(locked->isHidden());
        QCOMPARE(expectation->text(), QString::fromStdString(step.expectation));
        const report::StepOutcome* outcome = panel().progress().outcome("b");
        QVERIFY(outcome != nullptr);
        QCOMPARE(outcome->checks.size(), step.checks.size());
        const auto [passed, total] = panel().progress().checksPassed("b");
        QVERIFY2(
            steps().item(1)->text().contains(QStringLiteral("checks %1/%2").arg(passed).arg(total)),
            qPrintable(steps().item(1)->text()));
        const QString checks = window_->findChild<QLabel*>(QStringLiteral("stepChecks"))->text();
        QCOMPARE(checks.count(QStringLiteral("passed")) + checks.count(QStringLiteral("failed")),
                 total);

        // The numbers are the run shown's: every step the window drew, measured by hand.
        QCOMPARE(outcome->metrics["steps"].get<std::size_t>(), session_->history().size());
        QCOMPARE(outcome->metrics["rms_position_error_m"].get<double>(),
                 rms_position_error(session_->history().records()));
        // Another step is still folded.
        QVERIFY(panel().showStep(QStringLiteral("c")));
        QVERIFY(!panel().stepView().expectationShown());
        QVERIFY(panel().showStep(QStringLiteral("b")));
        QVERIFY(panel().stepView().expectationShown());
        if (!qEnvironmentVariableIsEmpty("LEGOFEUP_SCREENSHOTS")) {
            // For the documentation: the whole step (two laps, 17 s at 10×), an answer typed.
            QSignalSpy shown(&panel(), &LessonPanel::stepOutcomeShown);
            panel().applyAndRun();
            QTRY_VERIFY_WITH_TIMEOUT(!shown.isEmpty(), 4 * kPatienceMs);
            type(window_->findChild<QLineEdit*>(QStringLiteral("studentNames")),
                 QStringLiteral("Ana Silva, Rui Costa"));
            type(panel().stepView().answerBox("q1"),
                 QStringLiteral("It snaps onto the wall and the ellipse collapses across it."));
            save_screenshot_of_panel("lesson-panel", expectation);
        }
    }

    void aStepTunedHalfWayIsJudgedOnTheRunShownNotOnAReRunOfItsLastTuning() {
        // Step f for 8 s in a straight line, its Q made a million times smaller half-way (step
        // d's 1e-12: the filter stops believing it can drift). Slow enough (2×) to change it
        // near the middle.
        const lessons::LessonStep& step = *lessons::legofeup_lesson().find_step("f");
        QVERIFY(panel().showStep(QStringLiteral("f")));
        lessons::RunConfig config = short_run(step.config);
        config.duration = kTunedRunSeconds;
        QVERIFY(session_->setConfig(config).isEmpty());
        LinkChoice slower = session_->linkChoice();
        slower.speed = 2.0;
        session_->setLinkChoice(slower);
        QSignalSpy shown(&panel(), &LessonPanel::stepOutcomeShown);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(
            !session_->history().empty()
                && session_->history().latest().snapshot.time >= kTunedRunSeconds / 2,
            kPatienceMs);
        const double tuned_at = session_->history().latest().snapshot.time;
        QVERIFY2(tuned_at < 0.75 * kTunedRunSeconds, qPrintable(QString::number(tuned_at)));
        lessons::RunConfig tuned = session_->config();
        tuned.filter.q11 = 1e-12;
        tuned.filter.q22 = 1e-12;
        QVERIFY(session_->setConfig(tuned).isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(!shown.isEmpty(), kPatienceMs);
        QCOMPARE(panel().progress().state("f"), StepState::Done);

        // The run shown, measured by hand from the window's own history…
        const std::vector<StepRecord>& steps = session_->history().records();
        const double shown_rms = rms_position_error(steps);
        const double shown_inside = inside_fraction(steps);
        // …and what a lockstep re-run of the configuration it ended with gives.
        const report::StepOutcome rerun = report::run_step(step, session_->config());
        const double rerun_inside = rerun.metrics["nees_inside_fraction"].get<double>();
        qInfo("tuned at %.2f s; NEES inside fraction: shown %.4f, re-run %.4f; rms %.4f vs %.4f",
              tuned_at, shown_inside, rerun_inside, shown_rms,
              rerun.metrics["rms_position_error_m"].get<double>());
        QVERIFY2(std::abs(shown_inside - rerun_inside) > kDistinct,
                 qPrintable(QStringLiteral("%1 vs %2").arg(shown_inside).arg(rerun_inside)));

        // The panel judged the run shown.
        const report::StepOutcome* outcome = panel().progress().outcome("f");
        QVERIFY(outcome != nullptr);
        QCOMPARE(outcome->metrics["steps"].get<std::size_t>(), steps.size());
        QCOMPARE(outcome->metrics["rms_position_error_m"].get<double>(), shown_rms);
        QCOMPARE(outcome->metrics["nees_inside_fraction"].get<double>(), shown_inside);
        const QString checks = window_->findChild<QLabel*>(QStringLiteral("stepChecks"))->text();
        const auto shown_text =
            QStringLiteral("nees_inside_fraction = %1").arg(QString::number(shown_inside, 'g', 4));
        QVERIFY2(checks.contains(shown_text), qPrintable(checks));
        QVERIFY2(!checks.contains(QStringLiteral("nees_inside_fraction = %1")
                                      .arg(QString::number(rerun_inside, 'g', 4))),
                 qPrintable(checks));
        QVERIFY2(checks.contains(QStringLiteral("Judged on the run shown")), qPrintable(checks));
    }

    void aRunWithoutTheTruePoseSaysWhichChecksItCannotJudge() {
        // Step a cut short, its truth withheld as a real NXT's link withholds it: its check on
        // updates_applied is judged, the one on final_position_error_m cannot be.
        const lessons::Lesson& lesson = lessons::legofeup_lesson();
        const lessons::LessonStep& step = *lesson.find_step("a");
        SampleCollector collector;
        lessons::run_lockstep(lessons::resolve(short_run(step.config)), &collector);
        ShownRun shown;
        for (RunSample sample : collector.take()) {
            sample.truth.reset();
            shown.add(sample);
        }
        LessonProgress progress(lesson);
        progress.setOutcome(shown.outcome(step, step.config, sim::WorldSpec{}));
        StepView view;
        view.resize(430, 900);
        view.showStep(step, progress);
        view.show();
        const QString checks = view.findChild<QLabel*>(QStringLiteral("stepChecks"))->text();
        QCOMPARE(checks.count(QStringLiteral("not judged")), 1);
        QVERIFY2(checks.contains(QStringLiteral("This check needs the true pose, which the NXT "
                                                "does not give")),
                 qPrintable(checks));
        QCOMPARE(checks.count(QStringLiteral("✓ passed")), 1);
        QCOMPARE(checks.count(QStringLiteral("failed")), 0);
        QCOMPARE(step_state_text(progress, "a"),
                 QStringLiteral("✓ done · checks 1/1 · 1 not judged"));
        testing::save_screenshot(view, "lesson-checks-without-truth");
    }

    void applyAndRunAppliesThePresetAndStartsTheStep() {
        QVERIFY(panel().showStep(QStringLiteral("a")));
        window_->findChild<QPushButton*>(QStringLiteral("applyAndRun"))->click();
        QVERIFY(!session_->config().filter.wall_updates);  // step a: odometry only
        QCOMPARE(session_->phase(), RunPhase::Connecting);
        QCOMPARE(panel().progress().state("a"), StepState::Running);
        session_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
    }

    void answersRoundTripThroughSaveAndOpenAndSurviveARestart() {
        QTemporaryDir out;
        type(window_->findChild<QLineEdit*>(QStringLiteral("studentNames")),
             QStringLiteral("Ana Silva, Rui Costa"));
        QVERIFY(panel().showStep(QStringLiteral("a")));
        type(panel().stepView().answerBox("q1"), QStringLiteral("It grows, lap after lap."));
        QVERIFY(panel().showStep(QStringLiteral("f")));
        type(panel().stepView().answerBox("q1"), QStringLiteral("Q = 3e-7 worked best."));
        // The tuning is the graded step's settings as the configuration panel has them.
        QVERIFY(session_->setConfig(lessons::legofeup_lesson().find_step("f")->config).isEmpty());
        lessons::RunConfig tuned = session_->config();
        tuned.filter.q11 = 3e-7;
        QVERIFY(session_->setConfig(tuned).isEmpty());

        const QString path = out.filePath(QStringLiteral("answers.toml"));
        QCOMPARE(panel().saveAnswers(path), QString());
        const lessons::Submission saved =
            lessons::load_submission_file(path.toStdString(), lessons::legofeup_lesson());
        QCOMPARE(saved.students, std::string("Ana Silva, Rui Costa"));
        QCOMPARE(saved.answers.at("a").at("q1"), std::string("It grows, lap after lap."));
        QCOMPARE(saved.tuned.filter.q11, 3e-7);

        // Wiped, then opened again: every box comes back.
        panel().stepView().answerBox("q1")->clear();
        window_->findChild<QLineEdit*>(QStringLiteral("studentNames"))->clear();
        QCOMPARE(panel().openAnswers(path), QString());
        QCOMPARE(window_->findChild<QLineEdit*>(QStringLiteral("studentNames"))->text(),
                 QStringLiteral("Ana Silva, Rui Costa"));
        QCOMPARE(panel().stepView().answerBox("q1")->toPlainText(),
                 QStringLiteral("Q = 3e-7 worked best."));
        QVERIFY(panel().showStep(QStringLiteral("a")));
        QCOMPARE(panel().stepView().answerBox("q1")->toPlainText(),
                 QStringLiteral("It grows, lap after lap."));

        // Answers of another lesson are refused with the file's line.
        write_file(out.filePath(QStringLiteral("other.toml")),
                   "lesson = \"other\"\nstudents = \"X\"\n");
        const QString refused = panel().openAnswers(out.filePath(QStringLiteral("other.toml")));
        QVERIFY2(refused.contains(QStringLiteral("other.toml:1")), qPrintable(refused));

        // Kept as typed: a new window (the application restarted) has them all.
        type(panel().stepView().answerBox("q2"), QStringLiteral("Typed just before a crash."));
        // Kept with the preferences a moment after typing, before anything is closed.
        QTRY_VERIFY(QSettings()
                        .value(QStringLiteral("answers/legofeup"))
                        .toMap()
                        .value(QStringLiteral("a/q2"))
                        .toString()
                        .contains(QStringLiteral("crash")));
        window_->close();
        cleanup();
        openWindow();
        QCOMPARE(window_->findChild<QLineEdit*>(QStringLiteral("studentNames"))->text(),
                 QStringLiteral("Ana Silva, Rui Costa"));
        QCOMPARE(panel().progress().answer("a", "q2"), std::string("Typed just before a crash."));
        QCOMPARE(panel().progress().answer("f", "q1"), std::string("Q = 3e-7 worked best."));
    }

    void theExportedReportHasTheStepRunAndTheAnswersInHtmlAndPdf() {
        type(window_->findChild<QLineEdit*>(QStringLiteral("studentNames")),
             QStringLiteral("Ana Silva"));
        runShortStep(QStringLiteral("c"));
        type(panel().stepView().answerBox("q1"), QStringLiteral("Every reading pulls it."));
        QTemporaryDir out;
        QCOMPARE(panel().exportReport(out.path()), QString());
        const QByteArray html = read_file(out.filePath(QStringLiteral("report.html")));
        const QByteArray pdf = read_file(out.filePath(QStringLiteral("report.pdf")));
        QVERIFY(html.contains("Ana Silva"));
        QVERIFY(html.contains("Every reading pulls it."));
        QVERIFY(html.contains("<svg"));  // the run's plots, inline
        QVERIFY(pdf.startsWith("%PDF"));
        QVERIFY(pdf.size() > 10000);
        // A folder that cannot be made (under a plain file): refused with the reason.
        const QString blocked = out.filePath(QStringLiteral("report.html/inside"));
        QCOMPARE(panel().exportReport(blocked).isEmpty(), false);
    }

    void theFileMenusExportWritesOnAWorkerAndSaysWhenItIsDone() {
        type(window_->findChild<QLineEdit*>(QStringLiteral("studentNames")),
             QStringLiteral("Rui Costa"));
        runShortStep(QStringLiteral("b"));
        auto* actions = window_->findChild<LessonActions*>();
        QVERIFY(actions != nullptr);
        QTemporaryDir out;
        QSignalSpy exported(actions, &LessonActions::reportExported);
        QSignalSpy notes(actions, &LessonActions::done);
        QVERIFY(actions->exportReportTo(out.path()));
        // The call returned at once: the worker writes, the window answers meanwhile.
        QVERIFY(exported.isEmpty());
        QVERIFY(actions->exporting());
        QVERIFY(!actions->exportReportTo(out.path()));  // one report at a time
        QVERIFY(exported.wait(60000));
        QCOMPARE(exported.takeFirst().at(0).toString(), QString());
        QVERIFY(!actions->exporting());
        QVERIFY(notes.last().at(0).toString().contains(QStringLiteral("Wrote report.html")));
        QVERIFY(read_file(out.filePath(QStringLiteral("report.html"))).contains("Rui Costa"));
        QVERIFY(read_file(out.filePath(QStringLiteral("report.pdf"))).startsWith("%PDF"));

        // A folder that cannot be made: the warning names it, nothing is left half-written.
        const QString blocked = out.filePath(QStringLiteral("report.html/inside"));
        QString warning;
        testing::answer_modals([&warning](QWidget& modal) {
            auto* box = qobject_cast<QMessageBox*>(&modal);
            if (box == nullptr) {
                return false;
            }
            warning = box->informativeText();
            box->accept();
            return true;
        });
        QVERIFY(actions->exportReportTo(blocked));
        QVERIFY(exported.wait(60000));
        QVERIFY(!exported.takeFirst().at(0).toString().isEmpty());
        QTRY_VERIFY(!warning.isEmpty());
        QVERIFY2(warning.contains(QStringLiteral("inside")), qPrintable(warning));
    }

    void aTeachersLessonOpensAndABrokenOneIsRefusedWithItsLine() {
        QTemporaryDir out;
        const QString good = out.filePath(QStringLiteral("teacher.toml"));
        write_file(good, kTeacherLesson);
        QCOMPARE(panel().openLesson(good), QString());
        QCOMPARE(steps().count(), 2);
        QCOMPARE(steps().item(0)->text(), QStringLiteral("○  one) Trust the walls"));
        QCOMPARE(panel().progress().lesson().id, std::string("teacher"));

        // A check on a metric that does not exist, on line 15: refused through the File menu
        // with a message box naming the file and line; the teacher's lesson stays.
        QByteArray broken = kTeacherLesson;
        broken.replace("updates_applied > 0", "updates_aplied > 0");
        const QString bad = out.filePath(QStringLiteral("broken.toml"));
        write_file(bad, broken);
        preferences::kLessonFolder.write(out.path());  // where the file dialog opens
        QString shown;
        testing::answer_modals([&](QWidget& modal) {
            if (auto* files = qobject_cast<QFileDialog*>(&modal)) {
                // Typed, as selectFile() leaves a focused name field alone.
                files->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(bad);
                QMetaObject::invokeMethod(files, "accept");
            } else if (auto* box = qobject_cast<QMessageBox*>(&modal)) {
                shown = box->informativeText();
                box->accept();
                return true;
            }
            return false;
        });
        window_->lessonActions().openLesson();
        QVERIFY2(shown.contains(QStringLiteral("broken.toml:15")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral("updates_aplied")), qPrintable(shown));
        QCOMPARE(panel().progress().lesson().id, std::string("teacher"));
        QCOMPARE(steps().count(), 2);

        // Back to the built-in lesson from the lesson box.
        panel().useBuiltInLesson();
        QCOMPARE(steps().count(), 8);  // a–f and the bump of g–h
    }

  private:
    /// The window as on a 1600 × 1000 projector, the lesson's step scrolled to `shown`.
    void save_screenshot_of_panel(const char* name, QWidget* shown) {
        if (qEnvironmentVariableIsEmpty("LEGOFEUP_SCREENSHOTS")) {
            return;
        }
        window_->resizeDocks({window_->findChild<QDockWidget*>(QStringLiteral("lessonDock")),
                              window_->findChild<QDockWidget*>(QStringLiteral("configDock"))},
                             {430, 330}, Qt::Horizontal);
        window_->resizeDocks({window_->findChild<QDockWidget*>(QStringLiteral("lessonDock"))},
                             {760}, Qt::Vertical);
        QTest::qWait(50);
        window_->findChild<QScrollArea*>(QStringLiteral("stepScroll"))->ensureWidgetVisible(shown);
        QTest::qWait(50);
        testing::save_screenshot(*window_, name);
    }
};

QTEST_MAIN(LessonPanelTest)
#include "test_lesson_panel.moc"
