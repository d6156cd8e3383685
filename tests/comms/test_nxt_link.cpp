// NxtLink against a scripted brick on the other end of a socket pair: what the host sends
// (setup, cycle requests, motor commands, safety stops) and how it takes the replies
// (mapping, refusals, malformed and late replies, a vanished brick, the relay program).

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <mutex>
#include <thread>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/nxt_link.hpp"
#include "legofeup/comms/nxt/relay_message.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace std::chrono_literals;

/// A brick whose answers the test writes: `respond` gets every decoded request and returns
/// the reply to send (or nothing). Every request is logged.
class ScriptedBrick {
  public:
    using Respond = std::function<std::optional<Telegram>(const DecodedRequest&)>;

    /// `last_of_a_request` tells which requests end one of the host's requests (a direct
    /// cycle's batch is several telegrams), for replies_with_a_request_waiting().
    explicit ScriptedBrick(Respond respond,
                           std::function<bool(const DecodedRequest&)> last_of_a_request = {})
        : respond_(std::move(respond)), last_of_a_request_(std::move(last_of_a_request)) {
        int fds[2];
        if (::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) {
            throw std::runtime_error("socketpair");
        }
        host_ = stream_from_fd(fds[0], "test:host");
        brick_ = stream_from_fd(fds[1], "test:brick");
        thread_ = std::jthread([this](const std::stop_token& stop) { serve(stop); });
    }
    ~ScriptedBrick() {
        thread_.request_stop();
        thread_.join();
    }

    std::unique_ptr<ByteStream> take_host_end() { return std::move(host_); }
    /// Closes the brick's end: the host sees the link go away.
    void pull_the_plug() { unplugged_ = true; }
    /// Replies ending a request, sent while the host's next request was already waiting:
    /// how often the host had more than one request in flight.
    int replies_with_a_request_waiting() const { return pipelined_; }

    std::vector<DecodedRequest> log() const {
        const std::lock_guard lock(mutex_);
        return log_;
    }
    /// The SETOUTPUTSTATEs received since index `from` of the log.
    std::vector<OutputState> outputs_set(std::size_t from = 0) const {
        std::vector<OutputState> outputs;
        const auto requests = log();
        for (std::size_t i = from; i < requests.size(); ++i) {
            if (const auto* set = std::get_if<SetOutputState>(&*requests[i].body)) {
                outputs.push_back(set->state);
            }
        }
        return outputs;
    }

  private:
    void serve(const std::stop_token& stop) {
        while (!stop.stop_requested()) {
            if (unplugged_) {
                brick_->close();
                return;
            }
            Telegram request;
            try {
                request = read_telegram(*brick_, ByteStream::Clock::now() + 20ms);
            } catch (const StreamTimeout&) {
                continue;
            } catch (const LinkError&) {
                return;
            }
            const DecodedRequest decoded = decode_request(request);
            {
                const std::lock_guard lock(mutex_);
                log_.push_back(decoded);
            }
            std::optional<Telegram> reply = respond_(decoded);
            if (reply && last_of_a_request_ && last_of_a_request_(decoded)
                && brick_->wait_readable(ByteStream::Clock::now())) {
                ++pipelined_;
            }
            if (reply && decoded.wants_reply()) {
                try {
                    write_telegram(*brick_, *reply);
                } catch (const LinkError&) {
                    return;
                }
            }
        }
    }

    Respond respond_;
    std::function<bool(const DecodedRequest&)> last_of_a_request_;
    std::unique_ptr<ByteStream> host_;
    std::unique_ptr<ByteStream> brick_;
    std::atomic<bool> unplugged_{false};
    std::atomic<int> pipelined_{0};
    mutable std::mutex mutex_;
    std::vector<DecodedRequest> log_;
    std::jthread thread_;
};

/// Default firmware-like answers: motor p's RotationCount = 100·(p+1) + `count_offset`,
/// input p's raw = 300 + p, battery 7654 mV.
struct Firmware {
    std::atomic<int> count_offset{0};
    std::atomic<bool> silent{false};

