// The direct-command handler of the emulated brick (cCmdHandleRemoteCommands in the
// firmware's c_cmd.c, and the message queues beside it), over the output, input, mailbox and
// relay-program models of this directory.

#include "legofeup/nxtemu/brick_firmware.hpp"

#include <utility>
#include <variant>

#include "input_ports.hpp"
#include "mailboxes.hpp"
#include "output_ports.hpp"
#include "relay_program.hpp"

namespace legofeup::nxtemu {
namespace {

namespace nxt = comms::nxt;
namespace status = nxt::status;
using nxt::Opcode;
using nxt::Telegram;

constexpr double kMillivoltsPerVolt = 1000.0;

MotorModel motor_model(const FirmwareOptions& options) {
    MotorModel model;
    model.max_degrees_per_second = options.max_motor_degrees_per_second;
    model.battery_volts = options.battery_millivolts / kMillivoltsPerVolt;
    return model;
}

/// The reply the firmware gives `opcode` with a refusing `code`: full length, payload zeros.
Telegram refusal(std::uint8_t opcode, std::uint8_t code) {
    switch (static_cast<Opcode>(opcode)) {
        case Opcode::GetOutputState:
            return nxt::encode_output_state_reply(code, {});
        case Opcode::GetInputValues:
            return nxt::encode_input_values_reply(code, {});
        case Opcode::GetBatteryLevel:
            return nxt::encode_battery_level_reply(code, 0);
        case Opcode::KeepAlive:
            return nxt::encode_keep_alive_reply(code, 0);
        case Opcode::MessageRead:
            return nxt::encode_message_read_reply(code, {});
        default:
            return nxt::encode_status_reply(opcode, code);
    }
}

}  // namespace

struct BrickFirmware::State {
    State(BrickHardware& hw, FirmwareOptions opts)
        : hardware(hw), options(std::move(opts)), outputs(motor_model(options)) {}

    ProgramDevices devices() { return {inputs, outputs, mailboxes, options, counters}; }

    /// Devices to their defaults, as the firmware does when a program starts or ends.
    void reset_devices(double now) {
        inputs.reset_all(now);
        outputs.reset_all();
        mailboxes.clear();
    }

    void advance(double now) {
        if (now < time) {
            now = time;  // the caller's clock never runs backwards here
        }
        time = now;
        outputs.update(hardware.tacho_counts());
        inputs.update(hardware.adc(), now);
        ProgramDevices program_devices = devices();
        relay.run_until(now, program_devices);
        push_speeds();
    }

    void push_speeds() {
        const auto speeds = outputs.speeds();
        if (speeds != motor_speeds || !speeds_given) {
            motor_speeds = speeds;
            speeds_given = true;
            hardware.set_motor_speeds(speeds);
        }
    }

    bool program_running() const { return relay.running(); }

    // One handler per request. Each returns the reply (sent only if the host asked for one).
    Telegram operator()(const nxt::StartProgram& request) {
        if (!options.relay_installed || request.file_name != options.relay_program) {
            return nxt::encode_status_reply(op(Opcode::StartProgram), status::kOutOfRange);
        }
        // A running program is ended first (its devices reset), then the new one starts.
        reset_devices(time);
        ProgramDevices program_devices = devices();
        relay.start(time, program_devices);
        ++counters.programs_started;
        return nxt::encode_status_reply(op(Opcode::StartProgram), status::kOk);
    }

    Telegram operator()(const nxt::StopProgram&) {
        if (!program_running()) {
            return nxt::encode_status_reply(op(Opcode::StopProgram), status::kNoActiveProgram);
        }
        relay.stop();
        reset_devices(time);
        return nxt::encode_status_reply(op(Opcode::StopProgram), status::kOk);
    }

    Telegram operator()(const nxt::SetOutputState& request) {
        const std::uint8_t port = request.state.port;
        if (port == nxt::kAllOutputs) {
            for (std::uint8_t p = 0; p < kOutputCount; ++p) {
                outputs.set(p, request.state);
            }
        } else if (port < kOutputCount) {
            outputs.set(port, request.state);
        } else {
            return nxt::encode_status_reply(op(Opcode::SetOutputState), status::kOutOfRange);
        }
        return nxt::encode_status_reply(op(Opcode::SetOutputState), status::kOk);
    }

    Telegram operator()(const nxt::SetInputMode& request) {
        if (request.port >= kInputCount) {
            return nxt::encode_status_reply(op(Opcode::SetInputMode), status::kOutOfRange);
        }
        inputs.set_mode(request.port, request.sensor_type, request.sensor_mode, time);
        return nxt::encode_status_reply(op(Opcode::SetInputMode), status::kOk);
    }

