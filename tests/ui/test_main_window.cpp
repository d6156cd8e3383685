// The whole window, driven as a student would drive it (QtTest, offscreen): start a run,
// change R while it runs and see the filter respond, switch presets, have a bad entry
// refused, drive with the keyboard, export the plots and the trace, keep the settings.

#include <Eigen/Eigenvalues>
#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <limits>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/panels/config_panel.hpp"
#include "legofeup/ui/panels/covariance_view.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/keyboard_driver.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"
#include "support/sample_recorder.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr int kPatienceMs = 30000;

/// The mean ‖K‖ of the applied wall updates from sample `first` on, of at most `most` of them
/// (`count`: how many there were).
double mean_gain(const std::vector<RunSample>& samples, std::size_t first, int* count,
                 int most = std::numeric_limits<int>::max()) {
    double sum = 0.0;
    *count = 0;
    for (std::size_t i = first; i < samples.size() && *count < most; ++i) {
        const WallUpdateReport& update = samples[i].snapshot.update;
        if (update.status == StepStatus::Applied) {
            sum += update.gain.norm();
            ++*count;
        }
    }
    return *count > 0 ? sum / *count : 0.0;
}

double smallest_eigenvalue(const Eigen::Matrix2d& S) {
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S, Eigen::EigenvaluesOnly)
        .eigenvalues()
        .minCoeff();
}

