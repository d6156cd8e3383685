// The emulated Bluetooth link over a socket pair: round trips of about up + down latency,
// pipelined requests in one round trip, no-reply silence, framing errors, hosts that vanish,
// and the injected drop and freeze.

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <future>
#include <mutex>
#include <thread>
#include <vector>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/nxtemu/brick_server.hpp"
#include "support/output_states.hpp"
#include "support/scripted_hardware.hpp"

namespace legofeup {
namespace {

namespace nxt = comms::nxt;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// A firmware on scripted hardware behind a BrickServer, and a connected host stream.
class Link {
  public:
    explicit Link(nxtemu::BrickServerOptions options)
        : server_(
            [this](std::span<const std::uint8_t> request) {
                ++handled;
                const std::lock_guard lock(mutex_);
                return brick_.firmware.handle(request, seconds());
            },
            std::move(options)) {
        connect();
    }
    ~Link() {
        server_.stop();
        if (session_.valid()) {
            session_.wait();
        }
    }

    /// A fresh connection (the previous session must have ended).
    void connect() {
        int fds[2];
        EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds), 0);
        host = nxt::stream_from_fd(fds[0], "host");
        brick_end_ = nxt::stream_from_fd(fds[1], "brick");
        session_ = std::async(std::launch::async, [this] { return server_.serve(*brick_end_); });
    }

    nxt::Telegram reply(std::chrono::milliseconds timeout = 2000ms) {
        return nxt::read_telegram(*host, Clock::now() + timeout);
    }

    /// How the session ended, waiting at most `timeout`.
    std::optional<nxtemu::SessionEnd> end(std::chrono::milliseconds timeout = 3000ms) {
        if (session_.wait_for(timeout) != std::future_status::ready) {
            return std::nullopt;
        }
        return session_.get();
    }

    nxtemu::BrickServer& server() { return server_; }
    std::unique_ptr<nxt::ByteStream> host;
    std::atomic<int> handled{0};

  private:
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    std::mutex mutex_;
    testing::ScriptedBrick brick_;
    Clock::time_point start_ = Clock::now();
    nxtemu::BrickServer server_;
    std::unique_ptr<nxt::ByteStream> brick_end_;
    std::future<nxtemu::SessionEnd> session_;
};

nxtemu::BrickServerOptions latency(int up_ms, int down_ms) {
    nxtemu::BrickServerOptions options;
    options.latency_up = std::chrono::milliseconds(up_ms);
    options.latency_down = std::chrono::milliseconds(down_ms);
    return options;
}

