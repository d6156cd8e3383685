#include "legofeup/ui/window/bluetooth_scan.hpp"

#include <QBluetoothDeviceDiscoveryAgent>
#include <QBluetoothDeviceInfo>
#include <QBluetoothLocalDevice>
#include <QDBusConnection>
#include <QDBusConnectionInterface>
#include <QTimer>

namespace legofeup::ui {

BluetoothScan::BluetoothScan(QObject* parent) : QObject(parent) {
    limit_ = new QTimer(this);
    limit_->setSingleShot(true);
    connect(limit_, &QTimer::timeout, this, [this] {
        if (agent_ != nullptr) {
            agent_->stop();
        }
        finish({});
    });
}

BluetoothScan::~BluetoothScan() = default;

QString BluetoothScan::unavailableReason() {
    const QString type_it = tr("Type the brick's address instead (bt:00:16:53:…).");
    QDBusConnection bus = QDBusConnection::systemBus();
    if (!bus.isConnected()) {
        return tr("Cannot scan: there is no system D-Bus, so no BlueZ daemon (bluetoothd) to "
                  "ask. Start it (sudo systemctl start bluetooth) to scan. %1")
            .arg(type_it);
    }
    if (bus.interface() == nullptr
        || !bus.interface()->isServiceRegistered(QStringLiteral("org.bluez")).value()) {
        return tr("Cannot scan: the BlueZ daemon (bluetoothd) is not running. Start it with "
                  "sudo systemctl start bluetooth. %1")
            .arg(type_it);
    }
    if (QBluetoothLocalDevice::allDevices().isEmpty()) {
        return tr("Cannot scan: BlueZ finds no Bluetooth adapter. Plug one in, or unblock it "
                  "(rfkill unblock bluetooth). %1")
            .arg(type_it);
    }
    if (QBluetoothLocalDevice().hostMode() == QBluetoothLocalDevice::HostPoweredOff) {
        return tr("Cannot scan: the Bluetooth adapter is switched off (bluetoothctl power "
                  "on). %1")
            .arg(type_it);
    }
    return {};
}

void BluetoothScan::start(int seconds) {
    stop();
    active_ = true;
    const QString reason = unavailableReason();
    if (!reason.isEmpty()) {
        // Reported from the event loop, like every other outcome.
        QTimer::singleShot(0, this, [this, reason] { finish(reason); });
        return;
    }
    if (agent_ == nullptr) {
        agent_ = new QBluetoothDeviceDiscoveryAgent(this);
        connect(agent_, &QBluetoothDeviceDiscoveryAgent::deviceDiscovered, this,
                &BluetoothScan::discovered);
        connect(agent_, &QBluetoothDeviceDiscoveryAgent::finished, this, [this] { finish({}); });
        connect(agent_, &QBluetoothDeviceDiscoveryAgent::canceled, this, [this] { finish({}); });
        // Queued: the agent may report an error from inside start().
        connect(
            agent_, &QBluetoothDeviceDiscoveryAgent::errorOccurred, this,
            [this] { finish(tr("The scan failed: %1").arg(agent_->errorString())); },
            Qt::QueuedConnection);
    }
    limit_->start(seconds * 1000);
    agent_->start(QBluetoothDeviceDiscoveryAgent::ClassicMethod);
}

void BluetoothScan::stop() {
    limit_->stop();
    if (agent_ != nullptr && agent_->isActive()) {
        agent_->stop();
    }
    active_ = false;
}

void BluetoothScan::discovered(const QBluetoothDeviceInfo& device) {
    emit deviceFound(device.address().toString(), device.name());
}

void BluetoothScan::finish(const QString& problem) {
    if (!active_) {
        return;  // one report per scan
    }
    active_ = false;
    limit_->stop();
    emit finished(problem);
}

}  // namespace legofeup::ui
