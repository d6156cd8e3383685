#include "legofeup/comms/udp_socket.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <ctime>
#include <system_error>
#include <utility>

#include "legofeup/comms/protocol.hpp"

namespace legofeup::comms {
namespace {

sockaddr_in to_sockaddr(const Endpoint& endpoint) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(endpoint.address);
    address.sin_port = htons(endpoint.port);
    return address;
}

Endpoint from_sockaddr(const sockaddr_in& address) {
    return {ntohl(address.sin_addr.s_addr), ntohs(address.sin_port)};
}

[[noreturn]] void throw_errno(const std::string& what) {
    throw std::system_error(errno, std::generic_category(), what);
}

/// ppoll rather than poll: microsecond timeouts, so a 1 kHz server is not paced in whole ms.
int wait_for(pollfd* entries, std::size_t count, std::chrono::microseconds timeout) {
    const std::int64_t us = std::max<std::int64_t>(0, timeout.count());
    timespec limit{};
    limit.tv_sec = us / 1'000'000;
    limit.tv_nsec = (us % 1'000'000) * 1000;
    return ::ppoll(entries, count, &limit, nullptr);
}

}  // namespace

UdpSocket::UdpSocket(const Endpoint& local) : buffer_(kMaxPacketSize + 1) {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    if (fd_ < 0) {
        throw_errno("cannot create a UDP socket");
    }
    // Room for bursts: at 1 kHz a 100 ms stall of the reader must not lose frames.
    const int buffer_bytes = 1 << 20;
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buffer_bytes, sizeof buffer_bytes);
    const sockaddr_in address = to_sockaddr(local);
    if (::bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        const int error = errno;
        ::close(fd_);
        fd_ = -1;
        errno = error;
        throw_errno("cannot bind " + local.to_string());
    }
    sockaddr_in bound{};
    socklen_t length = sizeof bound;
    ::getsockname(fd_, reinterpret_cast<sockaddr*>(&bound), &length);
    local_ = from_sockaddr(bound);
}

UdpSocket::~UdpSocket() {
    if (fd_ >= 0) {
        ::close(fd_);
    }
}

UdpSocket::UdpSocket(UdpSocket&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), local_(other.local_), buffer_(std::move(other.buffer_)) {}

UdpSocket& UdpSocket::operator=(UdpSocket&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) {
            ::close(fd_);
        }
        fd_ = std::exchange(other.fd_, -1);
        local_ = other.local_;
        buffer_ = std::move(other.buffer_);
    }
    return *this;
}

bool UdpSocket::send_to(std::span<const std::uint8_t> bytes, const Endpoint& to) {
    const sockaddr_in address = to_sockaddr(to);
    const ssize_t sent = ::sendto(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL,
                                  reinterpret_cast<const sockaddr*>(&address), sizeof address);
    return sent == static_cast<ssize_t>(bytes.size());
}

std::optional<Datagram> UdpSocket::receive(std::chrono::microseconds timeout) {
    for (;;) {
        sockaddr_in from{};
        socklen_t length = sizeof from;
        // MSG_TRUNC: the return value is the datagram's real size even when it was cut to
        // the buffer, so oversized packets are recognised rather than read as truncated.
        const ssize_t size = ::recvfrom(fd_, buffer_.data(), buffer_.size(), MSG_TRUNC,
                                        reinterpret_cast<sockaddr*>(&from), &length);
        if (size >= 0) {
            const auto full = static_cast<std::size_t>(size);
            return Datagram{
                std::span<const std::uint8_t>(buffer_.data(), std::min(full, buffer_.size())), full,
                from_sockaddr(from)};
        }
        if (errno == EINTR) {
            continue;
        }
        if (errno != EAGAIN) {    // EWOULDBLOCK is the same value on Linux
            return std::nullopt;  // e.g. ECONNREFUSED from an earlier send: nothing to read
        }
        if (timeout.count() <= 0) {
            return std::nullopt;
        }
        pollfd entry{fd_, POLLIN, 0};
        if (wait_for(&entry, 1, timeout) <= 0) {
            return std::nullopt;
        }
        timeout = std::chrono::microseconds(0);  // readable now: one more read, no more waiting
    }
}

std::vector<bool> wait_readable(std::span<UdpSocket* const> sockets,
                                std::chrono::microseconds timeout) {
    std::vector<pollfd> entries;
    entries.reserve(sockets.size());
    for (const UdpSocket* socket : sockets) {
        entries.push_back({socket->native_handle(), POLLIN, 0});
    }
    std::vector<bool> readable(sockets.size(), false);
    if (wait_for(entries.data(), entries.size(), timeout) > 0) {
        for (std::size_t i = 0; i < entries.size(); ++i) {
            readable[i] = (entries[i].revents & POLLIN) != 0;
        }
    }
    return readable;
}

}  // namespace legofeup::comms
