// Host side: the direct-command requests. Each encoder refuses, with std::invalid_argument
// naming the field, what the firmware would reject or misread: sending it would only come
// back as an error status, or as nothing at all for a no-reply command.

#include <stdexcept>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "telegram_layout.hpp"

namespace legofeup::comms::nxt {
namespace {

using layout::ByteWriter;

constexpr int kMaxPower = 100;  // power and turn ratio are percentages: −100…100

/// A telegram of `size` bytes with its type and opcode set, the rest zero.
ByteWriter start_request(Opcode opcode, bool reply, std::size_t size) {
    ByteWriter out(size);
    const TelegramType type = reply ? TelegramType::DirectWithReply : TelegramType::DirectNoReply;
    out.u8(layout::kType, static_cast<std::uint8_t>(type));
    out.u8(layout::kOpcode, static_cast<std::uint8_t>(opcode));
    return out;
}

/// Throws "SETOUTPUTSTATE: power = 120, expected -100..100" unless `ok`.
void require(bool ok, Opcode opcode, const char* field, int value, const char* expected) {
    if (!ok) {
        throw std::invalid_argument(opcode_name(opcode) + ": " + field + " = "
                                    + std::to_string(value) + ", expected " + expected);
    }
}

void require_output_port(Opcode opcode, std::uint8_t port) {
    require(port < kOutputPorts, opcode, "port", port, "0..2 (A, B, C)");
}

void require_input_port(Opcode opcode, std::uint8_t port) {
    require(port < kInputPorts, opcode, "port", port, "0..3 (sensor ports 1..4)");
}

void require_mailbox(Opcode opcode, const char* field, std::uint8_t inbox) {
    require(inbox < kMailboxCount, opcode, field, inbox, "0..19");
}

void require_percent(Opcode opcode, const char* field, std::int8_t value) {
    require(value >= -kMaxPower && value <= kMaxPower, opcode, field, value, "-100..100");
}

void require_output_state(const OutputState& state) {
    constexpr Opcode op = Opcode::SetOutputState;
    require(state.port < kOutputPorts || state.port == kAllOutputs, op, "port", state.port,
            "0..2 (A, B, C) or 255 (all)");
    require_percent(op, "power", state.power);
    require((state.mode & ~(kModeMotorOn | kModeBrake | kModeRegulated)) == 0, op, "mode",
            state.mode, "a combination of MOTORON 1, BRAKE 2, REGULATED 4");
    require(state.regulation <= kRegulationMotorSync, op, "regulation", state.regulation,
            "0 (idle), 1 (motor speed) or 2 (motor sync)");
    require_percent(op, "turn_ratio", state.turn_ratio);
    const bool known_run_state =
        state.run_state == kRunStateIdle || state.run_state == kRunStateRampUp
        || state.run_state == kRunStateRunning || state.run_state == kRunStateRampDown;
    require(known_run_state, op, "run_state", state.run_state,
            "0 (idle), 16 (ramp up), 32 (running) or 64 (ramp down)");
}

}  // namespace

Telegram encode_start_program(const std::string& file_name, bool reply) {
    constexpr std::size_t kMaxName = layout::kFileNameField - 1;
    if (file_name.empty() || file_name.size() > kMaxName) {
        throw std::invalid_argument("STARTPROGRAM: file_name \"" + file_name + "\" has "
                                    + std::to_string(file_name.size())
                                    + " characters, expected 1..19 (e.g. \"legofeup.rxe\")");
    }
    if (file_name.find('\0') != std::string::npos) {
        throw std::invalid_argument("STARTPROGRAM: file_name contains a NUL character");
    }
    ByteWriter out = start_request(Opcode::StartProgram, reply, layout::kStartProgramSize);
    // ASCIIZ in a fixed 20-byte field: the NUL and the padding are the writer's zeros.
    out.text(layout::kRequestHeaderSize, file_name, layout::kFileNameField);
    return out.take();
}

Telegram encode_stop_program(bool reply) {
    return start_request(Opcode::StopProgram, reply, layout::kStopProgramSize).take();
}

Telegram encode_set_output_state(const OutputState& state, bool reply) {
    require_output_state(state);
    ByteWriter out = start_request(Opcode::SetOutputState, reply, layout::kSetOutputStateSize);
    layout::write_output_state(out, layout::kRequestOutputState, state);
    return out.take();
}

Telegram encode_set_input_mode(std::uint8_t port, std::uint8_t sensor_type,
                               std::uint8_t sensor_mode, bool reply) {
    require_input_port(Opcode::SetInputMode, port);
    // Types 0x00–0x11 exist in firmware 1.29 (NO_SENSOR … the colour sensor's modes). Every
    // mode byte is valid: the high 3 bits choose the mode, the low 5 the slope.
    constexpr std::uint8_t kSensorTypes = 0x12;
    require(sensor_type < kSensorTypes, Opcode::SetInputMode, "sensor_type", sensor_type,
            "0..17 (e.g. 1 SWITCH, 6 LIGHT_INACTIVE)");
    ByteWriter out = start_request(Opcode::SetInputMode, reply, layout::kSetInputModeSize);
    out.u8(2, port);
    out.u8(3, sensor_type);
    out.u8(4, sensor_mode);
    return out.take();
}

Telegram encode_get_output_state(std::uint8_t port) {
    require_output_port(Opcode::GetOutputState, port);
    ByteWriter out = start_request(Opcode::GetOutputState, true, layout::kGetOutputStateSize);
    out.u8(2, port);
    return out.take();
}

Telegram encode_get_input_values(std::uint8_t port) {
    require_input_port(Opcode::GetInputValues, port);
    ByteWriter out = start_request(Opcode::GetInputValues, true, layout::kGetInputValuesSize);
    out.u8(2, port);
    return out.take();
}

Telegram encode_message_write(std::uint8_t inbox, std::span<const std::uint8_t> message,
                              bool reply) {
    require_mailbox(Opcode::MessageWrite, "inbox", inbox);
    // The size byte counts the NUL the encoder appends: at most 58 bytes of message.
    if (message.size() + 1 > kMaxMessageSize) {
        throw std::invalid_argument("MESSAGEWRITE: message has " + std::to_string(message.size())
                                    + " bytes, expected at most 58 (59 with its NUL)");
    }
    const std::size_t size = message.size() + 1;
    ByteWriter out = start_request(Opcode::MessageWrite, reply, layout::kMessageWriteData + size);
    out.u8(layout::kMessageWriteInbox, inbox);
    out.u8(layout::kMessageWriteSize, static_cast<std::uint8_t>(size));
    layout::write_bytes(out, layout::kMessageWriteData, message);
    return out.take();  // the last byte, the NUL, is the writer's zero
}

Telegram encode_reset_motor_position(std::uint8_t port, bool relative, bool reply) {
    require_output_port(Opcode::ResetMotorPosition, port);
    ByteWriter out =
        start_request(Opcode::ResetMotorPosition, reply, layout::kResetMotorPositionSize);
    out.u8(2, port);
    out.u8(3, layout::from_bool(relative));
    return out.take();
}

Telegram encode_get_battery_level() {
    return start_request(Opcode::GetBatteryLevel, true, layout::kGetBatteryLevelSize).take();
}

Telegram encode_keep_alive(bool reply) {
    return start_request(Opcode::KeepAlive, reply, layout::kKeepAliveSize).take();
}

Telegram encode_message_read(std::uint8_t remote_inbox, std::uint8_t local_inbox, bool remove) {
    require_mailbox(Opcode::MessageRead, "remote_inbox", remote_inbox);
    require_mailbox(Opcode::MessageRead, "local_inbox", local_inbox);
    ByteWriter out = start_request(Opcode::MessageRead, true, layout::kMessageReadSize);
    out.u8(2, remote_inbox);
    out.u8(3, local_inbox);
    out.u8(4, layout::from_bool(remove));
    return out.take();
}

}  // namespace legofeup::comms::nxt
