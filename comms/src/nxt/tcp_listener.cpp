// The listening end of tcp: addresses, for an emulated brick or a bridge. One client at a
// time is the emulator's business; the listener only hands over each connection.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

#include "legofeup/comms/nxt/transport.hpp"
#include "posix_fd.hpp"

namespace legofeup::comms::nxt {
namespace {

/// "tcp:127.0.0.1:7000"
std::string describe(const sockaddr_in& address) {
    std::array<char, INET_ADDRSTRLEN> text{};
    ::inet_ntop(AF_INET, &address.sin_addr, text.data(), text.size());
    return "tcp:" + std::string(text.data()) + ":" + std::to_string(ntohs(address.sin_port));
}

}  // namespace

TcpListener::TcpListener(std::uint32_t address, std::uint16_t port) {
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(address);
    local.sin_port = htons(port);
    posix::UniqueFd fd(::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0));
    if (!fd.valid()) {
        throw LinkError("cannot create a TCP socket: " + posix::error_text(errno));
    }
    // A restarted emulator can listen again at once, without waiting out TIME_WAIT.
    const int on = 1;
    ::setsockopt(fd.get(), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
    if (::bind(fd.get(), reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0
        || ::listen(fd.get(), 4) != 0) {
        const int error = errno;
        throw LinkError("cannot listen on " + describe(local) + ": " + posix::error_text(error)
                        + (error == EADDRINUSE ? " — is another emulator running? Choose "
                                                 "another port, or 0 for any free one"
                                               : ""));
    }
    sockaddr_in bound{};
    socklen_t length = sizeof bound;
    ::getsockname(fd.get(), reinterpret_cast<sockaddr*>(&bound), &length);
    port_ = ntohs(bound.sin_port);
    fd_ = fd.release();
}

TcpListener::~TcpListener() {
    posix::UniqueFd closing(fd_);
}

std::unique_ptr<ByteStream> TcpListener::accept(std::chrono::milliseconds timeout) {
    const auto deadline = posix::Clock::now() + timeout;
    for (;;) {
        sockaddr_in peer{};
        socklen_t length = sizeof peer;
        const int client =
            ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &length, SOCK_CLOEXEC);
        if (client >= 0) {
            const int on = 1;
            ::setsockopt(client, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
            return stream_from_fd(client, describe(peer));
        }
        // ECONNABORTED: a client that gave up while queued; wait for the next one.
        if (errno != EAGAIN && errno != EINTR && errno != ECONNABORTED) {
            throw LinkError("accept on tcp port " + std::to_string(port_)
                            + " failed: " + posix::error_text(errno));
        }
        if (errno == EAGAIN) {
            const int ready = posix::wait_until(fd_, POLLIN, deadline);
            if (ready == 0) {
                return nullptr;
            }
            if (ready < 0) {
                throw LinkError("waiting for a client on tcp port " + std::to_string(port_)
                                + " failed: " + posix::error_text(errno));
            }
        }
    }
}

}  // namespace legofeup::comms::nxt
