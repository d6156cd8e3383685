#include "legofeup/comms/nxt/nxt_link.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/relay_message.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

/// Replies while connecting: Bluetooth round trips take 30–150 ms, a dozing brick longer.
constexpr auto kSetupTimeout = 2000ms;
/// After SETINPUTMODE the firmware flags readings invalid for ≈20 ms.
constexpr auto kInvalidWindow = 30ms;
/// The relay program needs a moment to start and write its first message.
constexpr auto kRelayStartTimeout = 3000ms;
constexpr auto kRelayPoll = 20ms;

/// Requests in flight at once: direct commands keep one batch in flight (the safe choice
/// for the brick's small receive buffer); the relay's one-telegram requests are pipelined
/// two deep so a cycle costs a period, not a round trip.
std::size_t pipeline_depth(CycleMode mode) {
    return mode == CycleMode::Relay ? 2 : 1;
}

double seconds_between(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

/// Speed-regulated power for a wheel speed: power = round(k · v), limited to ±100.
std::int8_t power_for(double speed, double power_per_meter_per_second, bool reversed) {
    const double power = std::clamp(std::round(speed * power_per_meter_per_second), -100.0, 100.0);
    return static_cast<std::int8_t>(reversed ? -power : power);
}

OutputState regulated_output(std::uint8_t port, std::int8_t power) {
    OutputState state;
    state.port = port;
    state.power = power;
    state.mode = kModeMotorOn | kModeBrake | kModeRegulated;
    state.regulation = kRegulationMotorSpeed;
    state.run_state = kRunStateRunning;
    return state;
}

/// Power 0 with the brake on: the motor holds still (coasting would let the robot roll).
OutputState braked_output(std::uint8_t port) {
    OutputState state;
    state.port = port;
    state.mode = kModeMotorOn | kModeBrake;
    state.run_state = kRunStateRunning;
    return state;
}

void check_wiring(const NxtWiring& wiring) {
    if (wiring.right_motor >= kOutputPorts || wiring.left_motor >= kOutputPorts
        || wiring.right_motor == wiring.left_motor) {
        throw std::invalid_argument(
            "NXT wiring: the wheel motors must be two different output ports 0–2 (A–C)");
    }
    if (wiring.front_ir >= kInputPorts || wiring.rear_ir >= kInputPorts
        || wiring.front_ir == wiring.rear_ir) {
        throw std::invalid_argument(
            "NXT wiring: the IR sensors must be two different input ports 0–3 (1–4)");
    }
    if (!std::isfinite(wiring.power_per_meter_per_second)
        || wiring.power_per_meter_per_second <= 0.0) {
        throw std::invalid_argument("NXT wiring: power_per_meter_per_second must be positive");
    }
}

}  // namespace

const char* to_string(LinkState state) {
    switch (state) {
        case LinkState::Disconnected:
            return "disconnected";
        case LinkState::Connecting:
            return "connecting";
        case LinkState::Connected:
            return "connected";
        case LinkState::Failed:
            return "failed";
    }
    return "unknown";
}

NxtLink::NxtLink(NxtLinkOptions options) : options_(std::move(options)) {
    check_wiring(options_.wiring);
}

NxtLink::~NxtLink() {
    disconnect();
}

bool NxtLink::connected() const {
    return stream_ != nullptr;
}

LinkQuality NxtLink::quality() const {
    const std::lock_guard lock(quality_mutex_);
    return quality_;
}

void NxtLink::set_state(LinkState state, const std::string& error) {
    const std::lock_guard lock(quality_mutex_);
    quality_.state = state;
    if (!error.empty()) {
        quality_.last_error = error;
    }
}

void NxtLink::connect() {
    disconnect();
    set_state(LinkState::Connecting);
    std::unique_ptr<ByteStream> stream;
    try {
        stream = open_transport(options_.address, options_.connect_timeout);
    } catch (const LinkError& error) {
        set_state(LinkState::Failed, error.what());
        throw;
    }
    connect(std::move(stream));
}

void NxtLink::connect(std::unique_ptr<ByteStream> stream) {
    disconnect();
    stream_ = std::move(stream);
    in_flight_.clear();
    owed_replies_ = 0;
    paused_ = false;
    consecutive_timeouts_ = 0;
    next_sequence_ = 0;
    {
        const std::lock_guard lock(quality_mutex_);
        quality_ = LinkQuality{};
        quality_.state = LinkState::Connecting;
    }
    try {
        open_session();
    } catch (const std::exception& error) {
        const std::string why =
            "NXT at " + options_.address.to_string() + ": " + std::string(error.what());
        send_stop_best_effort();
        stream_->close();
        stream_.reset();
        set_state(LinkState::Failed, why);
        throw LinkError(why);
    }
    set_state(LinkState::Connected);
}

