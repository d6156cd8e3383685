// tcp:HOST:PORT — an emulated brick, or a bridge that forwards to a real one. IPv4 only;
// TCP_NODELAY because telegrams are a few bytes and each one waits for its answer.

#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <cerrno>
#include <memory>

#include "transports.hpp"

namespace legofeup::comms::nxt::detail {
namespace {

struct AddrInfoDeleter {
    void operator()(addrinfo* list) const { ::freeaddrinfo(list); }
};
using AddrInfoList = std::unique_ptr<addrinfo, AddrInfoDeleter>;

AddrInfoList resolve(const TransportAddress& address) {
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* list = nullptr;
    const std::string port = std::to_string(address.port);
    const int error = ::getaddrinfo(address.target.c_str(), port.c_str(), &hints, &list);
    if (error != 0) {
        throw LinkError(address.to_string() + ": cannot resolve '" + address.target
                        + "': " + ::gai_strerror(error)
                        + " — check the host name, or give an IPv4 address");
    }
    return AddrInfoList(list);
}

[[noreturn]] void tcp_connect_failed(const TransportAddress& address, int error,
                                     std::chrono::milliseconds timeout) {
    const std::string where = address.to_string() + ": ";
    if (error == ETIMEDOUT) {
        throw LinkError(where + "connect timed out after " + posix::format_duration(timeout)
                        + " — is the host reachable and the port open?");
    }
    if (error == ECONNREFUSED) {
        throw LinkError(where + "connection refused — is the emulated brick (or the bridge) "
                                "running and listening on port "
                        + std::to_string(address.port) + "?");
    }
    throw LinkError(where + "connect failed: " + posix::error_text(error));
}

}  // namespace

std::unique_ptr<ByteStream> open_tcp(const TransportAddress& address,
                                     std::chrono::milliseconds timeout) {
    const auto deadline = posix::Clock::now() + timeout;
    const AddrInfoList list = resolve(address);
    int error = ECONNREFUSED;
    // Each resolved address in turn, all within the one deadline.
    for (const addrinfo* entry = list.get(); entry != nullptr; entry = entry->ai_next) {
        posix::UniqueFd fd(
            ::socket(entry->ai_family, entry->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
        if (!fd.valid()) {
            error = errno;
            continue;
        }
        error = connect_until(fd.get(), entry->ai_addr, entry->ai_addrlen, deadline);
        if (error == 0) {
            const int on = 1;
            ::setsockopt(fd.get(), IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
            return stream_from_fd(fd.release(), address.to_string());
        }
        if (error == ETIMEDOUT) {
            break;  // the deadline is spent: no time left for the next address
        }
    }
    tcp_connect_failed(address, error, timeout);
}

}  // namespace legofeup::comms::nxt::detail
