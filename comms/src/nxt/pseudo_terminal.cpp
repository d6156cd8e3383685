// A pseudo-terminal for the emulated brick: clients open its slave exactly as they open
// /dev/rfcomm0 (serial: addresses), so the serial path is tested without Bluetooth.
//
// The pair holds one slave fd open itself. Without it, the master sees a hang-up (POLLHUP,
// read() fails with EIO) whenever no client has the slave open — before the first client
// and after each one leaves — and the emulator would have to tell that apart from a failure.

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>

#include "legofeup/comms/nxt/transport.hpp"
#include "posix_fd.hpp"

namespace legofeup::comms::nxt {

PseudoTerminal::PseudoTerminal() {
    posix::UniqueFd master(::posix_openpt(O_RDWR | O_NOCTTY | O_CLOEXEC));
    if (!master.valid()) {
        throw LinkError("cannot create a pseudo-terminal: " + posix::error_text(errno)
                        + " — is /dev/pts mounted?");
    }
    std::array<char, 128> name{};
    if (::grantpt(master.get()) != 0 || ::unlockpt(master.get()) != 0
        || ::ptsname_r(master.get(), name.data(), name.size()) != 0) {
        throw LinkError("cannot unlock the pseudo-terminal's slave: " + posix::error_text(errno));
    }
    std::string path(name.data());
    posix::UniqueFd slave(::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC | O_NONBLOCK));
    if (!slave.valid()) {
        throw LinkError(path
                        + ": cannot open the pseudo-terminal's slave: " + posix::error_text(errno));
    }
    // Raw on both ends: the line discipline sits on the slave side, but a master left in
    // cooked mode would still translate bytes on some systems.
    make_raw_tty(slave.get(), path);
    make_raw_tty(master.get(), "the master of " + path);
    slave_path_ = std::move(path);
    master_fd_ = master.release();
    keep_slave_fd_ = slave.release();
}

PseudoTerminal::~PseudoTerminal() {
    posix::UniqueFd master(master_fd_);
    posix::UniqueFd slave(keep_slave_fd_);
}

std::unique_ptr<ByteStream> PseudoTerminal::take_master() {
    if (master_fd_ < 0) {
        throw std::logic_error("PseudoTerminal::take_master: the master was already taken");
    }
    return stream_from_fd(std::exchange(master_fd_, -1), "pty:" + slave_path_);
}

}  // namespace legofeup::comms::nxt