    // Every request without its own answer below gets a plain "ok" status reply. (Declared
    // before its use: clang reports a member template of a class in an anonymous namespace
    // used above its definition as undefined.)
    template <typename Other>
    std::optional<Telegram> answer(const DecodedRequest& request, const Other&) {
        return encode_status_reply(request.opcode, status::kOk);
    }
    std::optional<Telegram> operator()(const DecodedRequest& request) {
        if (silent || !request.body) {
            return std::nullopt;
        }
        return std::visit(
            [&](const auto& body) -> std::optional<Telegram> { return answer(request, body); },
            *request.body);
    }
    std::optional<Telegram> answer(const DecodedRequest&, const GetOutputState& get) {
        OutputStateReply reply;
        reply.state.port = get.port;
        reply.rotation_count = 100 * (get.port + 1) + count_offset;
        return encode_output_state_reply(status::kOk, reply);
    }
    std::optional<Telegram> answer(const DecodedRequest&, const GetInputValues& get) {
        InputValues values;
        values.port = get.port;
        values.valid = true;
        values.raw = static_cast<std::uint16_t>(300 + get.port);
        return encode_input_values_reply(status::kOk, values);
    }
    std::optional<Telegram> answer(const DecodedRequest&, const GetBatteryLevel&) {
        return encode_battery_level_reply(status::kOk, 7654);
    }
    std::optional<Telegram> answer(const DecodedRequest&, const KeepAlive&) {
        return encode_keep_alive_reply(status::kOk, 600000);
    }
};

NxtLinkOptions test_options() {
    NxtLinkOptions options;
    options.address = parse_transport_address("tcp:127.0.0.1:1");
    options.reply_timeout = 150ms;
    options.min_period = 20ms;
    return options;
}

TEST(NxtLink, ConnectSetsUpTheBrickInOrder) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    ASSERT_TRUE(link.connected());
    EXPECT_EQ(link.quality().state, LinkState::Connected);
    EXPECT_EQ(link.quality().battery_millivolts, 7654);

    const auto log = brick.log();
    std::vector<std::uint8_t> opcodes;
    for (const auto& request : log) {
        opcodes.push_back(request.opcode);
    }
    // KEEPALIVE, GETBATTERYLEVEL, two stops, two SETINPUTMODEs, two RESETMOTORPOSITIONs.
    EXPECT_EQ(opcodes, (std::vector<std::uint8_t>{0x0D, 0x0B, 0x04, 0x04, 0x05, 0x05, 0x0A, 0x0A}));
    const auto& front = std::get<SetInputMode>(*log[4].body);
    const auto& rear = std::get<SetInputMode>(*log[5].body);
    EXPECT_EQ(front.port, 0);
    EXPECT_EQ(rear.port, 1);
    EXPECT_EQ(front.sensor_type, kSensorLightInactive);  // raw A/D, 9 V pin off
    EXPECT_EQ(front.sensor_mode, kSensorModeRaw);
    EXPECT_EQ(std::get<ResetMotorPosition>(*log[6].body).port, 2);
    EXPECT_FALSE(std::get<ResetMotorPosition>(*log[6].body).relative);  // RotationCount
    EXPECT_EQ(std::get<ResetMotorPosition>(*log[7].body).port, 1);
    for (const OutputState& stop : brick.outputs_set()) {
        EXPECT_EQ(stop.power, 0);
        EXPECT_EQ(stop.mode & kModeBrake, kModeBrake);
    }
    EXPECT_EQ(log[2].type, TelegramType::DirectNoReply);
}

TEST(NxtLink, FramesMapTheWiringAndTimeAdvances) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    double first_time = 0.0;
    double last_time = 0.0;
    for (int i = 0; i < 5; ++i) {
        firmware.count_offset = 10 * i;
        const std::optional<SensorFrame> frame = link.next_frame();
        ASSERT_TRUE(frame);
        EXPECT_EQ(frame->encoder_counts[0], 300 + 10 * i);  // right wheel on port C (2)
        EXPECT_EQ(frame->encoder_counts[1], 200 + 10 * i);  // left wheel on port B (1)
        EXPECT_EQ(frame->ir_adc[0], 300);                   // front IR on port 1 (0)
        EXPECT_EQ(frame->ir_adc[1], 301);
        EXPECT_TRUE(frame->ir_valid[0] && frame->ir_valid[1]);
        EXPECT_EQ(frame->sequence, static_cast<std::uint32_t>(i + 1));
        // Never faster than min_period: read requests go out at least min_period apart and
        // frame i's reply follows request i, so frame i is at least i periods after connect.
        // (Two consecutive replies may be closer: a late reply can be followed by a prompt one.)
        EXPECT_GE(frame->time, 0.020 * i - 1e-3);
        EXPECT_GE(frame->time, last_time);
        first_time = i == 0 ? frame->time : first_time;
        last_time = frame->time;
    }
    const LinkQuality quality = link.quality();
    EXPECT_EQ(quality.cycles, 5u);
    EXPECT_EQ(quality.timeouts, 0u);
    // The rate is that of the frames' own times: 4 cycles from the first frame to the last.
    // (Not bounded by 1/min_period: when the first reply is late, the next four requests,
    // spaced from the requests, not the replies, span a little less than 4 periods.)
    ASSERT_GT(last_time, first_time);
    EXPECT_NEAR(quality.rate_hz(), 4.0 / (last_time - first_time), 1e-6 * quality.rate_hz());
    EXPECT_LE(quality.rate_hz(), 4.0 / (0.080 - 1e-3 - first_time));
}

