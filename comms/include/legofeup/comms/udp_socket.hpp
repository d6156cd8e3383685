#pragma once
// A bound UDP socket (POSIX), owned and closed by this object. Non-blocking underneath:
// receive() waits at most its timeout, so no caller can stall on a silent peer.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "legofeup/comms/endpoint.hpp"

namespace legofeup::comms {

struct Datagram {
    std::span<const std::uint8_t> bytes;  ///< valid until the next receive on the socket
    std::size_t full_size = 0;            ///< the datagram's real size (> bytes.size() if cut)
    Endpoint from;
};

class UdpSocket {
  public:
    /// Binds to `local` (port 0 picks a free port). Throws std::system_error naming the
    /// address, e.g. "cannot bind 127.0.0.1:5600: Address already in use".
    explicit UdpSocket(const Endpoint& local);
    ~UdpSocket();
    UdpSocket(UdpSocket&& other) noexcept;
    UdpSocket& operator=(UdpSocket&& other) noexcept;
    UdpSocket(const UdpSocket&) = delete;
    UdpSocket& operator=(const UdpSocket&) = delete;

    /// The address actually bound (the chosen port when bound to port 0).
    Endpoint local_endpoint() const { return local_; }

    /// Sends one datagram; false if the kernel refused it (e.g. no route, buffer full).
    bool send_to(std::span<const std::uint8_t> bytes, const Endpoint& to);

    /// The next datagram, waiting up to `timeout` (zero: only what is already queued).
    std::optional<Datagram> receive(std::chrono::microseconds timeout);

    int native_handle() const { return fd_; }

  private:
    int fd_ = -1;
    Endpoint local_;
    std::vector<std::uint8_t> buffer_;
};

/// Waits until one of `sockets` has a datagram or `timeout` passes; returns for each socket
/// whether it is readable. Interrupted waits (signals) return all false.
std::vector<bool> wait_readable(std::span<UdpSocket* const> sockets,
                                std::chrono::microseconds timeout);

}  // namespace legofeup::comms
