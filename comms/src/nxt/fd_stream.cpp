// A ByteStream over a file descriptor: RFCOMM and TCP sockets, ttys and pty masters alike.
// The fd is non-blocking and poll() does the waiting, so every read honours its deadline
// however the other end splits its bytes.
//
// How "the other end went away" shows, and why each is StreamClosed:
//  - sockets: read() returns 0 (orderly close) or fails with ECONNRESET; writes fail EPIPE;
//  - a pty master whose slave side has no open fd: POLLHUP and read() fails with EIO;
//  - a pty slave or tty whose master or device is gone: read() returns 0 or fails with EIO.
// A socket write uses send(MSG_NOSIGNAL): a peer that closed must give EPIPE, not a SIGPIPE
// that kills the program.

#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>

#include "legofeup/comms/nxt/transport.hpp"
#include "posix_fd.hpp"

namespace legofeup::comms::nxt {
namespace {

/// A write that makes no progress for this long means nobody reads the other end.
constexpr std::chrono::seconds kWriteStallLimit{5};
/// discard_pending() reads at most this much: a peer that never stops sending cannot hold it.
constexpr std::size_t kMaxDiscard = 1 << 20;

class FdStream final : public ByteStream {
  public:
    FdStream(posix::UniqueFd fd, std::string description)
        : fd_(std::move(fd)),
          description_(std::move(description)),
          is_socket_(is_socket(fd_.get())) {
        posix::set_nonblocking(fd_.get());
    }

    void write_all(std::span<const std::uint8_t> bytes) override {
        require_open();
        std::size_t done = 0;
        auto deadline = Clock::now() + kWriteStallLimit;
        while (done < bytes.size()) {
            const ssize_t n = write_some(bytes.subspan(done));
            if (n > 0) {
                done += static_cast<std::size_t>(n);
                deadline = Clock::now() + kWriteStallLimit;
                continue;
            }
            if (errno == EINTR) {
                continue;
            }
            if (errno != EAGAIN) {
                closed_by_error("write failed");
            }
            const int ready = posix::wait_until(fd_.get(), POLLOUT, deadline);
            if (ready == 0) {
                throw StreamClosed(description_ + ": the other end has not taken any data for "
                                   + std::to_string(kWriteStallLimit.count())
                                   + " s — it is not reading; closing");
            }
            if (ready < 0) {
                closed_by_error("poll failed");
            }
            // POLLOUT, POLLERR or POLLHUP: the next write tells which.
        }
    }

    void read_exact(std::span<std::uint8_t> bytes, Clock::time_point deadline) override {
        require_open();
        std::size_t done = 0;
        bool hung_up = false;
        while (done < bytes.size()) {
            const ssize_t n = ::read(fd_.get(), bytes.data() + done, bytes.size() - done);
            if (n > 0) {
                done += static_cast<std::size_t>(n);
                continue;
            }
            // A socket's 0 is the end. A tty in raw mode (VMIN = VTIME = 0) also returns 0
            // when it merely has no data; only after poll() saw a hang-up is it the end.
            if (n == 0 && (is_socket_ || hung_up)) {
                throw StreamClosed(description_ + ": closed by the other end");
            }
            if (n < 0 && errno == EINTR) {
                continue;
            }
            if (n < 0 && errno == EIO) {
                // A pty whose other side closed, a tty whose device went away.
                throw StreamClosed(description_ + ": the other end hung up (Input/output error)");
            }
            if (n < 0 && errno != EAGAIN) {
                closed_by_error("read failed");  // ECONNRESET, …
            }
            const int ready = posix::wait_until(fd_.get(), POLLIN, deadline);
            if (ready == 0) {
                throw StreamTimeout(description_ + ": no data before the deadline ("
                                    + std::to_string(done) + " of " + std::to_string(bytes.size())
                                    + " bytes arrived)");
            }
            if (ready < 0) {
                closed_by_error("poll failed");
            }
            if ((ready & POLLNVAL) != 0) {
                throw StreamClosed(description_ + ": the file descriptor is not open");
            }
            hung_up = (ready & POLLHUP) != 0;
            // POLLIN, POLLHUP or POLLERR: read again. Bytes that arrived before a hang-up are
            // still delivered; after them read() reports the end (0 or EIO).
        }
    }

    bool wait_readable(Clock::time_point deadline) override {
        if (!fd_.valid()) {
            return true;  // the next read reports the closed stream
        }
        // A hang-up or an error counts as readable: the next read_exact() throws it.
        const int ready = posix::wait_until(fd_.get(), POLLIN, deadline);
        if (ready < 0) {
            closed_by_error("poll failed");
        }
        return ready != 0;
    }

    void discard_pending() override {
        if (!fd_.valid()) {
            return;
        }
        std::array<std::uint8_t, 256> sink{};
        std::size_t discarded = 0;
        while (discarded < kMaxDiscard) {
            const ssize_t n = ::read(fd_.get(), sink.data(), sink.size());
            if (n > 0) {
                discarded += static_cast<std::size_t>(n);
            } else if (n < 0 && errno == EINTR) {
                continue;
            } else {
                return;  // drained (EAGAIN), or closed: the next read reports that
            }
        }
    }

    void close() override { fd_.reset(); }

    std::string describe() const override { return description_; }

  private:
    static bool is_socket(int fd) {
        struct stat info {};
        return ::fstat(fd, &info) == 0 && S_ISSOCK(info.st_mode);
    }

    ssize_t write_some(std::span<const std::uint8_t> bytes) const {
        if (is_socket_) {
            return ::send(fd_.get(), bytes.data(), bytes.size(), MSG_NOSIGNAL);
        }
        return ::write(fd_.get(), bytes.data(), bytes.size());
    }

    void require_open() const {
        if (!fd_.valid()) {
            throw StreamClosed(description_ + ": the stream was closed");
        }
    }

    [[noreturn]] void closed_by_error(const char* what) const {
        throw StreamClosed(description_ + ": " + what + ": " + posix::error_text(errno));
    }

    posix::UniqueFd fd_;
    std::string description_;
    bool is_socket_;
};

}  // namespace

std::unique_ptr<ByteStream> stream_from_fd(int fd, std::string description) {
    // Owned from here on: closed even if the stream cannot be made.
    return std::make_unique<FdStream>(posix::UniqueFd(fd), std::move(description));
}

}  // namespace legofeup::comms::nxt