double milliseconds_since(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

nxt::Telegram stop_motor_c() {
    return nxt::encode_set_output_state(testing::regulated_output(2, 0), false);
}

TEST(BrickServer, ARoundTripTakesTheUpAndDownLatency) {
    Link link(latency(40, 20));
    std::vector<double> round_trips;
    for (int i = 0; i < 8; ++i) {
        const auto start = Clock::now();
        nxt::write_telegram(*link.host, nxt::encode_keep_alive(true));
        EXPECT_EQ(nxt::decode_keep_alive_reply(link.reply()), 600'000U);
        round_trips.push_back(milliseconds_since(start));
    }
    std::sort(round_trips.begin(), round_trips.end());
    EXPECT_GE(round_trips.front(), 59.0);                         // never sooner than up + down
    EXPECT_LT(round_trips[round_trips.size() / 2], 60.0 + 60.0);  // loaded CI: generous
    std::printf("round trips (40 ms up, 20 ms down): min %.1f ms, median %.1f ms, max %.1f ms\n",
                round_trips.front(), round_trips[round_trips.size() / 2], round_trips.back());
}

TEST(BrickServer, PipelinedRequestsComeBackAfterOneRoundTrip) {
    Link link(latency(50, 50));
    const std::vector<nxt::Telegram> requests = {
        nxt::encode_keep_alive(true), nxt::encode_get_battery_level(),
        nxt::encode_get_output_state(2), nxt::encode_get_input_values(0)};
    const auto start = Clock::now();
    nxt::write_telegrams(*link.host, requests);  // one write
    for (const nxt::Telegram& request : requests) {
        const nxt::Telegram reply = link.reply();
        EXPECT_EQ(reply.at(1), request.at(1));  // in order
        EXPECT_EQ(reply.at(2), nxt::status::kOk);
    }
    const double elapsed = milliseconds_since(start);
    EXPECT_GE(elapsed, 99.0);
    EXPECT_LT(elapsed, 190.0);  // one round trip (100 ms), not four (400 ms)
    std::printf("4 pipelined requests (50 ms each way): %.1f ms\n", elapsed);
}

TEST(BrickServer, NoReplyTelegramsAreHandledAndAnsweredWithNothing) {
    Link link(latency(5, 5));
    nxt::write_telegram(*link.host, stop_motor_c());
    nxt::write_telegram(*link.host, nxt::encode_get_battery_level());
    EXPECT_EQ(nxt::decode_battery_level_reply(link.reply()), 7800);
    EXPECT_EQ(link.handled, 2);
    std::this_thread::sleep_for(50ms);  // the reply is counted once its write returned
    const nxtemu::BrickServerCounters counters = link.server().counters();
    EXPECT_EQ(counters.telegrams_in, 2U);
    EXPECT_EQ(counters.replies_out, 1U);
    EXPECT_EQ(counters.no_reply_telegrams, 1U);
}

TEST(BrickServer, AFramingErrorClosesTheConnection) {
    Link link(latency(5, 5));
    link.host->write_all(std::vector<std::uint8_t>{0x00, 0x00});  // length 0
    EXPECT_EQ(link.end(), nxtemu::SessionEnd::FramingError);
    EXPECT_THROW(link.reply(500ms), nxt::StreamClosed);
    EXPECT_EQ(link.server().counters().framing_errors, 1U);
}

TEST(BrickServer, TelegramsInFlightStillArriveAfterTheHostLeaves) {
    Link link(latency(60, 5));
    nxt::write_telegram(*link.host, stop_motor_c());
    link.host->close();  // at once, before the command has crossed the link
    EXPECT_EQ(link.end(), nxtemu::SessionEnd::ClientGone);
    EXPECT_EQ(link.handled, 1);
    EXPECT_EQ(link.server().counters().clients_gone, 1U);
}

TEST(BrickServer, DropAfterPullsThePlugOnceAndTheNextHostIsServed) {
    nxtemu::BrickServerOptions options = latency(5, 5);
    options.drop_after = 0.2;
    Link link(options);
    const auto start = Clock::now();
    bool closed = false;
    while (!closed && milliseconds_since(start) < 2000.0) {
        try {
            nxt::write_telegram(*link.host, nxt::encode_keep_alive(true));
            link.reply(1000ms);
            std::this_thread::sleep_for(20ms);
        } catch (const nxt::StreamClosed&) {
            closed = true;
        }
    }
    EXPECT_TRUE(closed);
    EXPECT_GE(milliseconds_since(start), 190.0);
    EXPECT_EQ(link.end(), nxtemu::SessionEnd::Dropped);
    EXPECT_EQ(link.server().counters().injected_drops, 1U);

    link.connect();
    std::this_thread::sleep_for(300ms);  // past the drop time: it happened once
    nxt::write_telegram(*link.host, nxt::encode_keep_alive(true));
    EXPECT_EQ(nxt::decode_keep_alive_reply(link.reply()), 600'000U);
}

TEST(BrickServer, FreezeAfterStopsTheRepliesButKeepsReading) {
    nxtemu::BrickServerOptions options = latency(5, 5);
    options.freeze_after = 0.1;
    std::vector<std::string> events;
    std::mutex events_mutex;
    options.log = [&](const std::string& event) {
        const std::lock_guard lock(events_mutex);
        events.push_back(event);
    };
    Link link(options);
    nxt::write_telegram(*link.host, nxt::encode_keep_alive(true));
    EXPECT_NO_THROW(link.reply());
    std::this_thread::sleep_for(150ms);
    nxt::write_telegram(*link.host, nxt::encode_keep_alive(true));
    EXPECT_THROW(link.reply(300ms), nxt::StreamTimeout);
    nxt::write_telegram(*link.host, stop_motor_c());
    std::this_thread::sleep_for(100ms);
    EXPECT_EQ(link.handled, 3);  // the commands still reach the firmware
    const nxtemu::BrickServerCounters counters = link.server().counters();
    EXPECT_EQ(counters.replies_frozen, 1U);
    EXPECT_EQ(counters.stop_commands_while_frozen, 1U);
    const std::lock_guard lock(events_mutex);
    EXPECT_TRUE(std::any_of(events.begin(), events.end(), [](const std::string& event) {
        return event.find("stop-motors") != std::string::npos;
    }));
}

TEST(BrickServer, StopEndsTheSessionPromptly) {
    Link link(latency(5, 5));
    const auto start = Clock::now();
    link.server().stop();
    EXPECT_EQ(link.end(), nxtemu::SessionEnd::Stopped);
    EXPECT_LT(milliseconds_since(start), 1000.0);
    EXPECT_THROW(link.reply(500ms), nxt::StreamClosed);
}

}  // namespace
}  // namespace legofeup
