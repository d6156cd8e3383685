// Brick side: the replies an emulated brick sends. As the firmware does, a reply keeps its
// full length whatever the status; when the status is not OK the payload is all zeros, so
// nothing stale or half-filled ever reaches the host.

#include <stdexcept>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "telegram_layout.hpp"

namespace legofeup::comms::nxt {
namespace {

using layout::ByteWriter;

/// 0x02 · opcode · status, then `size` − 3 zero bytes for the payload.
ByteWriter start_reply(Opcode opcode, std::uint8_t status, std::size_t size) {
    ByteWriter out(size);
    out.u8(layout::kType, static_cast<std::uint8_t>(TelegramType::Reply));
    out.u8(layout::kOpcode, static_cast<std::uint8_t>(opcode));
    out.u8(layout::kStatus, status);
    return out;
}

}  // namespace

Telegram encode_status_reply(std::uint8_t opcode, std::uint8_t status) {
    // The opcode stays a byte: the brick also answers opcodes it does not know.
    return start_reply(static_cast<Opcode>(opcode), status, layout::kStatusReplySize).take();
}

Telegram encode_output_state_reply(std::uint8_t status, const OutputStateReply& reply) {
    ByteWriter out = start_reply(Opcode::GetOutputState, status, layout::kOutputStateReplySize);
    if (status == status::kOk) {
        layout::write_output_state(out, layout::kReplyOutputState, reply.state);
        out.i32(layout::kTachoCount, reply.tacho_count);
        out.i32(layout::kBlockTachoCount, reply.block_tacho_count);
        out.i32(layout::kRotationCount, reply.rotation_count);
    }
    return out.take();
}

Telegram encode_input_values_reply(std::uint8_t status, const InputValues& values) {
    ByteWriter out = start_reply(Opcode::GetInputValues, status, layout::kInputValuesReplySize);
    if (status == status::kOk) {
        out.u8(layout::kInputPort, values.port);
        out.u8(layout::kInputValid, layout::from_bool(values.valid));
        out.u8(layout::kInputCalibrated, layout::from_bool(values.calibrated));
        out.u8(layout::kInputType, values.type);
        out.u8(layout::kInputMode, values.mode);
        out.u16(layout::kInputRaw, values.raw);
        out.u16(layout::kInputNormalized, values.normalized);
        out.u16(layout::kInputScaled, std::bit_cast<std::uint16_t>(values.scaled));
        out.u16(layout::kInputCalibratedValue,
                std::bit_cast<std::uint16_t>(values.calibrated_value));
    }
    return out.take();
}

Telegram encode_battery_level_reply(std::uint8_t status, std::uint16_t millivolts) {
    ByteWriter out = start_reply(Opcode::GetBatteryLevel, status, layout::kBatteryLevelReplySize);
    if (status == status::kOk) {
        out.u16(layout::kReplyHeaderSize, millivolts);
    }
    return out.take();
}

Telegram encode_keep_alive_reply(std::uint8_t status, std::uint32_t sleep_limit_ms) {
    ByteWriter out = start_reply(Opcode::KeepAlive, status, layout::kKeepAliveReplySize);
    if (status == status::kOk) {
        out.u32(layout::kReplyHeaderSize, sleep_limit_ms);
    }
    return out.take();
}

Telegram encode_message_read_reply(std::uint8_t status, const MailboxMessage& message) {
    ByteWriter out = start_reply(Opcode::MessageRead, status, layout::kMessageReadReplySize);
    if (status != status::kOk) {
        return out.take();
    }
    const std::size_t size = message.data.size();
    if (size == 0 || size > kMaxMessageSize) {
        throw std::invalid_argument("MESSAGEREAD reply: message.data has " + std::to_string(size)
                                    + " bytes, expected 1..59 (NUL included)");
    }
    out.u8(layout::kMessageReadLocalInbox, message.local_inbox);
    out.u8(layout::kMessageReadMessageSize, static_cast<std::uint8_t>(size));
    layout::write_bytes(out, layout::kMessageReadData, message.data);
    return out.take();  // the rest of the 59 data bytes stay zero
}

}  // namespace legofeup::comms::nxt
