// A build without the NXT (LEGOFEUP_WITH_NXT=OFF), in the window (QtTest, offscreen): the
// robot selector offers the simulators only and no menu offers to connect to an NXT; an NXT
// saved by a build with one comes back as the embedded simulator, and an NXT chosen anyway
// is refused at the start with the reason, like any other choice that cannot run.

#include <QAction>
#include <QComboBox>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/session/nxt_connection.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/main_window.hpp"
#include "legofeup/ui/window/run_toolbar.hpp"

using namespace legofeup;
using namespace legofeup::ui;

class NoNxtWindowTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;
    std::unique_ptr<Session> session_;
    std::unique_ptr<MainWindow> window_;

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab no-NXT Test"));
    }

    void init() {
        session_ = std::make_unique<Session>(lessons::find_experiment("f")->config);
        window_ = std::make_unique<MainWindow>(*session_);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
    }

    void cleanup() {
        window_.reset();
        session_.reset();
    }

    void theWindowOffersNoNxt() {
        QVERIFY(!nxt_supported());
        QComboBox* link = window_->runToolBar().linkChoice();
        QCOMPARE(link->count(), 2);  // the embedded simulator and an external legofeup-sim
        for (int i = 0; i < link->count(); ++i) {
            QVERIFY2(!link->itemText(i).contains(QStringLiteral("NXT")),
                     qPrintable(link->itemText(i)));
        }
        QAction* connect = window_->runToolBar().connectAction();
        QVERIFY(!connect->isVisible());  // hidden in the Run and Tools menus alike
        QVERIFY(window_->runToolBar().openConnectDialog() == nullptr);
    }

    void anNxtSavedByABuildWithOneIsTheEmbeddedSimulator() {
        LinkChoice saved;
        saved.kind = LinkKind::Nxt;
        saved.nxt_address = QStringLiteral("bt:00:16:53:01:02:03");
        save_link_choice(saved);
        QCOMPARE(saved_link_choice().kind, LinkKind::Embedded);
        QCOMPARE(saved_link_choice().nxt_address, saved.nxt_address);  // kept for a build with one
    }

    void anNxtChosenAnywayIsRefusedWithTheReason() {
        LinkChoice choice;
        choice.kind = LinkKind::Nxt;
        choice.emulated = true;
        session_->setLinkChoice(choice);
        QSignalSpy problems(session_.get(), &Session::problem);
        session_->start();
        QCOMPARE(problems.count(), 1);
        const QString message = problems.at(0).at(0).toString();
        QVERIFY2(message.contains(QStringLiteral("no NXT support")), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("LEGOFEUP_WITH_NXT=OFF")), qPrintable(message));
        QCOMPARE(session_->phase(), RunPhase::Idle);
        QVERIFY(!session_->running());
    }
};

QTEST_MAIN(NoNxtWindowTest)
#include "test_no_nxt_window.moc"
