// The real-robot path in the window (QtTest, offscreen), without a robot: rehearsing with the
// emulated brick inside the application runs the whole NXT link with ground truth and shows
// the link's state, battery and cycle time; a brick elsewhere (an emulator on loopback TCP,
// as a real one over Bluetooth) gives estimate-only samples, and when its link drops the run
// fails with the reason and Reconnect starts again without restarting anything.

#include <QComboBox>
#include <QDialog>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <chrono>
#include <cmath>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/nxtemu/emulated_nxt.hpp"
#include "legofeup/ui/panels/robot_status.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"
#include "support/screenshot.hpp"

using namespace legofeup;
using namespace legofeup::ui;
using namespace std::chrono_literals;

namespace {

constexpr int kPatienceMs = 20000;

}  // namespace

class NxtWindowTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<MainWindow> window_;

    QLabel* statusBarRobotLine() const {
        return window_->findChild<QLabel*>(QStringLiteral("robotLine"));
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab NXT Test"));
    }

    void init() {
        session_ = std::make_unique<Session>(lessons::find_experiment("f")->config);
        window_ = std::make_unique<MainWindow>(*session_);
        window_->resize(1400, 900);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    void cleanup() {
        window_.reset();
        session_.reset();
    }

    void rehearsingWithTheEmulatedBrickShowsTheLinkAndTheTruth() {
        LinkChoice choice;
        choice.kind = LinkKind::Nxt;
        choice.emulated = true;
        session_->setLinkChoice(choice);
        QVERIFY(window_->findChild<QDockWidget*>(QStringLiteral("robotDock"))->isVisible());
        QTRY_VERIFY(window_->runToolBar().nxtButton()->isVisible());  // laid out lazily
        QCOMPARE(window_->runToolBar().nxtButton()->text(), QStringLiteral("Emulated brick…"));
        window_->runToolBar().startAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= 30, kPatienceMs);
        QCOMPARE(session_->phase(), RunPhase::Running);
        QVERIFY(session_->history().latest().truth.has_value());  // the emulator's simulator
        QVERIFY(!window_->plots().showsNoTruth());

        RobotStatusView& robot = window_->robotStatus();
        QTRY_COMPARE(robot.stateLabel()->text(), QStringLiteral("Connected"));
        QCOMPARE(robot.batteryLabel()->text(), QStringLiteral("7.80 V"));
        QTRY_VERIFY(robot.cycleLabel()->text().contains(QStringLiteral(" Hz)")));
        QVERIFY(!robot.reconnectButton()->isVisible());
        QVERIFY2(statusBarRobotLine()->text().startsWith(QStringLiteral("NXT: Connected · 7.80 V")),
                 qPrintable(statusBarRobotLine()->text()));
        QVERIFY(session_->robotHealth() != nullptr);
        QVERIFY(session_->status().health.has_value());
        QVERIFY(session_->status().health->rate_hz() > 5.0);

        window_->runToolBar().stopAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        QCOMPARE(robot.stateLabel()->text(), QStringLiteral("Disconnected"));
    }

    void aDroppedLinkFailsWithTheReasonAndReconnectStartsAgain() {
        // A brick on loopback TCP whose first connection is pulled 2.5 s in; the next one is
        // served normally (as a robot that went out of range and came back).
        nxtemu::EmulatorOptions options;
        options.run = lessons::find_experiment("f")->config;
        options.link.drop_after = 2.5;
        nxtemu::EmulatedNxt brick(std::move(options));
        const QString address = QStringLiteral("tcp:127.0.0.1:%1").arg(brick.serve_tcp());

        LinkChoice choice;
        choice.kind = LinkKind::Nxt;
        choice.nxt_address = address;
        session_->setLinkChoice(choice);
        window_->runToolBar().startAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= 5, kPatienceMs);
        // Nobody knows a real robot's pose: samples without truth, plots say so.
        QVERIFY(!session_->history().latest().truth.has_value());
        QVERIFY(std::isnan(session_->history().latest().nees));
        QTRY_VERIFY(window_->plots().showsNoTruth());

        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Failed, kPatienceMs);
        RobotStatusView& robot = window_->robotStatus();
        QVERIFY2(robot.stateLabel()->text().startsWith(QStringLiteral("Failed: ")),
                 qPrintable(robot.stateLabel()->text()));
        QVERIFY2(robot.stateLabel()->text().contains(address),  // the link is named
                 qPrintable(robot.stateLabel()->text()));
        QVERIFY(robot.reconnectButton()->isVisible());
        QVERIFY(window_->reconnectAction()->isEnabled());
        QVERIFY2(statusBarRobotLine()->text().startsWith(QStringLiteral("NXT: Failed · 7.80 V")),
                 qPrintable(statusBarRobotLine()->text()));
        testing::save_screenshot(*window_, "nxt-failed");
        const std::size_t before = session_->history().size();
        QVERIFY(before >= 5);

        QTest::mouseClick(robot.reconnectButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Running, kPatienceMs);
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= 20, kPatienceMs);
        QTRY_COMPARE(robot.stateLabel()->text(), QStringLiteral("Connected"));
        QVERIFY(!robot.reconnectButton()->isVisible());
        QVERIFY(!window_->reconnectAction()->isEnabled());
        session_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
    }

    void aRobotProfileGivesTheFilterThisRobotsModel() {
        lessons::RobotProfile profile;
        profile.name = "test robot";
        profile.ir_curve.c_m = 3100.0;  // the configuration's is 2914
        profile.ir_curve.c_r = 9.0;
        const QString file = config_home_.filePath(QStringLiteral("robot.toml"));
        lessons::save_robot_profile(file.toStdString(), profile);
        LinkChoice choice;
        choice.kind = LinkKind::Nxt;
        choice.emulated = true;
        choice.robot_profile = file;
        session_->setLinkChoice(choice);
        session_->start();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= 10, kPatienceMs);
        // The IR distances are eq. 2 with the profile's constants, not the configuration's.
        const IrSample& ir = session_->history().latest().snapshot.ir[0];
        QCOMPARE(ir.reading.distance, distance_from_adc(ir.adc, profile.ir_curve).distance);
        QVERIFY(ir.reading.distance
                != distance_from_adc(ir.adc, session_->resolved().loop.ir_curve).distance);
        // A live change keeps the profile's model.
        QCOMPARE(session_->changeSetting(*lessons::find_setting_by_key("filter.r11"),
                                         lessons::SettingValue(2e-4)),
                 QString());
        const std::size_t changed = session_->history().size();
        QTRY_VERIFY_WITH_TIMEOUT(session_->history().size() >= changed + 5, kPatienceMs);
        const IrSample& later = session_->history().latest().snapshot.ir[0];
        QCOMPARE(later.reading.distance, distance_from_adc(later.adc, profile.ir_curve).distance);
        // A profile that does not load is refused before anything starts.
        choice.robot_profile = config_home_.filePath(QStringLiteral("missing.toml"));
        session_->stop();
        QTRY_COMPARE_WITH_TIMEOUT(session_->phase(), RunPhase::Stopped, kPatienceMs);
        session_->setLinkChoice(choice);
        QSignalSpy problems(session_.get(), &Session::problem);
        session_->start();
        QCOMPARE(problems.size(), 1);
        QVERIFY2(problems.front().front().toString().contains(QStringLiteral("missing.toml")),
                 qPrintable(problems.front().front().toString()));
        QCOMPARE(session_->phase(), RunPhase::Stopped);
    }

    void theStatusWordsAreTheLinksState() {
        LiveRunStatus status;
        lessons::LinkHealth quality;
        quality.state = lessons::LinkState::Connected;
        quality.battery_millivolts = 6420;
        quality.frames = 100;
        quality.mean_cycle_seconds = 0.0625;
        quality.timeouts = 3;
        status.health = quality;
        // A simulator's health (its stream's counters) is not a robot's: no status line.
        QCOMPARE(robot_status_line(RunPhase::Running, status), QString());
        status.capabilities.robot_health = true;
        QCOMPARE(robot_status_line(RunPhase::Running, status),
                 QStringLiteral("NXT: Connected · 6.42 V (low) · 63 ms (16.0 Hz) · 3 timeouts"));
        QVERIFY(battery_low(quality));
        quality.battery_millivolts = 7000;
        QVERIFY(!battery_low(quality));
        QCOMPARE(connection_state_text(RunPhase::Connecting, {}), QStringLiteral("Connecting…"));
        status.message = "NXT at bt:00:16:53:01:02:03 (direct commands): no reply";
        QCOMPARE(connection_state_text(RunPhase::Failed, status),
                 QStringLiteral("Failed: NXT at bt:00:16:53:01:02:03 (direct commands): no "
                                "reply"));
        QCOMPARE(connection_state_text(RunPhase::Stopped, status), QStringLiteral("Disconnected"));
        QCOMPARE(robot_status_line(RunPhase::Running, LiveRunStatus{}), QString());  // a simulator
    }

    void choosingTheNxtOpensTheConnectDialogAndCancelKeepsTheRobot() {
        QComboBox* link = window_->runToolBar().linkChoice();
        link->setCurrentIndex(static_cast<int>(LinkKind::Nxt));
        auto* dialog = window_->findChild<QDialog*>(QStringLiteral("connectDialog"));
        QVERIFY(dialog != nullptr);
        QCOMPARE(session_->linkChoice().kind, LinkKind::Embedded);  // not before OK
        dialog->reject();
        QCOMPARE(session_->linkChoice().kind, LinkKind::Embedded);
        QCOMPARE(link->currentIndex(), static_cast<int>(LinkKind::Embedded));
    }
};

QTEST_MAIN(NxtWindowTest)
#include "test_nxt_window.moc"
