#pragma once
// Byte layouts of the NXT direct commands (docs/nxt.md), shared by the four codecs: host
// requests, host reply decoding, brick request decoding and brick replies. Offsets count from
// the telegram's first byte (the type), without the two length bytes of the framing.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "../byte_order.hpp"
#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::comms::nxt::layout {

using comms::detail::ByteReader;
using comms::detail::ByteWriter;

// Every telegram: type · opcode. A reply adds the status byte before its payload.
inline constexpr std::size_t kType = 0;
inline constexpr std::size_t kOpcode = 1;
inline constexpr std::size_t kStatus = 2;
inline constexpr std::size_t kRequestHeaderSize = 2;
inline constexpr std::size_t kReplyHeaderSize = 3;

// STARTPROGRAM: the file name as a 20-byte ASCIIZ field (19 characters and the NUL).
inline constexpr std::size_t kFileNameField = 20;
inline constexpr std::size_t kStartProgramSize = kRequestHeaderSize + kFileNameField;

// Fixed-size requests: type · opcode · the fields of the table in docs/nxt.md.
inline constexpr std::size_t kStopProgramSize = kRequestHeaderSize;
inline constexpr std::size_t kSetOutputStateSize = kRequestHeaderSize + 10;
inline constexpr std::size_t kSetInputModeSize = kRequestHeaderSize + 3;
inline constexpr std::size_t kGetOutputStateSize = kRequestHeaderSize + 1;
inline constexpr std::size_t kGetInputValuesSize = kRequestHeaderSize + 1;
inline constexpr std::size_t kResetMotorPositionSize = kRequestHeaderSize + 2;
inline constexpr std::size_t kGetBatteryLevelSize = kRequestHeaderSize;
inline constexpr std::size_t kKeepAliveSize = kRequestHeaderSize;
inline constexpr std::size_t kMessageReadSize = kRequestHeaderSize + 3;

// MESSAGEWRITE: inbox · size · size bytes of data, the last one the NUL.
inline constexpr std::size_t kMessageWriteInbox = 2;
inline constexpr std::size_t kMessageWriteSize = 3;
inline constexpr std::size_t kMessageWriteData = 4;

// Replies: 02 · opcode · status · payload. The payload keeps its length whatever the status.
inline constexpr std::size_t kStatusReplySize = kReplyHeaderSize;
inline constexpr std::size_t kOutputStateReplySize = 25;
inline constexpr std::size_t kInputValuesReplySize = 16;
inline constexpr std::size_t kBatteryLevelReplySize = 5;
inline constexpr std::size_t kKeepAliveReplySize = 7;
inline constexpr std::size_t kMessageReadReplySize = 64;

// The OutputState block: at offset 2 of SETOUTPUTSTATE and offset 3 of GETOUTPUTSTATE's reply.
inline constexpr std::size_t kOutputStateBlockSize = 10;
inline constexpr std::size_t kRequestOutputState = kRequestHeaderSize;
inline constexpr std::size_t kReplyOutputState = kReplyHeaderSize;
// GETOUTPUTSTATE's counters follow the block.
inline constexpr std::size_t kTachoCount = kReplyOutputState + kOutputStateBlockSize;
inline constexpr std::size_t kBlockTachoCount = kTachoCount + 4;
inline constexpr std::size_t kRotationCount = kBlockTachoCount + 4;
static_assert(kRotationCount + 4 == kOutputStateReplySize);
static_assert(kRequestOutputState + kOutputStateBlockSize == kSetOutputStateSize);

// GETINPUTVALUES's reply fields.
inline constexpr std::size_t kInputPort = 3;
inline constexpr std::size_t kInputValid = 4;
inline constexpr std::size_t kInputCalibrated = 5;
inline constexpr std::size_t kInputType = 6;
inline constexpr std::size_t kInputMode = 7;
inline constexpr std::size_t kInputRaw = 8;
inline constexpr std::size_t kInputNormalized = 10;
inline constexpr std::size_t kInputScaled = 12;
inline constexpr std::size_t kInputCalibratedValue = 14;
static_assert(kInputCalibratedValue + 2 == kInputValuesReplySize);

// MESSAGEREAD's reply: local inbox · size · 59 data bytes (the message, then zeros).
inline constexpr std::size_t kMessageReadLocalInbox = 3;
inline constexpr std::size_t kMessageReadMessageSize = 4;
inline constexpr std::size_t kMessageReadData = 5;
static_assert(kMessageReadData + kMaxMessageSize == kMessageReadReplySize);
static_assert(kMessageReadReplySize <= kMaxTelegramSize);

/// The wire's booleans are bytes; the firmware reads any non-zero byte as true.
inline bool to_bool(std::uint8_t byte) {
    return byte != 0;
}
inline std::uint8_t from_bool(bool value) {
    return value ? 1 : 0;
}

inline void write_bytes(ByteWriter& out, std::size_t offset, std::span<const std::uint8_t> bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        out.u8(offset + i, bytes[i]);
    }
}

inline void write_output_state(ByteWriter& out, std::size_t offset, const OutputState& state) {
    out.u8(offset, state.port);
    out.u8(offset + 1, std::bit_cast<std::uint8_t>(state.power));
    out.u8(offset + 2, state.mode);
    out.u8(offset + 3, state.regulation);
    out.u8(offset + 4, std::bit_cast<std::uint8_t>(state.turn_ratio));
    out.u8(offset + 5, state.run_state);
    out.u32(offset + 6, state.tacho_limit);
}

inline OutputState read_output_state(const ByteReader& in, std::size_t offset) {
    OutputState state;
    state.port = in.u8(offset);
    state.power = std::bit_cast<std::int8_t>(in.u8(offset + 1));
    state.mode = in.u8(offset + 2);
    state.regulation = in.u8(offset + 3);
    state.turn_ratio = std::bit_cast<std::int8_t>(in.u8(offset + 4));
    state.run_state = in.u8(offset + 5);
    state.tacho_limit = in.u32(offset + 6);
    return state;
}

/// "0x0C": one byte as the messages show it.
std::string hex_byte(std::uint8_t byte);
/// One of the direct commands of the Opcode enum.
bool is_known_opcode(std::uint8_t opcode);

}  // namespace legofeup::comms::nxt::layout
