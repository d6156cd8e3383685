#pragma once
// The Bluetooth link of the emulated brick: serves one host over a byte stream (a TCP
// connection or a pseudo-terminal's master) with the NXT framing, and delays each direction
// like the real link does.
//
// Latency model (a delay line in each direction, docs/nxt-emulator.md): a telegram is handed
// to the firmware `up` after it was completely received; its reply is written `down` after
// the firmware produced it. Several telegrams may be in flight each way, so four requests
// written at once come back as four replies after one round trip (up + down), not four.
//
// Failures it can inject, for tests and rehearsals:
//  - drop: at a time after the first telegram of the first session the connection is closed
//    (the plug is pulled): telegrams in flight are lost; the next client is served normally.
//  - freeze: from a time after the first telegram the brick stops answering (replies are
//    discarded) but keeps reading, and the commands still reach the firmware; every
//    SETOUTPUTSTATE that stops a motor is logged, to check the host stops the robot.
//
// A framing error (a length of 0 or over 64) ends the session: the stream is out of step and
// nothing after it can be trusted, so the connection is closed, as if the link dropped.

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "legofeup/comms/nxt/byte_stream.hpp"
#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::nxtemu {

struct BrickServerOptions {
    std::chrono::microseconds latency_up{30'000};    ///< host → brick
    std::chrono::microseconds latency_down{30'000};  ///< brick → host
    /// Seconds after the first telegram of the first session; unset: never.
    std::optional<double> drop_after;
    std::optional<double> freeze_after;
    /// Events worth telling a person ("client connected", "frozen", warnings). May be empty.
    std::function<void(const std::string&)> log;
};

/// Everything the link has seen since the server was made.
struct BrickServerCounters {
    std::uint64_t sessions = 0;
    std::uint64_t telegrams_in = 0;
    std::uint64_t replies_out = 0;
    std::uint64_t no_reply_telegrams = 0;  ///< handled, nothing to send back
    std::uint64_t framing_errors = 0;
    std::uint64_t clients_gone = 0;  ///< sessions the host ended (closed, reset)
    std::uint64_t injected_drops = 0;
    std::uint64_t replies_frozen = 0;  ///< replies discarded while frozen
    std::uint64_t stop_commands_while_frozen = 0;
    std::uint64_t lost_in_flight = 0;  ///< telegrams and replies a drop or stop threw away
};

enum class SessionEnd {
    ClientGone,    ///< the host closed the connection (or it failed)
    FramingError,  ///< out of step: closed by the brick
    Dropped,       ///< the injected drop
    Stopped,       ///< stop() was called
};
const char* to_string(SessionEnd end);

class BrickServer {
  public:
    /// Handles one request telegram; returns the reply, or nullopt for none. Called on the
    /// server's own thread, one telegram at a time.
    using Handler =
        std::function<std::optional<comms::nxt::Telegram>(std::span<const std::uint8_t>)>;

    BrickServer(Handler handler, BrickServerOptions options);
    ~BrickServer();
    BrickServer(const BrickServer&) = delete;
    BrickServer& operator=(const BrickServer&) = delete;

    /// Serves one host over `stream` until the session ends, and says why. Telegrams
    /// received before the host went away still reach the handler (at their time); replies
    /// to a host that is gone are not written. The stream is closed on return. Blocks; one
    /// call per stream (several streams may be served at once from different threads).
    SessionEnd serve(comms::nxt::ByteStream& stream);
    /// Ends every session within about 100 ms, now and from now on. Any thread.
    void stop();
    BrickServerCounters counters() const;

  private:
    struct State;
    struct Session;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::nxtemu
