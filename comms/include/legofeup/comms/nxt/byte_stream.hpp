#pragma once
// A reliable byte stream to or from a brick: an RFCOMM socket, a tty, a TCP socket or a
// pseudo-terminal. The NXT framing is the same on all of them (framing.hpp).

#include <chrono>
#include <cstdint>
#include <span>
#include <string>

#include "legofeup/comms/link_error.hpp"

namespace legofeup::comms::nxt {

/// No bytes came before the deadline. The stream is still usable.
class StreamTimeout : public LinkError {
  public:
    using LinkError::LinkError;
};

/// The other end went away (EOF, hang-up, reset) or the stream failed: it is unusable now.
class StreamClosed : public LinkError {
  public:
    using LinkError::LinkError;
};

class ByteStream {
  public:
    using Clock = std::chrono::steady_clock;
    virtual ~ByteStream() = default;

    /// Writes every byte (retrying short writes). Throws StreamClosed.
    virtual void write_all(std::span<const std::uint8_t> bytes) = 0;
    /// Reads exactly bytes.size() bytes, however the other end splits them, before
    /// `deadline`. Throws StreamTimeout (some bytes may have been consumed: the caller must
    /// then treat the framing as lost) or StreamClosed.
    virtual void read_exact(std::span<std::uint8_t> bytes, Clock::time_point deadline) = 0;
    /// Waits until at least one byte can be read (or the other end closed: the next read
    /// then throws StreamClosed). False if nothing came before `deadline`. Consumes nothing.
    virtual bool wait_readable(Clock::time_point deadline) = 0;
    /// Discards whatever has arrived and not been read (resynchronising after a timeout).
    virtual void discard_pending() = 0;
    virtual void close() = 0;
    /// "tcp:127.0.0.1:7000", "serial:/dev/rfcomm0", "bt:00:16:53:01:02:03".
    virtual std::string describe() const = 0;
};

}  // namespace legofeup::comms::nxt
