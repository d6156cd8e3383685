// File ▸ Re-filter recorded run… and File ▸ Record runs (QtTest, offscreen): a run log
// recorded by a short lockstep run, replayed with other Q and R — the old estimate is the
// recorded one, the new differs, the table compares them (a log without truth: the counts,
// and a dash for the errors); a bad log is refused with its line; a live run recorded from the
// window replays exactly.

#include <qcustomplot.h>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"
#include "legofeup/ui/panels/setting_editor.hpp"
#include "legofeup/ui/refilter/refilter_dialog.hpp"
#include "legofeup/ui/refilter/refilter_plots.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "support/screenshot.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr int kPatienceMs = 30000;

/// Step f of the lesson (Q and R tuned well), one lap.
lessons::RunConfig one_lap() {
    lessons::RunConfig config = lessons::legofeup_lesson().find_step("f")->config;
    config.laps = 1;
    return config;
}

/// Records a lockstep run of `config` into `path`.
void record(const lessons::RunConfig& config, const QString& path) {
    const lessons::ResolvedRun run = lessons::resolve(config);
    lessons::RunLogWriter writer(path.toStdString(), run, "step f, one lap");
    lessons::run_lockstep(run, &writer);
    writer.close();
}

/// Largest distance between two curves' points, index by index.
double largest_gap(const QCPCurve& a, const QCPCurve& b) {
    double gap = 0.0;
    auto j = b.data()->constBegin();
    for (auto i = a.data()->constBegin(); i != a.data()->constEnd(); ++i, ++j) {
        gap = std::max(gap, std::hypot(i->key - j->key, i->value - j->value));
    }
    return gap;
}

/// Opens `path` in the dialog and waits until it is read (on its RunLogReadJob's thread):
/// "" or the problem. The dialog answers while it reads (the GUI thread reads nothing).
QString open_log(RefilterDialog& dialog, const QString& path) {
    QSignalSpy opened(&dialog, &RefilterDialog::logOpened);
    dialog.openLog(path);
    if (!opened.isEmpty()) {
        return QStringLiteral("openLog read the log on the GUI thread");
    }
    if (!dialog.busy()) {
        return QStringLiteral("openLog started no reading");
    }
    if (!opened.wait(kPatienceMs)) {
        return QStringLiteral("the log was not read within the patience");
    }
    return opened.takeFirst().at(0).toString();
}

/// Waits for the dialog's replay (on its RefilterJob's thread) to be shown.
bool refiltered(RefilterDialog& dialog) {
    return QTest::qWaitFor([&] { return !dialog.busy(); }, kPatienceMs);
}

}  // namespace

class RefilterDialogTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir dir_;
    QString log_path_;
    std::unique_ptr<Session> session_;

    void enter(RefilterDialog& dialog, const char* key, const QString& text) {
        auto* field = dialog.findChild<QLineEdit*>(QString::fromLatin1(key));
        QVERIFY2(field != nullptr, key);
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, text);
        QTest::keyClick(field, Qt::Key_Return);
    }

  private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("XDG_CONFIG_HOME", dir_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Refilter Test"));
        log_path_ = dir_.filePath(QStringLiteral("f.log"));
        record(one_lap(), log_path_);
        session_ = std::make_unique<Session>(one_lap());
    }

    void cleanupTestCase() { session_.reset(); }

    void changingQGivesASecondEstimateOnTheSameReadings() {
        RefilterDialog dialog(*session_);
        dialog.resize(1400, 900);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QCOMPARE(open_log(dialog, log_path_), QString());
        const lessons::RunLog log = lessons::load_run_log(log_path_.toStdString());
        // Prefilled from the log's configuration, in the configuration panel's editors.
        QCOMPARE(dialog.findChild<QLineEdit*>(QStringLiteral("filter.q11"))->text(),
                 QStringLiteral("%1").arg(log.config.filter.q11));
        QVERIFY(dialog.editor("filter.r22") != nullptr);

        // Unchanged settings: the two replays are the same run, and the recorded one.
        QCOMPARE(dialog.refilterNow(), QString());
        QVERIFY(refiltered(dialog));
        RefilterPlots& plots = dialog.plots();
        const auto steps = static_cast<int>(log.records.size());
        QCOMPARE(plots.oldPath().data()->size(), steps);
        QCOMPARE(plots.newPath().data()->size(), steps);
        QCOMPARE(plots.truthPath().data()->size(), steps);
        QCOMPARE(largest_gap(plots.oldPath(), plots.newPath()), 0.0);
        QVERIFY(dialog.result()->reproduces_recording());
        auto old_point = plots.oldPath().data()->constBegin();
        for (const lessons::RunLogRecord& record : log.records) {
            QCOMPARE(old_point->key, record.estimate(0));
            QCOMPARE(old_point->value, record.estimate(1));
            ++old_point;
        }

        // Q a million times larger: the walls pull the estimate much harder.
        enter(dialog, "filter.q11", QStringLiteral("1e-1"));
        enter(dialog, "filter.q22", QStringLiteral("1e-1"));
        QCOMPARE(dialog.newConfig().filter.q11, 1e-1);
        QCOMPARE(dialog.refilterNow(), QString());
        QVERIFY(refiltered(dialog));
        const double gap = largest_gap(plots.oldPath(), plots.newPath());
        QVERIFY2(gap > 0.005, qPrintable(QString::number(gap)));
        QCOMPARE(plots.oldError().data()->size(), steps);
        QCOMPARE(plots.newError().data()->size(), steps);
        // The old curve is still the recorded run's.
        QCOMPARE(plots.oldPath().data()->constBegin()->key, log.records.front().estimate(0));

        // The table: the two replays' metrics side by side, from the library's result.
        QTableWidget& table = dialog.metricsTable();
        QCOMPARE(table.columnCount(), 2);
        QCOMPARE(table.rowCount(), 8);
        QCOMPARE(table.item(0, 0)->text(),
                 QStringLiteral("%1 m").arg(
                     dialog.result()->old_metrics.truth.value().rms_position_error, 0, 'f', 4));
        QCOMPARE(table.item(0, 1)->text(),
                 QStringLiteral("%1 m").arg(
                     dialog.result()->new_metrics.truth.value().rms_position_error, 0, 'f', 4));
        QVERIFY(table.item(0, 0)->text() != table.item(0, 1)->text());

        // A value the filter cannot take is refused, never clamped.
        enter(dialog, "filter.r11", QStringLiteral("-1"));
        QCOMPARE(dialog.newConfig().filter.r11, log.config.filter.r11);
        const QString message =
            dialog.findChild<QLabel*>(QStringLiteral("refilterMessage"))->text();
        QVERIFY2(message.contains(QStringLiteral("must be between")), qPrintable(message));

        // Experiment d on the same readings: Q tiny, the filter trusts its odometry and the
        // walls barely move it — the error grows like odometry's.
        enter(dialog, "filter.q11", QStringLiteral("1e-12"));
        enter(dialog, "filter.q22", QStringLiteral("1e-12"));
        QCOMPARE(dialog.newConfig().filter.q22, 1e-12);  // re-filtered on Enter
        QVERIFY(dialog.busy());  // on the job's thread: the dialog answers meanwhile
        QVERIFY(refiltered(dialog));
        QVERIFY(dialog.result()->new_metrics.truth.value().rms_position_error
                > 2.0 * dialog.result()->old_metrics.truth.value().rms_position_error);
        testing::save_screenshot(dialog, "refilter");
    }

    void aBrokenLogIsRefusedWithItsLineAndTheLogShownStays() {
        RefilterDialog dialog(*session_);
        QCOMPARE(open_log(dialog, log_path_), QString());
        // The header as recorded, then a record line cut to nonsense.
        QFile good(log_path_);
        QVERIFY(good.open(QIODevice::ReadOnly));
        QList<QByteArray> lines = good.readAll().split('\n');
        int first_record = 0;
        while (first_record < lines.size() && !lines[first_record].startsWith("1,")) {
            ++first_record;
        }
        QVERIFY(first_record < lines.size());
        lines[first_record] = "1,not-a-number,x\n";
        const QString bad = dir_.filePath(QStringLiteral("bad.log"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(lines.mid(0, first_record + 1).join('\n'));
        file.write("\n");
        file.close();
        const QString error = open_log(dialog, bad);
        QVERIFY2(error.contains(QStringLiteral("bad.log:%1").arg(first_record + 1)),
                 qPrintable(error));
        QCOMPARE(dialog.findChild<QLineEdit*>(QStringLiteral("refilterLogPath"))->text(),
                 log_path_);
        QCOMPARE(dialog.refilterNow(), QString());  // the good log is still there
        QVERIFY(refiltered(dialog));
        QVERIFY(dialog.result().has_value());
    }

    void aLogWithoutTruthShowsTheCountsAndSaysTheErrorsNeedOne() {
        // A short drive recorded as from a real robot: the truth withheld.
        lessons::RunConfig config = one_lap();
        config.duration = 10.0;
        const lessons::ResolvedRun run = lessons::resolve(config);
        sim::WorldSpec world = run.world;
        world.start = run.true_start;
        sim::Simulator simulator(world, run.robot, run.config.simulator, run.config.seed);
        sim::LockstepLink link(simulator);
        lessons::UnknownTruth unknown;
        const QString path = dir_.filePath(QStringLiteral("blind.log"));
        lessons::RunResult live;
        {
            lessons::RunLogWriter writer(path.toStdString(), run, "step f, no truth");
            live = lessons::run_with_link(run, link, unknown, &writer);
            writer.close();
        }
        QVERIFY(live.metrics.updates_applied > 0);

        RefilterDialog dialog(*session_);
        QCOMPARE(open_log(dialog, path), QString());
        QCOMPARE(dialog.refilterNow(), QString());
        QVERIFY(refiltered(dialog));
        const QTableWidget& table = dialog.metricsTable();
        for (int row = 0; row < 6; ++row) {  // the errors and the NEES need the truth
            QCOMPARE(table.item(row, 0)->text(), QStringLiteral("— (no ground truth)"));
            QCOMPARE(table.item(row, 1)->text(), QStringLiteral("— (no ground truth)"));
        }
        // The counts need none: the live run's, in both columns (same settings).
        const QString updates = QStringLiteral("%1 / %2")
                                    .arg(live.metrics.updates_applied)
                                    .arg(live.metrics.updates_rejected);
        QCOMPARE(table.item(7, 0)->text(), updates);
        QCOMPARE(table.item(7, 1)->text(), updates);
    }

    void aLiveRunRecordedFromTheWindowReplaysExactly() {
        Session session(one_lap());
        LinkChoice fast;
        fast.speed = 10.0;
        session.setLinkChoice(fast);
        lessons::RunConfig short_line = one_lap();
        short_line.routine.kind = lessons::RoutineSpec::Kind::Line;
        short_line.duration = 4.0;
        QVERIFY(session.setConfig(short_line).isEmpty());
        MainWindow window(session);
        window.show();
        const QString folder = dir_.filePath(QStringLiteral("recorded"));
        QCOMPARE(session.setRecordingDirectory(folder), QString());
        session.start();
        QTRY_COMPARE_WITH_TIMEOUT(session.phase(), RunPhase::Finished, kPatienceMs);
        QCOMPARE(session.recordingFile(), folder + QStringLiteral("/run.log"));
        QTRY_VERIFY(window.findChild<QLabel*>(QStringLiteral("runStatus"))
                        ->text()
                        .contains(QStringLiteral("recording run.log")));

        const lessons::RunLog log = lessons::load_run_log(session.recordingFile().toStdString());
        QVERIFY(log.ended);  // the run finished: the log has its end line
        QCOMPARE(log.records.size(), session.history().size());
        QCOMPARE(log.records.back().estimate, session.history().latest().snapshot.estimate);

        RefilterDialog* dialog = window.openRefilter();
        QCOMPARE(open_log(*dialog, session.recordingFile()), QString());
        QCOMPARE(dialog->refilterNow(), QString());
        QVERIFY(refiltered(*dialog));
        QVERIFY(dialog->result()->reproduces_recording());

        // The next run gets a file of its own.
        session.start();
        QTRY_COMPARE_WITH_TIMEOUT(session.phase(), RunPhase::Finished, kPatienceMs);
        QCOMPARE(session.recordingFile(), folder + QStringLiteral("/run-2.log"));
        QVERIFY(QFile::exists(folder + QStringLiteral("/trace-2.csv")));
    }
};

QTEST_MAIN(RefilterDialogTest)
#include "test_refilter_dialog.moc"