Telegram NxtLink::exchange(const Telegram& request, std::chrono::milliseconds timeout) {
    write_telegram(*stream_, request);
    try {
        return read_telegram(*stream_, Clock::now() + timeout);
    } catch (const StreamTimeout&) {
        throw LinkError("no reply to " + opcode_name(static_cast<Opcode>(request.at(1)))
                        + " within " + std::to_string(timeout.count())
                        + " ms (is it an NXT, switched on, with the standard firmware?)");
    }
}

// Checks the brick answers, puts both motors at rest, then either sets the IR ports to raw
// A/D and zeroes the wheel counters (direct commands) or restarts the relay program and
// waits for its first message.
void NxtLink::open_session() {
    decode_keep_alive_reply(exchange(encode_keep_alive(true), kSetupTimeout));
    const std::uint16_t battery =
        decode_battery_level_reply(exchange(encode_get_battery_level(), kSetupTimeout));
    {
        const std::lock_guard lock(quality_mutex_);
        quality_.battery_millivolts = battery;
    }
    send_stop_best_effort();
    const NxtWiring& wiring = options_.wiring;
    if (options_.mode == CycleMode::Relay) {
        try {
            decode_status_reply(exchange(encode_stop_program(true), kSetupTimeout),
                                Opcode::StopProgram);
        } catch (const ReplyError& error) {
            if (error.status() != status::kNoActiveProgram) {
                throw;
            }
        }
    } else {
        for (const std::uint8_t port : {wiring.front_ir, wiring.rear_ir}) {
            decode_status_reply(
                exchange(encode_set_input_mode(port, kSensorLightInactive, kSensorModeRaw, true),
                         kSetupTimeout),
                Opcode::SetInputMode);
        }
    }
    for (const std::uint8_t port : {wiring.right_motor, wiring.left_motor}) {
        decode_status_reply(exchange(encode_reset_motor_position(port, false, true), kSetupTimeout),
                            Opcode::ResetMotorPosition);
    }
    if (options_.mode == CycleMode::Relay) {
        try {
            decode_status_reply(
                exchange(encode_start_program(options_.relay_program, true), kSetupTimeout),
                Opcode::StartProgram);
        } catch (const ReplyError& error) {
            throw LinkError("the brick could not start " + options_.relay_program + " ("
                            + error.what()
                            + "): compile resources/nxt/legofeup_relay.nxc and download it "
                              "to the brick, or connect without the relay (direct commands)");
        }
        const auto give_up = Clock::now() + kRelayStartTimeout;
        for (;;) {
            const auto message = decode_message_read_reply(
                exchange(encode_message_read(options_.relay_mailbox, 0, true), kSetupTimeout));
            if (message) {
                parse_relay_message(message->data);
                break;
            }
            if (Clock::now() > give_up) {
                throw LinkError(options_.relay_program + " started but left no message in "
                                "mailbox " + std::to_string(options_.relay_mailbox)
                                + " within 3 s");
            }
            std::this_thread::sleep_for(kRelayPoll);
        }
    } else {
        std::this_thread::sleep_for(kInvalidWindow);
    }
    const auto now = Clock::now();
    connected_at_ = now;
    last_frame_at_ = now;
    next_read_at_ = now;
    next_keep_alive_ = now + options_.keep_alive_interval;
    next_battery_ = now;
}

std::vector<Telegram> NxtLink::motor_commands(const WheelSpeeds& speeds) const {
    const NxtWiring& w = options_.wiring;
    const double k = w.power_per_meter_per_second;
    return {
        encode_set_output_state(
            regulated_output(w.right_motor, power_for(speeds.right, k, w.reversed_motors)), false),
        encode_set_output_state(
            regulated_output(w.left_motor, power_for(speeds.left, k, w.reversed_motors)), false)};
}

void NxtLink::send_stop_best_effort() noexcept {
    if (!stream_) {
        return;
    }
    try {
        const NxtWiring& w = options_.wiring;
        const std::vector<Telegram> stop = {
            encode_set_output_state(braked_output(w.right_motor), false),
            encode_set_output_state(braked_output(w.left_motor), false)};
        write_telegrams(*stream_, stop);
    } catch (...) {  // NOLINT(bugprone-empty-catch): best effort, the link may be gone
    }
}

void NxtLink::stop_motors() {
    send_stop_best_effort();
}

void NxtLink::set_paused(bool paused) {
    paused_ = paused;
    if (paused) {
        stop_motors();
    }
}

void NxtLink::send_command(const WheelSpeeds& command) {
    if (!stream_ || paused_) {
        return;
    }
    // Sent at once, no reply: a motor command never waits for a read.
    try {
        write_telegrams(*stream_, motor_commands(command));
    } catch (const StreamClosed& error) {
        fail("the link closed while sending a motor command: " + std::string(error.what()));
    }
}