int applied_updates_since(const std::vector<RunSample>& samples, std::size_t first) {
    int count = 0;
    mean_gain(samples, first, &count);
    return count;
}

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<testing::SampleRecorder> recorded_;  ///< every sample of the run, whole
    std::unique_ptr<MainWindow> window_;

    /// Types `text` into the field of setting `key` and presses Enter.
    void enter(const char* key, const QString& text) {
        auto* field = window_->findChild<QLineEdit*>(QString::fromLatin1(key));
        QVERIFY2(field != nullptr, key);
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
    }

    void startAndWaitForSamples(std::size_t count) {
        window_->runToolBar().startAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= count, kPatienceMs);
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Test"));
    }

    void init() {
        session_ = std::make_unique<Session>(lessons::find_experiment("f")->config);
        LinkChoice fast;
        fast.speed = 10.0;  // 200 control periods per second: the tests need a few laps' worth
        session_->setLinkChoice(fast);
        recorded_ = std::make_unique<testing::SampleRecorder>(*session_);
        window_ = std::make_unique<MainWindow>(*session_);
        window_->resize(1400, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    void cleanup() {
        window_.reset();
        recorded_.reset();
        session_.reset();
    }

    void startRunsTheLoopAndEveryViewFollows() {
        QCOMPARE(session_->phase(), RunPhase::Idle);
        startAndWaitForSamples(100);
        QCOMPARE(session_->phase(), RunPhase::Running);
        // The covariance view shows the latest P, the arena and the plots have repainted.
        QTRY_VERIFY(window_->arena().frameStats().summary().total > 0);
        QTRY_VERIFY(window_->plots().frameStats().summary().total > 0);
        QTest::qWait(100);
        const double pxx = session_->history().latest().snapshot.covariance(0, 0);
        QCOMPARE(window_->covarianceView().cellText(0, 0), QString::number(pxx, 'e', 3));
        // Samples arrive in order, every one with the truth (the embedded simulator's).
        const auto& samples = recorded_->samples();
        for (std::size_t i = 1; i < samples.size(); ++i) {
            QCOMPARE(samples[i].snapshot.step, samples[i - 1].snapshot.step + 1);
            QVERIFY(samples[i].truth.has_value());
        }
        window_->runToolBar().stopAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        QVERIFY(session_->history().size() >= 100);  // stopping keeps the history
        window_->runToolBar().resetAction()->trigger();
        QCOMPARE(session_->phase(), RunPhase::Idle);
        QVERIFY(session_->history().empty());
    }

    void raisingRMidRunMakesTheWallUpdatesBarelyMoveTheEstimate() {
        startAndWaitForSamples(10);
        QTRY_VERIFY_WITH_TIMEOUT(applied_updates_since(recorded_->samples(), 0) >= 10, kPatienceMs);
        int before_count = 0;
        const double before = mean_gain(recorded_->samples(), 0, &before_count);
        // R = 1000 m²: the IR readings are worth nothing next to the prediction.
        enter("filter.r11", QStringLiteral("1e3"));
        enter("filter.r22", QStringLiteral("1e3"));
        QCOMPARE(session_->config().filter.r11, 1000.0);
        QCOMPARE(session_->config().filter.r22, 1000.0);
        QVERIFY(!window_->configPanel().messageIsError());
        QVERIFY(session_->running());  // applied live, the run goes on
        // The worker takes each entry at its next step, and a worker may run steps between
        // the two. While only r11 is new, S = H·P·Hᵀ + J·R·Jᵀ keeps one direction as precise
        // as sensor 2 alone (its smallest eigenvalue about r22·‖J‖², far below 1), and the
        // filter rightly goes on trusting that sensor; once both are new, every direction of
        // S is at least about 1000·σ_min(J)² (hundreds). So the first update whose S has
        // its smallest eigenvalue above 100 is the first with both.
        const auto first_with_new_r = [this]() -> std::size_t {
            const auto& samples = recorded_->samples();
            for (std::size_t i = 0; i < samples.size(); ++i) {
                const WallUpdateReport& update = samples[i].snapshot.update;
                if (update.status == StepStatus::Applied
                    && smallest_eigenvalue(update.innovation_covariance) > 100.0) {
                    return i;
                }
            }
            return samples.size();
        };
        QTRY_VERIFY_WITH_TIMEOUT(first_with_new_r() < recorded_->samples().size(), kPatienceMs);
        const std::size_t changed_at = first_with_new_r();
        QTRY_VERIFY_WITH_TIMEOUT(applied_updates_since(recorded_->samples(), changed_at) >= 10,
                                 kPatienceMs);
        // The first ten only: with the walls ignored P keeps growing, and K ≈ P·Hᵀ·S⁻¹ with
        // it, so a slow test machine would otherwise average in later gains.
        int after_count = 0;
        const double after = mean_gain(recorded_->samples(), changed_at, &after_count, 10);
        QVERIFY2(after < before * 1e-2,
                 qPrintable(QStringLiteral("gain before %1, after %2").arg(before).arg(after)));
    }

    void aBadEntryIsRefusedWithAMessageAndNothingChanges() {
        const double r11 = session_->config().filter.r11;
        enter("filter.r11", QStringLiteral("-1"));
        QVERIFY(window_->configPanel().messageIsError());
        QVERIFY2(window_->configPanel().message().contains(QStringLiteral("filter.r11")),
                 qPrintable(window_->configPanel().message()));
        QVERIFY(window_->configPanel().message().contains(QStringLiteral("-1")));
        QCOMPARE(session_->config().filter.r11, r11);
        auto* field = window_->findChild<QLineEdit*>(QStringLiteral("filter.r11"));
        QCOMPARE(field->text(), QStringLiteral("0.00013"));  // the value in use, not the typo

        enter("filter.q11", QStringLiteral("1e-9x"));
        QVERIFY(window_->configPanel().message().contains(QStringLiteral("not a number")));
        enter("filter.q11", QStringLiteral("1e-9"));  // the exact value students type
        QVERIFY(!window_->configPanel().messageIsError());
        QCOMPARE(session_->config().filter.q11, 1e-9);

        enter("seed", QStringLiteral("2.5"));
        QVERIFY(window_->configPanel().message().contains(QStringLiteral("whole number")));
        enter("filter.r22", QStringLiteral("1e30"));  // beyond what the filter accepts
        QVERIFY(window_->configPanel().messageIsError());
        QCOMPARE(session_->config().filter.r22, 1.3e-4);  // step f's, unchanged
    }

    void theLogSliderProposesDecadesAndTheFieldShowsThem() {
        auto* slider = window_->findChild<QSlider*>(QStringLiteral("filter.r11.slider"));
        QVERIFY(slider != nullptr);
        slider->setValue(-3 * 20);  // 1e-3
        QCOMPARE(session_->config().filter.r11, 1e-3);
        QCOMPARE(window_->findChild<QLineEdit*>(QStringLiteral("filter.r11"))->text(),
                 QStringLiteral("0.001"));
    }

    void switchingLessonPresetsAppliesThemAndShowsTheInstructions() {
        auto& panel = window_->lessonPanel();
        QVERIFY(panel.selectStep(QStringLiteral("a")));
        QVERIFY(!session_->config().filter.wall_updates);
        QVERIFY(
            !window_->findChild<QCheckBox*>(QStringLiteral("filter.wall_updates"))->isChecked());
        QVERIFY(panel.instructions().contains(QStringLiteral("encoders")));

        // Picking step c in the list shows it; its button applies the preset (and runs it).
        auto* steps = window_->findChild<QListWidget*>(QStringLiteral("lessonSteps"));
        steps->setCurrentRow(2);
        QCOMPARE(panel.currentStep(), QStringLiteral("c"));
        QVERIFY(!session_->config().filter.wall_updates);  // only shown so far
        window_->findChild<QPushButton*>(QStringLiteral("applyAndRun"))->click();
        QCOMPARE(session_->phase(), RunPhase::Connecting);
        QCOMPARE(session_->config().filter.r11, 1e-8);
        QCOMPARE(session_->config().physical.ir_noise, 0.01);
        QCOMPARE(window_->findChild<QLineEdit*>(QStringLiteral("filter.r11"))->text(),
                 QStringLiteral("1e-08"));
        QCOMPARE(window_->findChild<QLineEdit*>(QStringLiteral("simulator.ir_noise"))->text(),
                 QStringLiteral("0.01"));
        QVERIFY(!panel.selectStep(QStringLiteral("z")));
    }

    void theKeyboardDrivesWhenThePathControllerIsOff() {
        window_->runToolBar().pathControllerSwitch()->setChecked(false);
        QVERIFY(session_->manualDriving());
        startAndWaitForSamples(5);
        window_->arena().setFocus();
        QTest::keyPress(window_.get(), Qt::Key_Up);
        const double v_ref = session_->resolved().loop.motion.v_ref;
        QCOMPARE(window_->keyboard().speed(), v_ref);
        const std::size_t pressed_at = session_->history().size();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() > pressed_at + 60, kPatienceMs);
        const RunSample& moving = session_->history().latest();
        QCOMPARE(moving.snapshot.velocity.v, v_ref);
        QVERIFY(std::abs(moving.truth->velocity.v - v_ref) < 0.02);  // the robot drives
        QTest::keyClick(window_.get(), Qt::Key_Space);
        QCOMPARE(window_->keyboard().speed(), 0.0);
        // In a text field the same keys type: they do not drive.
        auto* field = window_->findChild<QLineEdit*>(QStringLiteral("filter.q11"));
        field->setFocus();
        QTest::keyPress(field, Qt::Key_W);
        QCOMPARE(window_->keyboard().speed(), 0.0);
    }

    void exportsPlotsTraceAndConfiguration() {
        startAndWaitForSamples(60);
        window_->runToolBar().stopAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        QTemporaryDir out;
        const ExportResult plots = window_->plots().exportPlots(out.path());
        QVERIFY2(plots.ok(), qPrintable(plots.error));
        QVERIFY(plots.files.size() >= 9);  // every plot, three formats

        const QString trace = out.filePath(QStringLiteral("trace.csv"));
        QCOMPARE(session_->exportTrace(trace), QString());
        QFile file(trace);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines.front(), QByteArray(lessons::trace_csv_header()));
        QCOMPARE(static_cast<std::size_t>(lines.size() - 2), session_->history().size());

        enter("filter.q22", QStringLiteral("3e-6"));
        const QString config = out.filePath(QStringLiteral("mine.toml"));
        QCOMPARE(session_->saveConfig(config), QString());
        const lessons::RunConfig read = lessons::load_config_file(config.toStdString(), {});
        QCOMPARE(read.filter.q22, 3e-6);  // the CLI reads what the GUI wrote
        QCOMPARE(session_->exportTrace(QStringLiteral("/nonexistent/dir/trace.csv")).isEmpty(),
                 false);
    }

    void recordingWritesTheConfigurationAndTheTraceAsTheRunGoes() {
        QTemporaryDir out;
        const QString directory = out.filePath(QStringLiteral("run1"));
        QCOMPARE(session_->setRecordingDirectory(directory), QString());
        QVERIFY(QFile::exists(directory + QStringLiteral("/config.toml")));
        startAndWaitForSamples(40);
        // Written on the recorder's thread and flushed after every frame's batch: most rows
        // are on disk while the run still goes.
        const auto rows_on_disk = [&] {
            QFile trace(directory + QStringLiteral("/trace.csv"));
            return trace.open(QIODevice::ReadOnly) ? trace.readAll().count('\n') : -1;
        };
        QTRY_VERIFY(rows_on_disk() >= 20);
        QVERIFY(session_->running());
    }

    void loadingABrokenConfigurationReportsTheLineAndKeepsTheCurrentOne() {
        QTemporaryDir out;
        const QString path = out.filePath(QStringLiteral("broken.toml"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("[filter]\nq11 = 1e-7\nr11 = -5\n");
        file.close();
        const QStringList problems = session_->loadConfig(path);
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.front().contains(QStringLiteral("broken.toml:3")),
                 qPrintable(problems.front()));
        QCOMPARE(session_->config().filter.r11, 1.3e-4);  // step f's, in use before the load
    }

    void closingSavesTheConfigurationAndTheLayout() {
        enter("filter.r11", QStringLiteral("2e-4"));
        window_->close();
        QVERIFY(QFile::exists(last_config_path()));
        const lessons::RunConfig saved =
            lessons::load_config_file(last_config_path().toStdString(), {});
        QCOMPARE(saved.filter.r11, 2e-4);
        QVERIFY(!preferences::kWindowState.read().isEmpty());
    }

    void largeTextScalesTheApplicationFont() {
        const double normal = QApplication::font().pointSizeF();
        window_->setLargeText(true);
        QCOMPARE(QApplication::font().pointSizeF(), normal * 1.6);
        // The views' own fonts follow once (not 1.6 × 1.6).
        QTRY_COMPARE(window_->arena().font().pointSizeF(), normal * 1.6);
        QTRY_COMPARE(window_->plots().font().pointSizeF(), normal * 1.6);
        QCOMPARE(window_->arena().textScale(), 1.0);
        window_->setLargeText(false);
        QCOMPARE(QApplication::font().pointSizeF(), normal);
    }
};

QTEST_MAIN(MainWindowTest)
#include "test_main_window.moc"
