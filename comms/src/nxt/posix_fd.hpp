#pragma once
// Small POSIX helpers the NXT transports share: an owning file descriptor, waiting on one
// with a deadline, and the system's reason for an errno as text.

#include <chrono>
#include <string>
#include <utility>

namespace legofeup::comms::nxt::posix {

using Clock = std::chrono::steady_clock;

/// Owns a file descriptor: closes it unless released. Keeps error paths free of leaks.
class UniqueFd {
  public:
    UniqueFd() = default;
    explicit UniqueFd(int fd) : fd_(fd) {}
    ~UniqueFd() { reset(); }
    UniqueFd(UniqueFd&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    UniqueFd& operator=(UniqueFd&& other) noexcept {
        if (this != &other) {
            reset();
            fd_ = std::exchange(other.fd_, -1);
        }
        return *this;
    }
    UniqueFd(const UniqueFd&) = delete;
    UniqueFd& operator=(const UniqueFd&) = delete;

    int get() const { return fd_; }
    bool valid() const { return fd_ >= 0; }
    int release() { return std::exchange(fd_, -1); }
    void reset();

  private:
    int fd_ = -1;
};

/// strerror for `error`, thread-safe: "Connection refused".
std::string error_text(int error);

/// Sets O_NONBLOCK (reads and writes then never block; poll() does the waiting).
void set_nonblocking(int fd);

/// Waits until `fd` reports one of `events` (or an error/hang-up) or `deadline` passes; an
/// interrupted wait resumes with the time left. Returns the revents, 0 on timeout, and −1
/// with errno set when poll() itself fails.
int wait_until(int fd, short events, Clock::time_point deadline);

/// "8 s", "250 ms": a timeout as messages show it.
std::string format_duration(std::chrono::milliseconds duration);

}  // namespace legofeup::comms::nxt::posix