TEST(NxtLink, CommandsBecomeRegulatedPowerWithoutReply) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLinkOptions options = test_options();
    options.wiring.power_per_meter_per_second = 265.3;
    NxtLink link(options);
    link.connect(brick.take_host_end());
    const std::size_t before = brick.log().size();
    link.send_command({0.1, -0.05});
    link.send_command({1.0, -1.0});  // beyond full power: limited to ±100
    ASSERT_TRUE(link.next_frame());  // the brick has read the commands by now
    const std::vector<OutputState> sets = brick.outputs_set(before);
    ASSERT_EQ(sets.size(), 4u);
    EXPECT_EQ(sets[0].port, 2);
    EXPECT_EQ(sets[0].power, 27);  // round(0.1 · 265.3) = 27
    EXPECT_EQ(sets[1].port, 1);
    EXPECT_EQ(sets[1].power, -13);  // round(−0.05 · 265.3) = −13
    EXPECT_EQ(sets[2].power, 100);
    EXPECT_EQ(sets[3].power, -100);
    EXPECT_EQ(sets[0].mode, kModeMotorOn | kModeBrake | kModeRegulated);
    EXPECT_EQ(sets[0].regulation, kRegulationMotorSpeed);
    EXPECT_EQ(sets[0].run_state, kRunStateRunning);
    EXPECT_EQ(sets[0].tacho_limit, 0u);
    for (const auto& request : brick.log()) {
        if (request.opcode == 0x04) {
            EXPECT_EQ(request.type, TelegramType::DirectNoReply);
        }
    }
}

TEST(NxtLink, ReversedMotorsFlipCountsAndPower) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLinkOptions options = test_options();
    options.wiring.reversed_motors = true;
    NxtLink link(options);
    link.connect(brick.take_host_end());
    const std::size_t before = brick.log().size();
    link.send_command({0.1, 0.1});
    const auto frame = link.next_frame();
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->encoder_counts[0], -300);
    EXPECT_EQ(frame->encoder_counts[1], -200);
    const auto sets = brick.outputs_set(before);
    ASSERT_EQ(sets.size(), 2u);
    EXPECT_EQ(sets[0].power, -27);
}

TEST(NxtLink, PausedLinkStopsTheMotorsAndIgnoresCommands) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    const std::size_t before = brick.log().size();
    link.set_paused(true);
    link.send_command({0.2, 0.2});
    ASSERT_TRUE(link.next_frame());  // frames keep coming while paused
    auto sets = brick.outputs_set(before);
    ASSERT_EQ(sets.size(), 2u);  // the two stops, not the command
    EXPECT_EQ(sets[0].power, 0);
    link.set_paused(false);
    link.send_command({0.2, 0.2});
    ASSERT_TRUE(link.next_frame());
    sets = brick.outputs_set(before);
    ASSERT_EQ(sets.size(), 4u);
    EXPECT_EQ(sets[3].power, 53);
}

TEST(NxtLink, AMalformedReplyCostsOneFrameOnly) {
    Firmware firmware;
    std::atomic<int> cut{0};
    ScriptedBrick brick([&](const DecodedRequest& request) -> std::optional<Telegram> {
        std::optional<Telegram> reply = firmware(request);
        if (reply && request.opcode == 0x07 && cut.exchange(0) == 1) {
            reply->pop_back();  // one byte short
        }
        return reply;
    });
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    ASSERT_TRUE(link.next_frame());
    cut = 1;
    EXPECT_FALSE(link.next_frame());
    EXPECT_EQ(link.quality().rejected_replies, 1u);
    EXPECT_NE(link.quality().last_error.find("GETINPUTVALUES"), std::string::npos)
        << link.quality().last_error;
    const auto frame = link.next_frame();
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->ir_adc[1], 301);
    EXPECT_TRUE(link.connected());
}

