// A connect() that cannot hang: BlueZ's RFCOMM connect waits for paging, which takes up to
// tens of seconds when the brick is off, and a TCP SYN to a silent host is retried for
// minutes. The socket is non-blocking, so connect() returns EINPROGRESS at once and poll()
// waits for it with the caller's deadline.

#include <poll.h>

#include <cerrno>

#include "transports.hpp"

namespace legofeup::comms::nxt::detail {

int connect_until(int fd, const sockaddr* address, socklen_t length,
                  posix::Clock::time_point deadline) {
    if (::connect(fd, address, length) == 0) {
        return 0;
    }
    // EINTR: the connect goes on in the background, exactly as after EINPROGRESS.
    if (errno != EINPROGRESS && errno != EINTR) {
        return errno;
    }
    const int ready = posix::wait_until(fd, POLLOUT, deadline);
    if (ready == 0) {
        return ETIMEDOUT;
    }
    if (ready < 0) {
        return errno;
    }
    // Writable means finished, one way or the other: SO_ERROR says which.
    int error = 0;
    socklen_t size = sizeof error;
    if (::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size) != 0) {
        return errno;
    }
    return error;
}

}  // namespace legofeup::comms::nxt::detail
