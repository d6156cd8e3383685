// The emulated Bluetooth link: per session, the reader (the serving thread) frames telegrams
// off the stream and queues each one for the firmware `up` later; a delay-line thread hands
// them to the handler when due, queues each reply `down` later, and writes it when due.

#include "legofeup/nxtemu/brick_server.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <variant>

#include "legofeup/comms/nxt/framing.hpp"

namespace legofeup::nxtemu {
namespace {

namespace nxt = comms::nxt;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// How often the reader looks at stop() and the failure times while the host is quiet.
constexpr auto kPollInterval = 100ms;
/// Once a telegram's first byte arrived, the rest must follow within this.
constexpr auto kRestOfTelegram = 2s;

struct InFlight {
    Clock::time_point due;
    nxt::Telegram telegram;
};

/// A SETOUTPUTSTATE that leaves its motor(s) still: what a host sends to stop the robot.
std::optional<std::uint8_t> stopped_port(std::span<const std::uint8_t> telegram) {
    const nxt::DecodedRequest request = nxt::decode_request(telegram);
    if (!request.body) {
        return std::nullopt;
    }
    const auto* set = std::get_if<nxt::SetOutputState>(&*request.body);
    if (set == nullptr) {
        return std::nullopt;
    }
    const nxt::OutputState& s = set->state;
    const bool still =
        (s.mode & nxt::kModeMotorOn) == 0 || s.power == 0 || s.run_state == nxt::kRunStateIdle;
    return still ? std::optional<std::uint8_t>(s.port) : std::nullopt;
}

std::string seconds_text(Clock::duration duration) {
    std::array<char, 32> text{};
    std::snprintf(text.data(), text.size(), "%.3f s",
                  std::chrono::duration<double>(duration).count());
    return text.data();
}

}  // namespace

const char* to_string(SessionEnd end) {
    switch (end) {
        case SessionEnd::ClientGone:
            return "the host went away";
        case SessionEnd::FramingError:
            return "framing error";
        case SessionEnd::Dropped:
            return "dropped (injected)";
        case SessionEnd::Stopped:
            return "stopped";
    }
    return "?";
}

struct BrickServer::State {
    State(Handler h, BrickServerOptions o) : handler(std::move(h)), options(std::move(o)) {}

    void log(const std::string& message) const {
        if (options.log) {
            options.log(message);
        }
    }

    template <typename Change>
    void count(Change change) {
        const std::lock_guard lock(mutex);
        change(counters);
    }

    /// The first telegram of the server's life starts the failure clocks.
    void first_telegram(Clock::time_point now) {
        const std::lock_guard lock(mutex);
        if (first_telegram_time) {
            return;
        }
        first_telegram_time = now;
        const auto at = [&](double seconds) {
            return now
                   + std::chrono::duration_cast<Clock::duration>(
                       std::chrono::duration<double>(seconds));
        };
        if (options.drop_after) {
            drop_at = at(*options.drop_after);
        }
        if (options.freeze_after) {
            freeze_at = at(*options.freeze_after);
        }
    }

    /// True once, for the session that reaches `when` first.
    bool claim(std::optional<Clock::time_point>& when, Clock::time_point now) {
        const std::lock_guard lock(mutex);
        if (when && now >= *when) {
            when.reset();
            return true;
        }
        return false;
    }

    std::optional<Clock::time_point> pending_drop() const {
        const std::lock_guard lock(mutex);
        return drop_at;
    }

    std::string since_first(Clock::time_point now) const {
        const std::lock_guard lock(mutex);
        return first_telegram_time ? seconds_text(now - *first_telegram_time) : "?";
    }

    Handler handler;
    BrickServerOptions options;
    std::atomic<bool> stopping{false};
    mutable std::mutex mutex;  // guards what follows
    BrickServerCounters counters;
    std::optional<Clock::time_point> first_telegram_time;
    std::optional<Clock::time_point> drop_at;    ///< reset once claimed
    std::optional<Clock::time_point> freeze_at;  ///< reset once claimed
};

struct BrickServer::Session {
    Session(State& s, nxt::ByteStream& out) : server(s), stream(out) {}

    /// The reader: frames telegrams until the session ends.
    SessionEnd read_telegrams() {
        for (;;) {
            if (server.stopping) {
                return SessionEnd::Stopped;
            }
            const Clock::time_point now = Clock::now();
            if (server.claim(server.drop_at, now)) {
                server.log("pulling the plug " + server.since_first(now)
                           + " after the first telegram (--drop-after)");
                return SessionEnd::Dropped;
            }
            Clock::time_point deadline = now + kPollInterval;
            if (const auto drop = server.pending_drop()) {
                deadline = std::min(deadline, *drop);
            }
            std::array<std::uint8_t, 2> length{};
            try {
                // One byte at a time until a telegram starts: a timeout then consumed nothing.
                stream.read_exact(std::span(length).first(1), deadline);
            } catch (const nxt::StreamTimeout&) {
                continue;
            } catch (const nxt::StreamClosed&) {
                return SessionEnd::ClientGone;
            }
            std::optional<nxt::Telegram> telegram;
            try {
                telegram = read_rest(length);
            } catch (const nxt::StreamTimeout&) {
                server.log("the host stopped in the middle of a telegram: closing");
                return SessionEnd::FramingError;
            } catch (const nxt::StreamClosed&) {
                return SessionEnd::ClientGone;
            }
            if (!telegram) {
                server.log("frame length " + std::to_string(length[0] | (length[1] << 8))
                           + " (expected 1..64): the stream is out of step, closing");
                return SessionEnd::FramingError;
            }
            received(std::move(*telegram));
        }
    }