TEST(NxtLink, ABadPortFailsTheLinkAndStopsTheMotors) {
    Firmware firmware;
    ScriptedBrick brick([&](const DecodedRequest& request) -> std::optional<Telegram> {
        if (request.opcode == 0x06 && std::get<GetOutputState>(*request.body).port == 2) {
            return encode_output_state_reply(status::kOutOfRange, {});
        }
        return firmware(request);
    });
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    const std::size_t before = brick.log().size();
    try {
        link.next_frame();
        FAIL() << "expected LinkError";
    } catch (const LinkError& error) {
        EXPECT_NE(std::string(error.what()).find("0xC0"), std::string::npos) << error.what();
    }
    EXPECT_FALSE(link.connected());
    EXPECT_EQ(link.quality().state, LinkState::Failed);
    std::this_thread::sleep_for(50ms);
    const auto sets = brick.outputs_set(before);
    ASSERT_GE(sets.size(), 2u);
    EXPECT_EQ(sets.back().power, 0);
    EXPECT_THROW(link.next_frame(), LinkError);  // not connected: says so, does not hang
}

TEST(NxtLink, ASilentBrickTimesOutThenFailsAfterTheLimit) {
    Firmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLinkOptions options = test_options();
    options.max_consecutive_timeouts = 3;
    NxtLink link(options);
    link.connect(brick.take_host_end());
    const std::size_t before = brick.log().size();
    firmware.silent = true;
    EXPECT_FALSE(link.next_frame());
    EXPECT_FALSE(link.next_frame());
    try {
        link.next_frame();
        FAIL() << "expected LinkError";
    } catch (const LinkError& error) {
        EXPECT_NE(std::string(error.what()).find("3 cycles"), std::string::npos) << error.what();
    }
    EXPECT_EQ(link.quality().timeouts, 3u);
    std::this_thread::sleep_for(50ms);
    const auto sets = brick.outputs_set(before);
    ASSERT_GE(sets.size(), 2u);
    EXPECT_EQ(sets.back().power, 0);  // the stop went out although nobody answered
}

TEST(NxtLink, LateRepliesAreNotTakenForTheNextCycle) {
    Firmware firmware;
    std::atomic<bool> slow{false};
    ScriptedBrick brick([&](const DecodedRequest& request) -> std::optional<Telegram> {
        if (slow && request.opcode == 0x06) {
            std::this_thread::sleep_for(200ms);  // past the 150 ms reply timeout
            slow = false;
        }
        return firmware(request);
    });
    NxtLink link(test_options());
    link.connect(brick.take_host_end());
    ASSERT_TRUE(link.next_frame());
    slow = true;
    EXPECT_FALSE(link.next_frame());
    std::this_thread::sleep_for(100ms);  // the stale replies are made (offset 0) and sent
    firmware.count_offset = 5000;
    const auto frame = link.next_frame();
    ASSERT_TRUE(frame);
    // The stale replies (offset 0) were drained; the frame holds the fresh counts.
    EXPECT_EQ(frame->encoder_counts[0], 5300);
    EXPECT_EQ(frame->encoder_counts[1], 5200);
}

TEST(NxtLink, APulledPlugFailsWithTheReasonAndReconnectWorks) {
    Firmware firmware;
    auto brick = std::make_unique<ScriptedBrick>(std::ref(firmware));
    NxtLink link(test_options());
    link.connect(brick->take_host_end());
    ASSERT_TRUE(link.next_frame());
    brick->pull_the_plug();
    std::this_thread::sleep_for(60ms);
    try {
        for (int i = 0; i < 10; ++i) {
            link.next_frame();
        }
        FAIL() << "expected LinkError";
    } catch (const LinkError& error) {
        EXPECT_NE(std::string(error.what()).find("closed the link"), std::string::npos)
            << error.what();
    }
    EXPECT_EQ(link.quality().state, LinkState::Failed);
    EXPECT_NE(link.quality().last_error.find("closed"), std::string::npos);

    ScriptedBrick second(std::ref(firmware));
    link.connect(second.take_host_end());
    EXPECT_EQ(link.quality().state, LinkState::Connected);
    EXPECT_TRUE(link.next_frame());
}

/// A relay program that leaves one message per read, or none while `empty`.
struct RelayFirmware : Firmware {
    std::atomic<bool> installed{true};
    std::atomic<bool> running{false};
    std::atomic<bool> empty{false};
    std::atomic<std::uint32_t> sequence{0};