    Telegram operator()(const nxt::GetOutputState& request) const {
        if (request.port >= kOutputCount) {
            return refusal(op(Opcode::GetOutputState), status::kOutOfRange);
        }
        return nxt::encode_output_state_reply(status::kOk, outputs.reply(request.port));
    }

    Telegram operator()(const nxt::GetInputValues& request) const {
        if (request.port >= kInputCount) {
            return refusal(op(Opcode::GetInputValues), status::kOutOfRange);
        }
        return nxt::encode_input_values_reply(status::kOk, inputs.values(request.port, time));
    }

    Telegram operator()(const nxt::MessageWrite& request) {
        // cCmdMessageWrite: the queue number first, then a running program.
        if (request.inbox >= nxt::kMailboxCount) {
            return nxt::encode_status_reply(op(Opcode::MessageWrite), status::kIllegalMailbox);
        }
        if (!program_running()) {
            return nxt::encode_status_reply(op(Opcode::MessageWrite), status::kNoActiveProgram);
        }
        mailboxes.write(request.inbox, request.message);
        return nxt::encode_status_reply(op(Opcode::MessageWrite), status::kOk);
    }

    Telegram operator()(const nxt::ResetMotorPosition& request) {
        if (request.port >= kOutputCount) {
            return nxt::encode_status_reply(op(Opcode::ResetMotorPosition), status::kOutOfRange);
        }
        outputs.reset_position(request.port, request.relative);
        return nxt::encode_status_reply(op(Opcode::ResetMotorPosition), status::kOk);
    }

    Telegram operator()(const nxt::GetBatteryLevel&) const {
        return nxt::encode_battery_level_reply(status::kOk, options.battery_millivolts);
    }

    Telegram operator()(const nxt::KeepAlive&) const {
        return nxt::encode_keep_alive_reply(status::kOk, options.sleep_limit_ms);
    }

    Telegram operator()(const nxt::MessageRead& request) {
        // cCmdMessageGetSize: a running program first, then the queue number.
        if (!program_running()) {
            return refusal(op(Opcode::MessageRead), status::kNoActiveProgram);
        }
        if (request.remote_inbox >= nxt::kMailboxCount) {
            return refusal(op(Opcode::MessageRead), status::kIllegalMailbox);
        }
        auto message = mailboxes.read(request.remote_inbox, request.remove);
        if (!message) {
            return refusal(op(Opcode::MessageRead), status::kMailboxEmpty);
        }
        if (request.remove && request.remote_inbox == RelayProgram::kResponseMailbox) {
            ++counters.relay_messages_read;
        }
        return nxt::encode_message_read_reply(status::kOk,
                                              {request.local_inbox, std::move(*message)});
    }

    static std::uint8_t op(Opcode opcode) { return static_cast<std::uint8_t>(opcode); }

    BrickHardware& hardware;
    FirmwareOptions options;
    InputPorts inputs;
    OutputPorts outputs;
    Mailboxes mailboxes;
    RelayProgram relay;
    FirmwareCounters counters;
    std::array<double, kOutputCount> motor_speeds{};
    bool speeds_given = false;
    double time = 0.0;
};

BrickFirmware::BrickFirmware(BrickHardware& hardware, FirmwareOptions options)
    : state_(std::make_unique<State>(hardware, std::move(options))) {}

BrickFirmware::~BrickFirmware() = default;

std::optional<Telegram> BrickFirmware::handle(std::span<const std::uint8_t> request,
                                              double now_seconds) {
    State& s = *state_;
    s.advance(now_seconds);
    const nxt::DecodedRequest decoded = nxt::decode_request(request);
    ++s.counters.requests;
    const Telegram reply =
        decoded.body ? std::visit(s, *decoded.body) : refusal(decoded.opcode, decoded.status);
    if (reply.at(2) != status::kOk) {
        ++s.counters.error_statuses;
    }
    s.push_speeds();  // a new output state turns the motors at once
    if (!decoded.wants_reply()) {
        ++s.counters.no_reply;
        return std::nullopt;
    }
    return reply;
}

void BrickFirmware::advance(double now_seconds) {
    state_->advance(now_seconds);
}

nxt::OutputStateReply BrickFirmware::output(std::uint8_t port) const {
    return state_->outputs.reply(port);
}

nxt::InputValues BrickFirmware::input(std::uint8_t port) const {
    return state_->inputs.values(port, state_->time);
}

const std::array<double, kOutputCount>& BrickFirmware::motor_speeds() const {
    return state_->motor_speeds;
}

std::optional<std::string> BrickFirmware::running_program() const {
    if (!state_->program_running()) {
        return std::nullopt;
    }
    return state_->options.relay_program;
}

const FirmwareCounters& BrickFirmware::counters() const {
    return state_->counters;
}

const FirmwareOptions& BrickFirmware::options() const {
    return state_->options;
}

}  // namespace legofeup::nxtemu
