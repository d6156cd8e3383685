#include "legofeup/ui/session/nxt_address.hpp"

#include <QObject>
#include <QRegularExpression>
#include <stdexcept>

#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/lessons/nxt_link_text.hpp"

namespace legofeup::ui {

QString normalized_nxt_address(const QString& text) {
    const QString trimmed = text.trimmed();
    if (lessons::is_nxt_link(trimmed.toStdString())) {
        return trimmed;
    }
    // Two hex digits then a colon: the start of a Bluetooth address, however it goes on (the
    // parser then says precisely what is wrong with the rest).
    static const QRegularExpression bluetooth(QStringLiteral("^[0-9A-Fa-f]{2}:"));
    if (bluetooth.match(trimmed).hasMatch()) {
        return QStringLiteral("bt:") + trimmed;
    }
    if (trimmed.startsWith(QLatin1Char('/'))) {
        return QStringLiteral("serial:") + trimmed;
    }
    return trimmed;
}

QString nxt_address_problem(const QString& text) {
    const QString address = normalized_nxt_address(text);
    if (address.isEmpty()) {
        return QObject::tr(
            "Type the brick's address: bt:00:16:53:XX:XX:XX, serial:/dev/rfcomm0 or "
            "tcp:HOST:PORT");
    }
    try {
        comms::nxt::parse_transport_address(address.toStdString());
    } catch (const std::invalid_argument& error) {
        return QString::fromStdString(error.what());
    }
    return {};
}

bool is_lego_bluetooth_address(const QString& address) {
    return address.trimmed().startsWith(QLatin1String(kLegoBluetoothPrefix), Qt::CaseInsensitive);
}

}  // namespace legofeup::ui
