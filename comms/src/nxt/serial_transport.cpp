// serial:/dev/rfcomm0 — any tty: a bound rfcomm device (rfcomm bind 0 <address>), or the
// slave side of an emulator's pseudo-terminal. Raw mode, so that no byte of a telegram is
// taken for a line ending, an interrupt character or flow control.

#include <fcntl.h>
#include <termios.h>

#include <cerrno>

#include "transports.hpp"

namespace legofeup::comms::nxt {
namespace detail {
namespace {

/// "/dev/rfcomm3" → "3", anything else → "".
std::string rfcomm_number(const std::string& path) {
    constexpr std::string_view kPrefix = "/dev/rfcomm";
    if (path.rfind(kPrefix, 0) != 0 || path.size() == kPrefix.size()) {
        return "";
    }
    return path.substr(kPrefix.size());
}

/// What to do about an open() that failed with `error`.
std::string open_hint(const std::string& path, int error) {
    const std::string rfcomm = rfcomm_number(path);
    switch (error) {
        case ENOENT:
            if (!rfcomm.empty()) {
                return "bind it first: rfcomm bind " + rfcomm + " <address>";
            }
            return "check the device path (ls /dev/rfcomm* /dev/tty*)";
        case EACCES:
        case EPERM:
            return "add yourself to the dialout group (sudo usermod -aG dialout $USER) and log "
                   "in again";
        case EBUSY:
            return "another program has it open: close it";
        default:
            return "is the brick on, paired (PIN 1234) and bound to this device?";
    }
}

}  // namespace

std::unique_ptr<ByteStream> open_serial(const TransportAddress& address) {
    const std::string& path = address.target;
    // O_NONBLOCK: open() must not wait for a carrier (or an rfcomm connect); O_NOCTTY: the
    // device must never become this process's controlling terminal.
    posix::UniqueFd fd(::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK));
    if (!fd.valid()) {
        const int error = errno;
        throw LinkError(address.to_string() + ": " + posix::error_text(error) + " — "
                        + open_hint(path, error));
    }
    make_raw_tty(fd.get(), address.to_string());
    // Bytes left over from an earlier client (a reply nobody read) would put the framing out
    // of step: start clean.
    ::tcflush(fd.get(), TCIOFLUSH);
    return stream_from_fd(fd.release(), address.to_string());
}

}  // namespace detail

void make_raw_tty(int fd, const std::string& path) {
    termios settings{};
    if (::tcgetattr(fd, &settings) != 0) {
        const int error = errno;
        throw LinkError(path + ": not a terminal (" + posix::error_text(error)
                        + ") — expected a tty such as /dev/rfcomm0");
    }
    ::cfmakeraw(&settings);  // no echo, no line editing, no signals, 8 data bits, no parity
    settings.c_cflag |= CLOCAL | CREAD;  // ignore modem lines; receive
    settings.c_cc[VMIN] = 0;             // read() returns what there is: poll() does the waiting
    settings.c_cc[VTIME] = 0;
    if (::tcsetattr(fd, TCSANOW, &settings) != 0) {
        const int error = errno;
        throw LinkError(path + ": cannot set raw mode: " + posix::error_text(error));
    }
}

}  // namespace legofeup::comms::nxt
