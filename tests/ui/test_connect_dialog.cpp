// The NXT connect dialog, driven as a teacher would (QtTest, offscreen): the address is
// checked as it is typed with the link's own words, OK waits for a usable one, the recent
// robots persist (most recent first, at most 8, removable), the emulated brick needs no
// address, and Scan on a machine without BlueZ says so at once instead of hanging.

#include <QCheckBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <stdexcept>

#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/ui/session/nxt_address.hpp"
#include "legofeup/ui/window/app_settings.hpp"
#include "legofeup/ui/window/bluetooth_scan.hpp"
#include "legofeup/ui/window/connect_dialog.hpp"
#include "support/screenshot.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

/// What the link itself says of `address`.
QString parser_message(const std::string& address) {
    try {
        comms::nxt::parse_transport_address(address);
    } catch (const std::invalid_argument& error) {
        return QString::fromStdString(error.what());
    }
    return {};
}

}  // namespace

class ConnectDialogTest : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;

    static void type(ConnectDialog& dialog, const QString& text) {
        dialog.addressField()->selectAll();
        dialog.addressField()->del();
        QTest::keyClicks(dialog.addressField(), text);
    }

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Connect Test"));
    }

    void init() { preferences::kRecentRobots.write({}); }

    void theAddressIsCheckedAsTypedWithTheLinksOwnWords() {
        ConnectDialog dialog(LinkChoice{});
        QVERIFY(!dialog.okButton()->isEnabled());  // nothing typed yet
        QVERIFY(dialog.addressMessage()->text().contains(QStringLiteral("bt:00:16:53")));

        type(dialog, QStringLiteral("00:16:53:0G:00:01"));
        const QString expected = parser_message("bt:00:16:53:0G:00:01");
        QVERIFY(!expected.isEmpty());
        QCOMPARE(dialog.addressMessage()->text(), expected);
        QVERIFY(dialog.addressMessage()->text().contains(QStringLiteral("0G")));
        QVERIFY(!dialog.okButton()->isEnabled());

        type(dialog, QStringLiteral("tcp:127.0.0.1"));  // no port
        QCOMPARE(dialog.addressMessage()->text(), parser_message("tcp:127.0.0.1"));
        QVERIFY(!dialog.okButton()->isEnabled());

        type(dialog, QStringLiteral("usb:1"));  // no such transport
        QCOMPARE(dialog.addressMessage()->text(), parser_message("usb:1"));
        QVERIFY(!dialog.okButton()->isEnabled());

        // A bare Bluetooth address is taken as bt:.
        type(dialog, QStringLiteral("00:16:53:0a:0b:0c"));
        QVERIFY2(dialog.okButton()->isEnabled(), qPrintable(dialog.addressMessage()->text()));
        QCOMPARE(dialog.choice().nxt_address, QStringLiteral("bt:00:16:53:0a:0b:0c"));
        QCOMPARE(dialog.choice().kind, LinkKind::Nxt);

        for (const char* good :
             {"bt:00:16:53:01:02:03", "serial:/dev/rfcomm0", "tcp:127.0.0.1:5700"}) {
            type(dialog, QString::fromLatin1(good));
            QVERIFY2(dialog.okButton()->isEnabled(), good);
            QCOMPARE(dialog.choice().nxt_address, QString::fromLatin1(good));
        }
        QCOMPARE(normalized_nxt_address(QStringLiteral(" /dev/rfcomm0 ")),
                 QStringLiteral("serial:/dev/rfcomm0"));
    }

    void theEmulatedBrickNeedsNoAddressAndDisablesIt() {
        ConnectDialog dialog(LinkChoice{});
        QVERIFY(!dialog.okButton()->isEnabled());
        dialog.emulatedBox()->setChecked(true);
        QVERIFY(dialog.okButton()->isEnabled());
        QVERIFY(!dialog.addressField()->isEnabled());
        QVERIFY(!dialog.scanButton()->isEnabled());
        const LinkChoice choice = dialog.choice();
        QVERIFY(choice.emulated);
        dialog.relayBox()->setChecked(true);
        QVERIFY(dialog.choice().relay);
        dialog.emulatedBox()->setChecked(false);
        QVERIFY(!dialog.okButton()->isEnabled());
        QVERIFY(dialog.addressField()->isEnabled());
    }

    void acceptingRemembersTheRobotMostRecentFirstAtMostEight() {
        const auto connect_to = [](const QString& address) {
            ConnectDialog dialog(LinkChoice{});
            dialog.show();
            type(dialog, address);
            QTest::mouseClick(dialog.okButton(), Qt::LeftButton);
            QCOMPARE(dialog.result(), int(QDialog::Accepted));
        };
        connect_to(QStringLiteral("00:16:53:00:00:01"));
        connect_to(QStringLiteral("tcp:127.0.0.1:5700"));
        connect_to(QStringLiteral("bt:00:16:53:00:00:01"));  // again: moves to the front
        QCOMPARE(preferences::kRecentRobots.read(),
                 QStringList({QStringLiteral("bt:00:16:53:00:00:01"),
                              QStringLiteral("tcp:127.0.0.1:5700")}));
        for (int i = 2; i <= 9; ++i) {
            connect_to(QStringLiteral("bt:00:16:53:00:00:%1").arg(i, 2, 10, QLatin1Char('0')));
        }
        const QStringList recent = preferences::kRecentRobots.read();
        QCOMPARE(recent.size(), kMaxRecentRobots);
        QCOMPARE(recent.front(), QStringLiteral("bt:00:16:53:00:00:09"));
        QCOMPARE(recent.back(), QStringLiteral("bt:00:16:53:00:00:02"));
        QVERIFY(!recent.contains(QStringLiteral("tcp:127.0.0.1:5700")));  // the oldest went

        // A new dialog lists them; clicking one uses it; Remove forgets it for good.
        ConnectDialog dialog(LinkChoice{});
        dialog.show();
        QCOMPARE(dialog.recentList()->count(), kMaxRecentRobots);
        QListWidgetItem* third = dialog.recentList()->item(2);
        QTest::mouseClick(dialog.recentList()->viewport(), Qt::LeftButton, {},
                          dialog.recentList()->visualItemRect(third).center());
        QCOMPARE(dialog.addressField()->text(), QStringLiteral("bt:00:16:53:00:00:07"));
        QVERIFY(dialog.removeRecentButton()->isEnabled());
        QTest::mouseClick(dialog.removeRecentButton(), Qt::LeftButton);
        QCOMPARE(dialog.recentList()->count(), kMaxRecentRobots - 1);
        QVERIFY(
            !preferences::kRecentRobots.read().contains(QStringLiteral("bt:00:16:53:00:00:07")));

        // An emulated brick is not a robot to remember.
        ConnectDialog emulated(LinkChoice{});
        emulated.emulatedBox()->setChecked(true);
        emulated.accept();
        QCOMPARE(preferences::kRecentRobots.read().size(), kMaxRecentRobots - 1);
    }

    void theRecentListKeepsItsOrderWithoutDuplicates() {
        QStringList recent;
        recent = with_recent_robot(recent, QStringLiteral("a"));
        recent = with_recent_robot(recent, QStringLiteral("b"));
        recent = with_recent_robot(recent, QStringLiteral(" a "));
        QCOMPARE(recent, QStringList({QStringLiteral("a"), QStringLiteral("b")}));
        QCOMPARE(with_recent_robot(recent, QString()), recent);  // nothing to remember
    }

    void scanningWithoutBlueZSaysSoAtOnceAndReturns() {
        if (BluetoothScan::unavailableReason().isEmpty()) {
            QSKIP("this machine has a Bluetooth adapter and BlueZ: nothing to test here");
        }
        preferences::kRecentRobots.write(
            {QStringLiteral("bt:00:16:53:0A:1B:2C"), QStringLiteral("tcp:127.0.0.1:5700")});
        ConnectDialog dialog(LinkChoice{});
        dialog.show();
        QElapsedTimer clock;
        clock.start();
        QTest::mouseClick(dialog.scanButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(
            dialog.scanMessage()->text().startsWith(QStringLiteral("Cannot scan")), 5000);
        QVERIFY2(clock.elapsed() < 5000, "the scan's report took too long");
        const QString message = dialog.scanMessage()->text();
        QVERIFY2(message.contains(QStringLiteral("BlueZ"))
                     || message.contains(QStringLiteral("adapter")),
                 qPrintable(message));
        QVERIFY(message.contains(QStringLiteral("Type the brick's address")));
        QVERIFY(dialog.scanButton()->isEnabled());  // ready to try again
        QCOMPARE(dialog.foundList()->count(), 0);
        // The dialog still works: an address typed now is accepted.
        type(dialog, QStringLiteral("00:16:53:0A:1B:2C"));
        QVERIFY(dialog.okButton()->isEnabled());
        testing::save_screenshot(dialog, "nxt-connect");
    }

    void legoAddressesAreRecognised() {
        QVERIFY(is_lego_bluetooth_address(QStringLiteral("00:16:53:0A:0B:0C")));
        QVERIFY(is_lego_bluetooth_address(QStringLiteral("00:16:53:0a:0b:0c")));
        QVERIFY(!is_lego_bluetooth_address(QStringLiteral("00:17:53:0A:0B:0C")));
    }
};

QTEST_MAIN(ConnectDialogTest)
#include "test_connect_dialog.moc"
