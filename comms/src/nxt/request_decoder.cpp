// Brick side: a request telegram as the firmware sees it. Nothing here throws — garbage gets
// the status the firmware would answer. Only the telegram's shape is judged: ports, powers
// and mailboxes out of range decode, and the emulated brick's handlers refuse them, as the
// firmware's do. Like the firmware, any non-zero byte is a true boolean and the bytes after
// the file name's NUL are ignored.

#include <algorithm>

#include "legofeup/comms/nxt/telegram.hpp"
#include "telegram_layout.hpp"

namespace legofeup::comms::nxt {
namespace {

using layout::ByteReader;

/// The fixed length of each direct command's request; 0 for MESSAGEWRITE (its own size byte
/// says) and for opcodes the firmware does not know.
std::size_t request_size(std::uint8_t opcode) {
    switch (static_cast<Opcode>(opcode)) {
        case Opcode::StartProgram:
            return layout::kStartProgramSize;
        case Opcode::StopProgram:
            return layout::kStopProgramSize;
        case Opcode::SetOutputState:
            return layout::kSetOutputStateSize;
        case Opcode::SetInputMode:
            return layout::kSetInputModeSize;
        case Opcode::GetOutputState:
            return layout::kGetOutputStateSize;
        case Opcode::GetInputValues:
            return layout::kGetInputValuesSize;
        case Opcode::ResetMotorPosition:
            return layout::kResetMotorPositionSize;
        case Opcode::GetBatteryLevel:
            return layout::kGetBatteryLevelSize;
        case Opcode::KeepAlive:
            return layout::kKeepAliveSize;
        case Opcode::MessageRead:
            return layout::kMessageReadSize;
        case Opcode::MessageWrite:
            break;
    }
    return 0;
}

/// MESSAGEWRITE: the size byte must match the telegram and leave room for 1..59 bytes ending
/// in the NUL the host appends.
void decode_message_write(std::span<const std::uint8_t> telegram, DecodedRequest& request) {
    if (telegram.size() < layout::kMessageWriteData) {
        request.status = status::kInsanePacket;
        return;
    }
    const std::size_t size = telegram[layout::kMessageWriteSize];
    if (size == 0 || size > kMaxMessageSize
        || telegram.size() != layout::kMessageWriteData + size) {
        request.status = status::kIllegalSize;
        return;
    }
    if (telegram.back() != 0) {
        request.status = status::kInvalidField;  // not terminated: not a message the host sent
        return;
    }
    const auto data = telegram.subspan(layout::kMessageWriteData);
    request.body = MessageWrite{telegram[layout::kMessageWriteInbox], {data.begin(), data.end()}};
}

/// STARTPROGRAM: a 20-byte ASCIIZ field; a name that fills it without a NUL is refused.
void decode_start_program(std::span<const std::uint8_t> telegram, DecodedRequest& request) {
    const auto field = telegram.subspan(layout::kRequestHeaderSize, layout::kFileNameField);
    const auto nul = std::find(field.begin(), field.end(), std::uint8_t{0});
    if (nul == field.end()) {
        request.status = status::kBadArguments;
        return;
    }
    request.body = StartProgram{std::string(field.begin(), nul)};
}

/// The fixed-length requests, their length already checked.
RequestBody decode_fixed(Opcode opcode, const ByteReader& in) {
    switch (opcode) {
        case Opcode::StopProgram:
            return StopProgram{};
        case Opcode::SetOutputState:
            return SetOutputState{layout::read_output_state(in, layout::kRequestOutputState)};
        case Opcode::SetInputMode:
            return SetInputMode{in.u8(2), in.u8(3), in.u8(4)};
        case Opcode::GetOutputState:
            return GetOutputState{in.u8(2)};
        case Opcode::GetInputValues:
            return GetInputValues{in.u8(2)};
        case Opcode::ResetMotorPosition:
            return ResetMotorPosition{in.u8(2), layout::to_bool(in.u8(3))};
        case Opcode::GetBatteryLevel:
            return GetBatteryLevel{};
        case Opcode::KeepAlive:
            return KeepAlive{};
        case Opcode::MessageRead:
            return MessageRead{in.u8(2), in.u8(3), layout::to_bool(in.u8(4))};
        case Opcode::StartProgram:
        case Opcode::MessageWrite:
            break;  // variable content: decoded on their own
    }
    return KeepAlive{};  // unreachable: request_size() admitted only the opcodes above
}

}  // namespace

bool DecodedRequest::wants_reply() const {
    return type == TelegramType::DirectWithReply || type == TelegramType::SystemWithReply;
}

DecodedRequest decode_request(std::span<const std::uint8_t> telegram) {
    DecodedRequest request;
    if (telegram.empty()) {
        // Nothing to answer, and nobody asked: treated as a silent no-reply telegram.
        request.type = TelegramType::DirectNoReply;
        request.status = status::kInsanePacket;
        return request;
    }
    request.type = static_cast<TelegramType>(telegram[layout::kType]);
    request.opcode = telegram.size() > layout::kOpcode ? telegram[layout::kOpcode] : 0;
    switch (request.type) {
        case TelegramType::DirectWithReply:
        case TelegramType::DirectNoReply:
            break;
        case TelegramType::SystemWithReply:
        case TelegramType::SystemNoReply:
            // System commands (files, firmware, Bluetooth settings) are not emulated.
            request.status = status::kUnknownOpcode;
            return request;
        case TelegramType::Reply:
        default:
            // A reply, or a type the firmware ignores: it answers nothing.
            request.status = status::kInsanePacket;
            return request;
    }
    if (telegram.size() < layout::kRequestHeaderSize) {
        request.status = status::kInsanePacket;
        return request;
    }
    const auto opcode = static_cast<Opcode>(request.opcode);
    if (opcode == Opcode::MessageWrite) {
        decode_message_write(telegram, request);
        return request;
    }
    const std::size_t size = request_size(request.opcode);
    if (size == 0) {
        request.status = status::kUnknownOpcode;
    } else if (telegram.size() != size) {
        request.status = status::kInsanePacket;
    } else if (opcode == Opcode::StartProgram) {
        decode_start_program(telegram, request);
    } else {
        request.body = decode_fixed(opcode, ByteReader(telegram));
    }
    return request;
}

}  // namespace legofeup::comms::nxt