// One read request: the wheel counters and IR readings (direct: four requests in one
// write; relay: one MESSAGEREAD), plus the battery now and then and a keep-alive.
void NxtLink::send_read_request() {
    const NxtWiring& w = options_.wiring;
    const auto now = Clock::now();
    std::vector<Telegram> batch;
    InFlight request{now, {}};
    if (now >= next_keep_alive_) {
        batch.push_back(encode_keep_alive(false));
        next_keep_alive_ = now + options_.keep_alive_interval;
    }
    if (options_.mode == CycleMode::Relay) {
        batch.push_back(encode_message_read(options_.relay_mailbox, 0, true));
        request.replies = {Opcode::MessageRead};
    } else {
        batch.push_back(encode_get_output_state(w.right_motor));
        batch.push_back(encode_get_output_state(w.left_motor));
        batch.push_back(encode_get_input_values(w.front_ir));
        batch.push_back(encode_get_input_values(w.rear_ir));
        request.replies = {Opcode::GetOutputState, Opcode::GetOutputState, Opcode::GetInputValues,
                           Opcode::GetInputValues};
        if (now >= next_battery_) {
            batch.push_back(encode_get_battery_level());
            request.replies.push_back(Opcode::GetBatteryLevel);
            next_battery_ = now + options_.battery_interval;
        }
    }
    write_telegrams(*stream_, batch);
    in_flight_.push_back(std::move(request));
    next_read_at_ = std::max(next_read_at_, now) + options_.min_period;
}

// Replies owed by requests that timed out: read and dropped, so the next cycle's replies are
// not taken for them. If they never come the stream is resynchronised by discarding.
void NxtLink::drain_owed_replies() {
    const auto give_up = Clock::now() + options_.reply_timeout;
    while (owed_replies_ > 0) {
        try {
            read_telegram(*stream_, give_up);
            --owed_replies_;
        } catch (const StreamTimeout&) {
            stream_->discard_pending();
            owed_replies_ = 0;
        } catch (const FramingError&) {
            stream_->discard_pending();
            owed_replies_ = 0;
        }
    }
}

void NxtLink::on_timeout(const std::string& what) {
    for (const InFlight& request : in_flight_) {
        owed_replies_ += request.replies.size();
    }
    in_flight_.clear();
    {
        const std::lock_guard lock(quality_mutex_);
        ++quality_.timeouts;
    }
    if (++consecutive_timeouts_ >= options_.max_consecutive_timeouts) {
        fail("no reply from the NXT at " + options_.address.to_string() + " for "
             + std::to_string(consecutive_timeouts_) + " cycles in a row (" + what + ")");
    }
}

void NxtLink::fail(const std::string& why) {
    send_stop_best_effort();
    if (stream_) {
        stream_->close();
        stream_.reset();
    }
    in_flight_.clear();
    set_state(LinkState::Failed, why);
    throw LinkError(why);
}

void NxtLink::disconnect() {
    if (!stream_) {
        return;
    }
    send_stop_best_effort();
    if (options_.mode == CycleMode::Relay) {
        try {
            write_telegram(*stream_, encode_stop_program(false));
        } catch (...) {  // NOLINT(bugprone-empty-catch): best effort on the way out
        }
    }
    stream_->close();
    stream_.reset();
    in_flight_.clear();
    set_state(LinkState::Disconnected);
}

std::optional<SensorFrame> NxtLink::next_frame() {
    if (!stream_) {
        const LinkQuality q = quality();
        throw LinkError("the NXT at " + options_.address.to_string() + " is not connected"
                        + (q.last_error.empty() ? "" : ": " + q.last_error));
    }
    try {
        drain_owed_replies();
        if (in_flight_.empty()) {
            std::this_thread::sleep_until(next_read_at_);  // never faster than min_period
            send_read_request();
        }
        const InFlight& oldest = in_flight_.front();
        const auto deadline = oldest.sent + options_.reply_timeout;
        // Keep the pipeline full while waiting: the next read goes out a period after the
        // last one, so its reply is due about when the loop wants it.
        while (!stream_->wait_readable(in_flight_.size() < pipeline_depth(options_.mode)
                                           ? std::min(deadline, next_read_at_)
                                           : deadline)) {
            if (Clock::now() >= deadline) {
                on_timeout(opcode_name(oldest.replies.front()) + " reply late");
                return std::nullopt;
            }
            send_read_request();
        }
        std::optional<SensorFrame> frame = receive_cycle();
        if (!frame) {
            return std::nullopt;
        }
        const auto now = Clock::now();
        {
            // Cycle times are the intervals between frames: the first frame has none.
            const std::lock_guard lock(quality_mutex_);
            if (quality_.cycles == 0) {
                first_frame_at_ = now;
            } else {
                const double cycle = seconds_between(last_frame_at_, now);
                quality_.last_cycle_seconds = cycle;
                quality_.max_cycle_seconds = std::max(quality_.max_cycle_seconds, cycle);
                quality_.mean_cycle_seconds =
                    seconds_between(first_frame_at_, now) / static_cast<double>(quality_.cycles);
            }
            ++quality_.cycles;
        }
        last_frame_at_ = now;
        consecutive_timeouts_ = 0;
        frame->time = seconds_between(connected_at_, now);
        frame->sequence = ++next_sequence_;
        return frame;
    } catch (const StreamClosed& error) {
        fail("the NXT at " + options_.address.to_string()
             + " closed the link: " + std::string(error.what()));
    } catch (const FramingError& error) {
        fail("the NXT at " + options_.address.to_string()
             + " sent garbage: " + std::string(error.what()));
    }
}