    std::optional<Telegram> operator()(const DecodedRequest& request) {
        if (request.body && std::holds_alternative<StartProgram>(*request.body)) {
            running = installed.load();
            return encode_status_reply(request.opcode,
                                       installed ? status::kOk : status::kOutOfRange);
        }
        if (request.body && std::holds_alternative<StopProgram>(*request.body)) {
            const bool was = running.exchange(false);
            return encode_status_reply(request.opcode,
                                       was ? status::kOk : status::kNoActiveProgram);
        }
        if (request.body && std::holds_alternative<MessageRead>(*request.body)) {
            if (!running || empty) {
                return encode_message_read_reply(status::kMailboxEmpty, {});
            }
            RelayReading reading;
            reading.sequence = ++sequence;
            reading.right_count = 1000 + count_offset;
            reading.left_count = -20;
            reading.front_raw = 512;
            reading.rear_raw = 1023;
            reading.front_valid = true;
            reading.battery_millivolts = 7100;
            const std::string text = format_relay_message(reading);
            MailboxMessage message;
            message.local_inbox = 0;
            message.data.assign(text.begin(), text.end());
            message.data.push_back(0);
            return encode_message_read_reply(status::kOk, message);
        }
        return Firmware::operator()(request);
    }
};

TEST(NxtLink, RelayModeStartsTheProgramAndReadsItsMessages) {
    RelayFirmware firmware;
    ScriptedBrick brick(std::ref(firmware));
    NxtLinkOptions options = test_options();
    options.mode = CycleMode::Relay;
    NxtLink link(options);
    link.connect(brick.take_host_end());
    const auto log = brick.log();
    bool started = false;
    for (const auto& request : log) {
        if (const auto* start = std::get_if<StartProgram>(&*request.body)) {
            EXPECT_EQ(start->file_name, "legofeup.rxe");
            started = true;
        }
        EXPECT_NE(request.opcode, 0x05);  // the program sets its own input modes
    }
    EXPECT_TRUE(started);
    firmware.count_offset = 7;
    const auto frame = link.next_frame();
    ASSERT_TRUE(frame);
    EXPECT_EQ(frame->encoder_counts[0], 1007);
    EXPECT_EQ(frame->encoder_counts[1], -20);
    EXPECT_EQ(frame->ir_adc[0], 512);
    EXPECT_TRUE(frame->ir_valid[0]);
    EXPECT_FALSE(frame->ir_valid[1]);
    EXPECT_EQ(link.quality().battery_millivolts, 7100);
    firmware.empty = true;
    // An empty mailbox (no new reading) gives no frame, and no error.
    EXPECT_FALSE(link.next_frame());
    EXPECT_TRUE(link.connected());
    firmware.empty = false;
    for (int i = 0; i < 3; ++i) {
        link.next_frame();
    }
    EXPECT_TRUE(link.next_frame());
    link.disconnect();
    std::this_thread::sleep_for(50ms);
    EXPECT_FALSE(firmware.running);  // STOPPROGRAM on the way out
}

TEST(NxtLink, RelayModeKeepsTheNextReadInFlightDirectCommandsDoNot) {
    // A brick that takes 100 ms per reply: with two reads in flight the next request is
    // already waiting when a reply goes out (the host sent it one 40 ms period after the
    // previous one); with one batch in flight it never is.
    const auto replies_with_a_request_waiting = [](CycleMode mode) {
        RelayFirmware firmware;
        std::atomic<bool> slow{false};
        ScriptedBrick brick(
            [&](const DecodedRequest& request) -> std::optional<Telegram> {
                if (slow && request.opcode != 0x04) {
                    std::this_thread::sleep_for(100ms);
                }
                return firmware(request);
            },
            [](const DecodedRequest& request) {
                // A relay cycle is one MESSAGEREAD; a direct one ends with the rear sensor.
                const auto* input =
                    request.body ? std::get_if<GetInputValues>(&*request.body) : nullptr;
                return request.opcode == 0x13 || (input != nullptr && input->port == 1);
            });
        NxtLinkOptions options = test_options();
        options.mode = mode;
        options.min_period = 40ms;
        options.reply_timeout = 1000ms;
        NxtLink link(options);
        link.connect(brick.take_host_end());
        EXPECT_TRUE(link.next_frame());  // the first cycle also asks for the battery
        const int before = brick.replies_with_a_request_waiting();
        slow = true;
        for (int i = 0; i < 4; ++i) {
            EXPECT_TRUE(link.next_frame());
        }
        return brick.replies_with_a_request_waiting() - before;
    };
    EXPECT_GE(replies_with_a_request_waiting(CycleMode::Relay), 2);
    EXPECT_EQ(replies_with_a_request_waiting(CycleMode::DirectCommands), 0);
}