    /// The second length byte and the telegram; nullopt for an impossible length.
    std::optional<nxt::Telegram> read_rest(std::array<std::uint8_t, 2>& length) {
        const Clock::time_point deadline = Clock::now() + kRestOfTelegram;
        stream.read_exact(std::span(length).subspan(1), deadline);
        const std::size_t size = std::size_t{length[0]} | (std::size_t{length[1]} << 8);
        if (size == 0 || size > nxt::kMaxTelegramSize) {
            return std::nullopt;
        }
        nxt::Telegram telegram(size);
        stream.read_exact(telegram, deadline);
        return telegram;
    }

    void received(nxt::Telegram telegram) {
        const Clock::time_point now = Clock::now();
        server.first_telegram(now);
        server.count([](BrickServerCounters& c) { ++c.telegrams_in; });
        if (is_frozen(now)) {
            if (const auto port = stopped_port(telegram)) {
                server.count([](BrickServerCounters& c) { ++c.stop_commands_while_frozen; });
                server.log("frozen: a stop-motors SETOUTPUTSTATE (port " + std::to_string(*port)
                           + ") arrived " + server.since_first(now) + " after the first telegram");
            }
        }
        {
            const std::lock_guard lock(mutex);
            up.push_back({now + server.options.latency_up, std::move(telegram)});
        }
        wake.notify_one();
    }

    bool is_frozen(Clock::time_point now) {
        if (!frozen && server.claim(server.freeze_at, now)) {
            frozen = true;
            server.log("freezing: no more replies on this connection (--freeze-after), "
                       + server.since_first(now) + " after the first telegram");
        }
        return frozen;
    }

    /// The delay line: hands telegrams to the firmware and writes replies, each when due.
    void run_delay_line() {
        std::unique_lock lock(mutex);
        for (;;) {
            if (abort || (input_ended && up.empty())) {
                const std::size_t lost = up.size() + down.size();
                server.count([&](BrickServerCounters& c) { c.lost_in_flight += lost; });
                return;  // replies still queued for a host that is gone are not written
            }
            const Clock::time_point now = Clock::now();
            if (!down.empty() && down.front().due <= now) {
                nxt::Telegram reply = std::move(down.front().telegram);
                down.pop_front();
                lock.unlock();
                send(reply, now);
                lock.lock();
            } else if (!up.empty() && up.front().due <= now) {
                nxt::Telegram request = std::move(up.front().telegram);
                up.pop_front();
                lock.unlock();
                std::optional<nxt::Telegram> reply = handle(request);
                lock.lock();
                if (reply) {
                    down.push_back({Clock::now() + server.options.latency_down, std::move(*reply)});
                } else {
                    server.count([](BrickServerCounters& c) { ++c.no_reply_telegrams; });
                }
            } else {
                Clock::time_point next = Clock::time_point::max();
                if (!up.empty()) {
                    next = up.front().due;
                }
                if (!down.empty()) {
                    next = std::min(next, down.front().due);
                }
                wake.wait_until(lock, next);
            }
        }
    }

    /// The handler's reply; nothing (and a log line) if it fails — a bug must not take the
    /// link down with it.
    std::optional<nxt::Telegram> handle(const nxt::Telegram& request) {
        try {
            return server.handler(request);
        } catch (const std::exception& error) {
            server.log(std::string("the firmware failed on a telegram: ") + error.what());
            return std::nullopt;
        }
    }

    void send(const nxt::Telegram& reply, Clock::time_point now) {
        if (is_frozen(now)) {
            server.count([](BrickServerCounters& c) { ++c.replies_frozen; });
            return;
        }
        if (host_gone) {
            return;
        }
        try {
            nxt::write_telegram(stream, reply);
            server.count([](BrickServerCounters& c) { ++c.replies_out; });
        } catch (const nxt::StreamClosed&) {
            host_gone = true;  // the reader finds out too and ends the session
        } catch (const std::invalid_argument& error) {
            server.log(std::string("a reply that cannot be framed: ") + error.what());
        }
    }

    State& server;
    nxt::ByteStream& stream;
    std::atomic<bool> frozen{false};  // set once, by whichever thread claims the freeze
    std::atomic<bool> host_gone{false};
    std::mutex mutex;  // guards what follows
    std::condition_variable wake;
    std::deque<InFlight> up;
    std::deque<InFlight> down;
    bool input_ended = false;
    bool abort = false;
};

BrickServer::BrickServer(Handler handler, BrickServerOptions options)
    : state_(std::make_unique<State>(std::move(handler), std::move(options))) {}

BrickServer::~BrickServer() = default;

SessionEnd BrickServer::serve(nxt::ByteStream& stream) {
    state_->count([](BrickServerCounters& c) { ++c.sessions; });
    Session session(*state_, stream);
    std::thread delay_line([&session] { session.run_delay_line(); });
    const SessionEnd end = session.read_telegrams();
    {
        const std::lock_guard lock(session.mutex);
        session.input_ended = true;
        session.abort = end == SessionEnd::Dropped || end == SessionEnd::Stopped;
    }
    session.wake.notify_one();
    delay_line.join();
    stream.close();
    state_->count([end](BrickServerCounters& c) {
        c.clients_gone += end == SessionEnd::ClientGone ? 1 : 0;
        c.framing_errors += end == SessionEnd::FramingError ? 1 : 0;
        c.injected_drops += end == SessionEnd::Dropped ? 1 : 0;
    });
    return end;
}

void BrickServer::stop() {
    state_->stopping = true;
}

BrickServerCounters BrickServer::counters() const {
    const std::lock_guard lock(state_->mutex);
    return state_->counters;
}

}  // namespace legofeup::nxtemu
