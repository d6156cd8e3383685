#pragma once
// Looking for bricks with Qt Bluetooth (BlueZ 5 on Linux): the connect dialog's "Scan".
//
// Scanning needs the BlueZ daemon (bluetoothd, on the system D-Bus) and a powered adapter.
// Where either is missing, start() says which, at once, and scans nothing: typing the
// address always works. Every result arrives through signals, never from inside start(),
// so the caller's state is set up before the first one.

#include <QObject>
#include <QString>

class QBluetoothDeviceDiscoveryAgent;
class QBluetoothDeviceInfo;
class QTimer;

namespace legofeup::ui {

class BluetoothScan : public QObject {
    Q_OBJECT

  public:
    explicit BluetoothScan(QObject* parent = nullptr);
    ~BluetoothScan() override;

    /// Why this machine cannot scan (no system D-Bus, no BlueZ daemon, no adapter, the
    /// adapter off) and what to do, or an empty string when it can. Quick: no scan.
    static QString unavailableReason();

    /// Starts a scan of `seconds` (classic Bluetooth inquiry, as the NXT needs).
    void start(int seconds = 15);
    void stop();
    bool active() const { return active_; }

  signals:
    /// A device answered: its address ("00:16:53:0A:0B:0C") and name (may be empty).
    void deviceFound(const QString& address, const QString& name);
    /// The scan is over: `problem` is empty when it ran to its end, else why it failed.
    void finished(const QString& problem);

  private:
    void finish(const QString& problem);
    void discovered(const QBluetoothDeviceInfo& device);

    QBluetoothDeviceDiscoveryAgent* agent_ = nullptr;
    QTimer* limit_ = nullptr;
    bool active_ = false;
};

}  // namespace legofeup::ui
