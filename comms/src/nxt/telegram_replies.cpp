// Host side: the brick's replies. A reply is checked in the order that gives the most useful
// message — long enough to hold a header, type 0x02, the expected opcode, status OK, then the
// exact length — before any field is read. The status comes before the length because a
// refusal is the more useful news, and a brick may shorten the payload of a refused request.

#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "telegram_layout.hpp"

namespace legofeup::comms::nxt {
namespace {

using layout::ByteReader;

[[noreturn]] void malformed(Opcode opcode, const std::string& problem) {
    throw ReplyError(opcode_name(opcode) + " reply: " + problem, std::nullopt);
}

[[noreturn]] void wrong_length(std::span<const std::uint8_t> reply, Opcode opcode,
                               std::size_t size) {
    malformed(opcode, std::to_string(reply.size()) + " bytes, expected " + std::to_string(size));
}

/// Checks the header and returns the status: kOk, or kMailboxEmpty when `empty_mailbox_ok`.
/// Every other status throws ReplyError carrying it.
std::uint8_t check_header(std::span<const std::uint8_t> reply, Opcode opcode,
                          std::size_t expected_size, bool empty_mailbox_ok = false) {
    if (reply.size() < layout::kReplyHeaderSize) {
        wrong_length(reply, opcode, expected_size);
    }
    const std::uint8_t type = reply[layout::kType];
    if (type != static_cast<std::uint8_t>(TelegramType::Reply)) {
        malformed(opcode, "type " + layout::hex_byte(type) + ", expected 0x02 (a reply)");
    }
    const std::uint8_t got = reply[layout::kOpcode];
    if (got != static_cast<std::uint8_t>(opcode)) {
        const std::string name =
            layout::is_known_opcode(got) ? opcode_name(static_cast<Opcode>(got)) : "unknown";
        throw ReplyError("reply to " + opcode_name(opcode) + " has opcode " + layout::hex_byte(got)
                             + " (" + name + ")",
                         std::nullopt);
    }
    const std::uint8_t status = reply[layout::kStatus];
    if (status == status::kMailboxEmpty && empty_mailbox_ok) {
        return status;
    }
    if (status != status::kOk) {
        throw ReplyError(opcode_name(opcode) + " reply: status " + describe_status(status), status);
    }
    if (reply.size() != expected_size) {
        wrong_length(reply, opcode, expected_size);
    }
    return status;
}

}  // namespace

void decode_status_reply(std::span<const std::uint8_t> reply, Opcode expected) {
    check_header(reply, expected, layout::kStatusReplySize);
}

OutputStateReply decode_output_state_reply(std::span<const std::uint8_t> reply) {
    check_header(reply, Opcode::GetOutputState, layout::kOutputStateReplySize);
    const ByteReader in(reply);
    OutputStateReply decoded;
    decoded.state = layout::read_output_state(in, layout::kReplyOutputState);
    decoded.tacho_count = in.i32(layout::kTachoCount);
    decoded.block_tacho_count = in.i32(layout::kBlockTachoCount);
    decoded.rotation_count = in.i32(layout::kRotationCount);
    return decoded;
}

InputValues decode_input_values_reply(std::span<const std::uint8_t> reply) {
    check_header(reply, Opcode::GetInputValues, layout::kInputValuesReplySize);
    const ByteReader in(reply);
    InputValues values;
    values.port = in.u8(layout::kInputPort);
    values.valid = layout::to_bool(in.u8(layout::kInputValid));
    values.calibrated = layout::to_bool(in.u8(layout::kInputCalibrated));
    values.type = in.u8(layout::kInputType);
    values.mode = in.u8(layout::kInputMode);
    values.raw = in.u16(layout::kInputRaw);
    values.normalized = in.u16(layout::kInputNormalized);
    values.scaled = std::bit_cast<std::int16_t>(in.u16(layout::kInputScaled));
    values.calibrated_value = std::bit_cast<std::int16_t>(in.u16(layout::kInputCalibratedValue));
    return values;
}

std::uint16_t decode_battery_level_reply(std::span<const std::uint8_t> reply) {
    check_header(reply, Opcode::GetBatteryLevel, layout::kBatteryLevelReplySize);
    return ByteReader(reply).u16(layout::kReplyHeaderSize);
}

std::uint32_t decode_keep_alive_reply(std::span<const std::uint8_t> reply) {
    check_header(reply, Opcode::KeepAlive, layout::kKeepAliveReplySize);
    return ByteReader(reply).u32(layout::kReplyHeaderSize);
}

std::optional<MailboxMessage> decode_message_read_reply(std::span<const std::uint8_t> reply) {
    const std::uint8_t status =
        check_header(reply, Opcode::MessageRead, layout::kMessageReadReplySize, true);
    if (status == status::kMailboxEmpty) {
        return std::nullopt;  // nothing posted yet: normal while the program starts up
    }
    const ByteReader in(reply);
    const std::uint8_t size = in.u8(layout::kMessageReadMessageSize);
    if (size == 0 || size > kMaxMessageSize) {
        malformed(Opcode::MessageRead,
                  "message size " + std::to_string(size) + ", expected 1..59 (NUL included)");
    }
    // The reply always carries 59 data bytes; the message is the first `size` of them and
    // whatever follows is padding, ignored.
    MailboxMessage message;
    message.local_inbox = in.u8(layout::kMessageReadLocalInbox);
    const auto data = reply.subspan(layout::kMessageReadData, size);
    message.data.assign(data.begin(), data.end());
    return message;
}

}  // namespace legofeup::comms::nxt