// The replies of the oldest request in flight, in order. A reply that is malformed or
// refused costs this cycle its frame (counted), unless the brick says the wiring is wrong.
std::optional<SensorFrame> NxtLink::receive_cycle() {
    const InFlight request = in_flight_.front();
    in_flight_.erase(in_flight_.begin());
    const auto deadline = request.sent + options_.reply_timeout;
    std::vector<Telegram> replies;
    replies.reserve(request.replies.size());
    try {
        for (std::size_t i = 0; i < request.replies.size(); ++i) {
            replies.push_back(read_telegram(*stream_, deadline));
        }
    } catch (const StreamTimeout&) {
        owed_replies_ += request.replies.size() - replies.size();
        on_timeout(opcode_name(request.replies.at(replies.size())) + " reply late");
        return std::nullopt;
    }
    try {
        return options_.mode == CycleMode::Relay ? frame_from_relay(replies.front())
                                                 : frame_from_direct(replies);
    } catch (const ReplyError& error) {
        if (error.status() == status::kOutOfRange || error.status() == status::kBadPort) {
            fail("the NXT refused a port of the wiring: " + std::string(error.what()));
        }
        const std::lock_guard lock(quality_mutex_);
        ++quality_.rejected_replies;
        quality_.last_error = error.what();
        return std::nullopt;
    }
}

SensorFrame NxtLink::frame_from_direct(std::span<const Telegram> replies) {
    const NxtWiring& w = options_.wiring;
    const OutputStateReply right = decode_output_state_reply(replies[0]);
    const OutputStateReply left = decode_output_state_reply(replies[1]);
    const InputValues front = decode_input_values_reply(replies[2]);
    const InputValues rear = decode_input_values_reply(replies[3]);
    if (right.state.port != w.right_motor || left.state.port != w.left_motor
        || front.port != w.front_ir || rear.port != w.rear_ir) {
        throw ReplyError("replies out of order (ports " + std::to_string(right.state.port) + ", "
                             + std::to_string(left.state.port) + ", " + std::to_string(front.port)
                             + ", " + std::to_string(rear.port) + ")",
                         std::nullopt);
    }
    if (replies.size() > 4) {
        const std::uint16_t battery = decode_battery_level_reply(replies[4]);
        const std::lock_guard lock(quality_mutex_);
        quality_.battery_millivolts = battery;
    }
    const std::int32_t sign = w.reversed_motors ? -1 : 1;
    SensorFrame frame;
    frame.encoder_counts = {sign * right.rotation_count, sign * left.rotation_count};
    frame.ir_adc = {front.raw, rear.raw};
    frame.ir_valid = {front.valid, rear.valid};
    if (!front.valid || !rear.valid) {
        const std::lock_guard lock(quality_mutex_);
        ++quality_.invalid_ir_readings;
    }
    return frame;
}

std::optional<SensorFrame> NxtLink::frame_from_relay(const Telegram& reply) {
    const std::optional<MailboxMessage> message = decode_message_read_reply(reply);
    if (!message) {
        return std::nullopt;  // no new reading since the last read: nothing to step on
    }
    const RelayReading reading = parse_relay_message(message->data);
    const std::int32_t sign = options_.wiring.reversed_motors ? -1 : 1;
    SensorFrame frame;
    frame.encoder_counts = {sign * reading.right_count, sign * reading.left_count};
    frame.ir_adc = {reading.front_raw, reading.rear_raw};
    frame.ir_valid = {reading.front_valid, reading.rear_valid};
    const std::lock_guard lock(quality_mutex_);
    quality_.battery_millivolts = reading.battery_millivolts;
    if (!reading.front_valid || !reading.rear_valid) {
        ++quality_.invalid_ir_readings;
    }
    return frame;
}

}  // namespace legofeup::comms::nxt