TEST(NxtLink, RelayModeWithoutTheProgramSaysWhatToDo) {
    RelayFirmware firmware;
    firmware.installed = false;
    ScriptedBrick brick(std::ref(firmware));
    NxtLinkOptions options = test_options();
    options.mode = CycleMode::Relay;
    NxtLink link(options);
    try {
        link.connect(brick.take_host_end());
        FAIL() << "expected LinkError";
    } catch (const LinkError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("legofeup.rxe"), std::string::npos) << message;
        EXPECT_NE(message.find("legofeup_relay.nxc"), std::string::npos) << message;
    }
    EXPECT_EQ(link.quality().state, LinkState::Failed);
    EXPECT_FALSE(link.connected());
}

TEST(NxtLink, ANonBrickAtTheOtherEndIsRefusedAtConnect) {
    ScriptedBrick brick([](const DecodedRequest&) -> std::optional<Telegram> {
        return Telegram{0x02, 0x0B, 0x00, 0x01, 0x02};  // a battery reply to a KEEPALIVE
    });
    NxtLink link(test_options());
    EXPECT_THROW(link.connect(brick.take_host_end()), LinkError);
    EXPECT_EQ(link.quality().state, LinkState::Failed);
    EXPECT_NE(link.quality().last_error.find("KEEPALIVE"), std::string::npos)
        << link.quality().last_error;
}

TEST(NxtLink, WiringIsCheckedUpFront) {
    NxtLinkOptions options = test_options();
    options.wiring.left_motor = options.wiring.right_motor;
    EXPECT_THROW(NxtLink{options}, std::invalid_argument);
    options = test_options();
    options.wiring.front_ir = 4;
    EXPECT_THROW(NxtLink{options}, std::invalid_argument);
    options = test_options();
    options.wiring.power_per_meter_per_second = 0.0;
    EXPECT_THROW(NxtLink{options}, std::invalid_argument);
}

TEST(RelayMessage, FormatsAndParsesTheDocumentedLayout) {
    RelayReading reading;
    reading.sequence = 999999;
    reading.right_count = -2147483647 - 1;
    reading.left_count = 2147483647;
    reading.front_raw = 1023;
    reading.rear_raw = 0;
    reading.front_valid = false;
    reading.rear_valid = true;
    reading.battery_millivolts = 65535;
    const std::string text = format_relay_message(reading);
    EXPECT_EQ(text, "L1 999999 -2147483648 2147483647 1023 0 2 65535");
    EXPECT_LE(text.size(), 58u);  // the longest message still fits a mailbox
    const std::vector<std::uint8_t> bytes(text.begin(), text.end());
    EXPECT_EQ(parse_relay_message(bytes), reading);
}

TEST(RelayMessage, RefusesEverythingElseWithTheField) {
    const auto refusal = [](const std::string& text) {
        const std::vector<std::uint8_t> bytes(text.begin(), text.end());
        try {
            parse_relay_message(bytes);
        } catch (const ReplyError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(refusal("L2 1 2 3 4 5 3 7000").find("does not start"), std::string::npos);
    EXPECT_NE(refusal("L1 1 2 3 4 5 3").find("expected 7 fields"), std::string::npos);
    EXPECT_NE(refusal("L1 1 2 3 4 5 3 7000 9").find("expected 7 fields"), std::string::npos);
    EXPECT_NE(refusal("L1 1 x 3 4 5 3 7000").find("field 3 (right_count)"), std::string::npos);
    EXPECT_NE(refusal("L1 1 2 3 1024 5 3 7000").find("front_raw"), std::string::npos);
    EXPECT_NE(refusal("L1 1 2 3 4 5 4 7000").find("valid_mask"), std::string::npos);
    EXPECT_NE(refusal("L1 1000000 2 3 4 5 3 7000").find("seq"), std::string::npos);
    EXPECT_NE(refusal("L1 1 +2 3 4 5 3 7000").find("right_count"), std::string::npos);
    EXPECT_NE(refusal("L1 1 2  3 4 5 3 7000"), "accepted");
    EXPECT_NE(refusal("L1 1 2 3 4 5 3 7000 "), "accepted");
    EXPECT_EQ(refusal(std::string("L1 1 2 3 4 5 3 7000") + '\0'), "accepted");
}

}  // namespace
}  // namespace legofeup::comms::nxt
