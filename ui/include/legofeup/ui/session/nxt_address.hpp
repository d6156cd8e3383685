#pragma once
// The NXT's address as a student types it into the connect dialog: "bt:00:16:53:01:02:03",
// "serial:/dev/rfcomm0", "tcp:127.0.0.1:5700" (docs/nxt.md), or the short forms the dialog
// also takes — a bare Bluetooth address "00:16:53:01:02:03" (bt:) and a bare device path
// "/dev/rfcomm0" (serial:).

#include <QString>

namespace legofeup::ui {

/// The address with its transport spelled out: a bare XX:XX:… gets "bt:", a bare /path
/// "serial:"; anything else is returned trimmed, as typed.
QString normalized_nxt_address(const QString& text);

/// Why `text` is not an address the NXT link can open (comms::nxt::parse_transport_address's
/// own words), or an empty string when it is.
QString nxt_address_problem(const QString& text);

/// The LEGO Group's Bluetooth vendor prefix: every NXT's address starts with it.
inline constexpr const char* kLegoBluetoothPrefix = "00:16:53";

/// Whether a Bluetooth address ("00:16:53:0a:…", any case) belongs to a LEGO brick.
bool is_lego_bluetooth_address(const QString& address);

}  // namespace legofeup::ui
