#pragma once
// The three ways open_transport() reaches a brick, one file each, and the non-blocking
// connect with a deadline that the two socket transports share.

#include <sys/socket.h>

#include <chrono>
#include <memory>

#include "legofeup/comms/nxt/transport.hpp"
#include "posix_fd.hpp"

namespace legofeup::comms::nxt::detail {

std::unique_ptr<ByteStream> open_bluetooth(const TransportAddress& address,
                                           std::chrono::milliseconds timeout);
std::unique_ptr<ByteStream> open_serial(const TransportAddress& address);
std::unique_ptr<ByteStream> open_tcp(const TransportAddress& address,
                                     std::chrono::milliseconds timeout);

/// connect() on a non-blocking socket, waiting at most until `deadline`. Returns 0 when
/// connected, else the errno: the socket's own error, or ETIMEDOUT when the deadline passed.
int connect_until(int fd, const sockaddr* address, socklen_t length,
                  posix::Clock::time_point deadline);

}  // namespace legofeup::comms::nxt::detail
