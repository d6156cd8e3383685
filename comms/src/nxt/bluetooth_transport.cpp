// bt:XX:XX:XX:XX:XX:XX — a BlueZ RFCOMM socket to the brick's serial port profile, which the
// NXT offers on channel 1. The brick must be paired first (PIN 1234 by default), and it takes
// one connection at a time.

#include <bluetooth/bluetooth.h>
#include <bluetooth/rfcomm.h>
#include <sys/socket.h>

#include <cerrno>

#include "transports.hpp"

namespace legofeup::comms::nxt::detail {
namespace {

constexpr std::uint8_t kNxtRfcommChannel = 1;

/// What to check when the brick does not answer: the usual causes, in the order to try them.
std::string brick_hint(const std::string& address) {
    return "is the brick on, Bluetooth visible and paired (bluetoothctl pair " + address
           + ", PIN 1234)?";
}

[[noreturn]] void bluetooth_connect_failed(const TransportAddress& address, int error,
                                           std::chrono::milliseconds timeout) {
    const std::string where = address.to_string() + ": ";
    switch (error) {
        case ETIMEDOUT:
            throw LinkError(where + "connect timed out after " + posix::format_duration(timeout)
                            + " — " + brick_hint(address.target));
        case ENODEV:
        case ENETDOWN:
        case EADDRNOTAVAIL:
            throw LinkError(where + "connect failed: " + posix::error_text(error)
                            + " — no Bluetooth adapter is up: check bluetoothctl show, then "
                              "bluetoothctl power on");
        case EBUSY:
        case EISCONN:
        case EALREADY:
            throw LinkError(where + "connect failed: " + posix::error_text(error)
                            + " — the brick takes one connection at a time: close the other "
                              "program (or release a bound /dev/rfcomm: rfcomm release 0)");
        case EACCES:
        case EPERM:
            throw LinkError(where + "connect failed: " + posix::error_text(error)
                            + " — not allowed to use Bluetooth here; pair the brick first "
                              "(bluetoothctl pair " + address.target + ", PIN 1234)");
        default:
            throw LinkError(where + "connect failed: " + posix::error_text(error) + " — "
                            + brick_hint(address.target));
    }
}

}  // namespace

std::unique_ptr<ByteStream> open_bluetooth(const TransportAddress& address,
                                           std::chrono::milliseconds timeout) {
    const auto deadline = posix::Clock::now() + timeout;
    posix::UniqueFd fd(
        ::socket(AF_BLUETOOTH, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, BTPROTO_RFCOMM));
    if (!fd.valid()) {
        const int error = errno;
        throw LinkError(address.to_string() + ": cannot create a Bluetooth socket: "
                        + posix::error_text(error)
                        + " — this computer has no Bluetooth support (no adapter, or the "
                          "bluetooth kernel module is not loaded); check bluetoothctl show, or "
                          "use serial:/dev/rfcomm0 after rfcomm bind 0 "
                        + address.target);
    }
    sockaddr_rc remote{};
    remote.rc_family = AF_BLUETOOTH;
    remote.rc_channel = kNxtRfcommChannel;
    // str2ba reverses the bytes into BlueZ's little-endian bdaddr_t; the text was checked by
    // parse_transport_address().
    if (::str2ba(address.target.c_str(), &remote.rc_bdaddr) != 0) {
        throw LinkError(address.to_string() + ": not a Bluetooth address");
    }
    const int error = connect_until(fd.get(), reinterpret_cast<const sockaddr*>(&remote),
                                    sizeof remote, deadline);
    if (error != 0) {
        bluetooth_connect_failed(address, error, timeout);
    }
    return stream_from_fd(fd.release(), address.to_string());
}

}  // namespace legofeup::comms::nxt::detail
