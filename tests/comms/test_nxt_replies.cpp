// NXT replies, host side (comms/src/nxt/telegram_replies.cpp): each decoder against a reply
// written out by hand, then every way a reply can be wrong — each truncation, one byte too
// many, another type, another opcode, each error status with its message — and the status
// and opcode names (status_text.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <set>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "nxt_test_support.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace test_support;

using Span = std::span<const std::uint8_t>;

// --- Replies written out by hand ------------------------------------------------------------

/// GETOUTPUTSTATE of port B: power −30, MOTORON|REGULATED, speed regulation, running,
/// TachoCount 1234, BlockTachoCount −5, RotationCount −123456.
const Bytes kOutputStateReply = {
    0x02, 0x06, 0x00,        // reply, GETOUTPUTSTATE, OK
    0x01,                    // port B
    0xE2,                    // power −30
    0x05, 0x01, 0x00, 0x20,  // mode, regulation, turn ratio, run state
    0x00, 0x00, 0x00, 0x00,  // tacho limit 0
    0xD2, 0x04, 0x00, 0x00,  // TachoCount 1234
    0xFB, 0xFF, 0xFF, 0xFF,  // BlockTachoCount −5
    0xC0, 0x1D, 0xFE, 0xFF,  // RotationCount −123456 = 0xFFFE1DC0
};

/// GETINPUTVALUES of port 1: valid, LIGHT_INACTIVE, raw mode, raw 512, normalized 1023,
/// scaled −2, calibrated 300.
const Bytes kInputValuesReply = {
    0x02, 0x07, 0x00,              // reply, GETINPUTVALUES, OK
    0x00, 0x01, 0x00, 0x06, 0x00,  // port, valid, calibrated, type, mode
    0x00, 0x02,                    // raw 512: the IR sensor's A/D value (bytes 8–9)
    0xFF, 0x03,                    // normalized 1023
    0xFE, 0xFF,                    // scaled −2
    0x2C, 0x01,                    // calibrated 300
};

const Bytes kBatteryReply = {0x02, 0x0B, 0x00, 0x40, 0x1F};                // 8000 mV
const Bytes kKeepAliveReply = {0x02, 0x0D, 0x00, 0xC0, 0x27, 0x09, 0x00};  // 600000 ms

/// MESSAGEREAD from local inbox 10: "abc" and its NUL, then 55 bytes of padding.
Bytes message_read_reply() {
    // Built at its full size and then filled: growing a vector made from an initializer list
    // makes GCC 12 at -O3 report an out-of-bounds memcpy (a false positive).
    constexpr std::array<std::uint8_t, 9> kHead = {0x02, 0x13, 0x00, 0x0A, 0x04,
                                                   'a',  'b',  'c',  0x00};
    Bytes reply(64, 0x00);
    std::copy(kHead.begin(), kHead.end(), reply.begin());
    return reply;
}

TEST(NxtReplies, OutputState) {
    const OutputStateReply reply = decode_output_state_reply(kOutputStateReply);
    EXPECT_EQ(reply.state.port, 1);
    EXPECT_EQ(reply.state.power, -30);
    EXPECT_EQ(reply.state.mode, kModeMotorOn | kModeRegulated);
    EXPECT_EQ(reply.state.regulation, kRegulationMotorSpeed);
    EXPECT_EQ(reply.state.turn_ratio, 0);
    EXPECT_EQ(reply.state.run_state, kRunStateRunning);
    EXPECT_EQ(reply.state.tacho_limit, 0U);
    EXPECT_EQ(reply.tacho_count, 1234);
    EXPECT_EQ(reply.block_tacho_count, -5);
    EXPECT_EQ(reply.rotation_count, -123456);
}

TEST(NxtReplies, InputValues) {
    const InputValues values = decode_input_values_reply(kInputValuesReply);
    EXPECT_EQ(values.port, 0);
    EXPECT_TRUE(values.valid);
    EXPECT_FALSE(values.calibrated);
    EXPECT_EQ(values.type, kSensorLightInactive);
    EXPECT_EQ(values.mode, kSensorModeRaw);
    EXPECT_EQ(values.raw, 512);
    EXPECT_EQ(values.normalized, 1023);
    EXPECT_EQ(values.scaled, -2);
    EXPECT_EQ(values.calibrated_value, 300);
}

TEST(NxtReplies, InputValuesReadsAnyNonZeroFlagAsTrue) {
    Bytes reply = kInputValuesReply;
    reply[4] = 0x00;
    reply[5] = 0x07;
    const InputValues values = decode_input_values_reply(reply);
    EXPECT_FALSE(values.valid);  // just after SETINPUTMODE
    EXPECT_TRUE(values.calibrated);
}

TEST(NxtReplies, BatteryAndKeepAlive) {
    EXPECT_EQ(decode_battery_level_reply(kBatteryReply), 8000);
    EXPECT_EQ(decode_keep_alive_reply(kKeepAliveReply), 600000U);
}

TEST(NxtReplies, StatusOnlyReplies) {
    for (const Opcode opcode :
         {Opcode::StartProgram, Opcode::StopProgram, Opcode::SetOutputState, Opcode::SetInputMode,
          Opcode::MessageWrite, Opcode::ResetMotorPosition}) {
        const Bytes reply = {0x02, static_cast<std::uint8_t>(opcode), 0x00};
        EXPECT_NO_THROW(decode_status_reply(reply, opcode)) << opcode_name(opcode);
    }
}

TEST(NxtReplies, MessageReadReturnsSizeBytesWithTheNul) {
    const auto message = decode_message_read_reply(message_read_reply());
    ASSERT_TRUE(message.has_value());
    EXPECT_EQ(message->local_inbox, 10);
    EXPECT_EQ(message->data, (Bytes{'a', 'b', 'c', 0x00}));
}

TEST(NxtReplies, MessageReadIgnoresThePadding) {
    Bytes reply = message_read_reply();
    reply[20] = 0xAA;
    reply[63] = 0x55;
    const auto message = decode_message_read_reply(reply);
    ASSERT_TRUE(message.has_value());
    EXPECT_EQ(message->data, (Bytes{'a', 'b', 'c', 0x00}));
}

TEST(NxtReplies, MessageReadSizeLimits) {
    Bytes reply = message_read_reply();
    reply[4] = 59;  // the whole data field
    const auto full = decode_message_read_reply(reply);
    ASSERT_TRUE(full.has_value());
    EXPECT_EQ(full->data.size(), 59U);
    EXPECT_EQ(Bytes(full->data.begin(), full->data.begin() + 4), (Bytes{'a', 'b', 'c', 0x00}));
    for (const std::uint8_t size : Bytes{0, 60, 255}) {
        reply[4] = size;
        const auto error = caught<ReplyError>([&] { decode_message_read_reply(reply); });
        ASSERT_TRUE(error.has_value());
        EXPECT_EQ(std::string(error->what()), "MESSAGEREAD reply: message size "
                                                  + std::to_string(size)
                                                  + ", expected 1..59 (NUL included)");
        EXPECT_FALSE(error->status().has_value());
    }
}

TEST(NxtReplies, MessageReadEmptyMailboxIsNoMessage) {
    Bytes reply(64, 0x00);
    reply[0] = 0x02;
    reply[1] = 0x13;
    reply[2] = status::kMailboxEmpty;
    EXPECT_EQ(decode_message_read_reply(reply), std::nullopt);
    // Judged by its status, like every refusal: a shortened reply is still "empty".
    EXPECT_EQ(decode_message_read_reply(Bytes{0x02, 0x13, 0x40}), std::nullopt);
}

// --- Malformed replies, for every decoder ---------------------------------------------------

struct DecoderCase {
    const char* name;
    Opcode opcode;
    Bytes valid;
    std::function<void(Span)> decode;
};

std::vector<DecoderCase> decoder_cases() {
    return {
        {"GETOUTPUTSTATE", Opcode::GetOutputState, kOutputStateReply,
         [](Span r) { decode_output_state_reply(r); }},
        {"GETINPUTVALUES", Opcode::GetInputValues, kInputValuesReply,
         [](Span r) { decode_input_values_reply(r); }},
        {"GETBATTERYLEVEL", Opcode::GetBatteryLevel, kBatteryReply,
         [](Span r) { decode_battery_level_reply(r); }},
        {"KEEPALIVE", Opcode::KeepAlive, kKeepAliveReply,
         [](Span r) { decode_keep_alive_reply(r); }},
        {"MESSAGEREAD", Opcode::MessageRead, message_read_reply(),
         [](Span r) { decode_message_read_reply(r); }},
        {"SETOUTPUTSTATE",
         Opcode::SetOutputState,
         {0x02, 0x04, 0x00},
         [](Span r) { decode_status_reply(r, Opcode::SetOutputState); }},
        {"STARTPROGRAM",
         Opcode::StartProgram,
         {0x02, 0x00, 0x00},
         [](Span r) { decode_status_reply(r, Opcode::StartProgram); }},
    };
}

/// The ReplyError `bytes` give, checked to be a malformed reply (no status).
std::string malformed(const DecoderCase& c, const Bytes& bytes) {
    const auto error = caught<ReplyError>([&] { c.decode(bytes); });
    if (!error) {
        return "<accepted " + hex(bytes) + ">";
    }
    EXPECT_FALSE(error->status().has_value()) << c.name << ": " << error->what();
    return error->what();
}

TEST(NxtReplies, ValidRepliesDecode) {
    for (const DecoderCase& c : decoder_cases()) {
        EXPECT_NO_THROW(c.decode(c.valid)) << c.name;
    }
}

TEST(NxtReplies, EveryTruncationIsRefusedWithTheLengths) {
    for (const DecoderCase& c : decoder_cases()) {
        const std::string expected = " bytes, expected " + std::to_string(c.valid.size());
        for (std::size_t size = 0; size < c.valid.size(); ++size) {
            const Bytes cut(c.valid.begin(), c.valid.begin() + static_cast<std::ptrdiff_t>(size));
            EXPECT_EQ(malformed(c, cut),
                      std::string(c.name) + " reply: " + std::to_string(size) + expected);
        }
    }
}

TEST(NxtReplies, OneByteTooManyIsRefused) {
    for (const DecoderCase& c : decoder_cases()) {
        Bytes longer = c.valid;
        longer.push_back(0x00);
        EXPECT_EQ(malformed(c, longer), std::string(c.name)
                                            + " reply: " + std::to_string(longer.size())
                                            + " bytes, expected " + std::to_string(c.valid.size()));
    }
}

TEST(NxtReplies, ARequestIsNotAReply) {
    for (const DecoderCase& c : decoder_cases()) {
        for (const std::uint8_t type : Bytes{0x00, 0x01, 0x80, 0x81, 0x03, 0xFF}) {
            Bytes bytes = c.valid;
            bytes[0] = type;
            char type_text[5];
            std::snprintf(type_text, sizeof type_text, "0x%02X", static_cast<unsigned>(type));
            EXPECT_EQ(malformed(c, bytes), std::string(c.name) + " reply: type " + type_text
                                               + ", expected 0x02 (a reply)");
        }
    }
}

TEST(NxtReplies, AnotherOpcodeIsRefusedAndNamed) {
    for (const DecoderCase& c : decoder_cases()) {
        Bytes bytes = c.valid;
        bytes[1] = c.opcode == Opcode::GetInputValues ? 0x06 : 0x07;
        const char* other =
            c.opcode == Opcode::GetInputValues ? "0x06 (GETOUTPUTSTATE)" : "0x07 (GETINPUTVALUES)";
        EXPECT_EQ(malformed(c, bytes), std::string("reply to ") + c.name + " has opcode " + other);
        bytes[1] = 0x42;
        EXPECT_EQ(malformed(c, bytes),
                  std::string("reply to ") + c.name + " has opcode 0x42 (unknown)");
    }
}

const std::vector<std::uint8_t> kErrorStatuses = {
    status::kPending,
    status::kRequestFailed,
    status::kUnknownOpcode,
    status::kInsanePacket,
    status::kOutOfRange,
    status::kBusError,
    status::kBufferFull,
    status::kInvalidChannel,
    status::kChannelNotReady,
    status::kNoActiveProgram,
    status::kIllegalSize,
    status::kIllegalMailbox,
    status::kInvalidField,
    status::kBadPort,
    status::kOutOfMemory,
    status::kBadArguments,
    0x01,
};

TEST(NxtReplies, EachErrorStatusIsAReplyErrorCarryingIt) {
    for (const DecoderCase& c : decoder_cases()) {
        for (const std::uint8_t code : kErrorStatuses) {
            Bytes bytes = c.valid;
            bytes[2] = code;
            std::fill(bytes.begin() + 3, bytes.end(), 0x00);  // the firmware zero-fills
            const auto error = caught<ReplyError>([&] { c.decode(bytes); });
            ASSERT_TRUE(error.has_value()) << c.name;
            EXPECT_EQ(error->status(), code);
            EXPECT_EQ(std::string(error->what()),
                      std::string(c.name) + " reply: status " + describe_status(code));
            // A refusal shortened to its header is still reported as the refusal.
            const auto short_error = caught<ReplyError>([&] { c.decode(Span(bytes).first(3)); });
            ASSERT_TRUE(short_error.has_value());
            EXPECT_EQ(short_error->status(), code);
        }
    }
}

TEST(NxtReplies, MailboxEmptyIsAnErrorExceptForMessageRead) {
    for (const DecoderCase& c : decoder_cases()) {
        Bytes bytes = c.valid;
        bytes[2] = status::kMailboxEmpty;
        if (c.opcode == Opcode::MessageRead) {
            EXPECT_EQ(decode_message_read_reply(bytes), std::nullopt);
            continue;
        }
        const auto error = caught<ReplyError>([&] { c.decode(bytes); });
        ASSERT_TRUE(error.has_value()) << c.name;
        EXPECT_EQ(error->status(), status::kMailboxEmpty);
    }
}

TEST(NxtReplies, ErrorMessagesReadWell) {
    Bytes bytes = kOutputStateReply;
    bytes[2] = status::kOutOfRange;
    EXPECT_EQ(message_of<ReplyError>([&] { decode_output_state_reply(bytes); }),
              "GETOUTPUTSTATE reply: status 0xC0 (out of range: bad port or value)");
    EXPECT_EQ(message_of<ReplyError>([] {
                  decode_status_reply(Bytes{0x02, 0x01, 0xEC}, Opcode::StopProgram);
              }),
              "STOPPROGRAM reply: status 0xEC (no active program)");
    EXPECT_EQ(message_of<ReplyError>(
                  [] { decode_input_values_reply(Span(kInputValuesReply).first(15)); }),
              "GETINPUTVALUES reply: 15 bytes, expected 16");
    // A ReplyError is a LinkError: the link's callers catch one type.
    EXPECT_THROW(decode_battery_level_reply(Bytes{}), LinkError);
}

// --- Names ---------------------------------------------------------------------------------

TEST(NxtStatusText, EveryStatusHasItsOwnMeaning) {
    std::set<std::string> texts;
    for (const std::uint8_t code : kErrorStatuses) {
        if (code == 0x01) {
            continue;
        }
        const std::string text = describe_status(code);
        char prefix[8];
        std::snprintf(prefix, sizeof prefix, "0x%02X (", static_cast<unsigned>(code));
        EXPECT_EQ(text.rfind(prefix, 0), 0U) << text;
        EXPECT_EQ(text.back(), ')') << text;
        EXPECT_EQ(text.find("does not define"), std::string::npos) << text;
        texts.insert(text);
    }
    EXPECT_EQ(texts.size(), kErrorStatuses.size() - 1);
    EXPECT_EQ(describe_status(status::kOk), "0x00 (success)");
    EXPECT_EQ(describe_status(status::kMailboxEmpty), "0x40 (mailbox empty)");
    EXPECT_EQ(describe_status(status::kBadPort), "0xF0 (bad input or output port)");
    EXPECT_EQ(describe_status(0x12), "0x12 (a status this firmware does not define)");
}

TEST(NxtStatusText, OpcodeNames) {
    EXPECT_EQ(opcode_name(Opcode::StartProgram), "STARTPROGRAM");
    EXPECT_EQ(opcode_name(Opcode::StopProgram), "STOPPROGRAM");
    EXPECT_EQ(opcode_name(Opcode::SetOutputState), "SETOUTPUTSTATE");
    EXPECT_EQ(opcode_name(Opcode::SetInputMode), "SETINPUTMODE");
    EXPECT_EQ(opcode_name(Opcode::GetOutputState), "GETOUTPUTSTATE");
    EXPECT_EQ(opcode_name(Opcode::GetInputValues), "GETINPUTVALUES");
    EXPECT_EQ(opcode_name(Opcode::MessageWrite), "MESSAGEWRITE");
    EXPECT_EQ(opcode_name(Opcode::ResetMotorPosition), "RESETMOTORPOSITION");
    EXPECT_EQ(opcode_name(Opcode::GetBatteryLevel), "GETBATTERYLEVEL");
    EXPECT_EQ(opcode_name(Opcode::KeepAlive), "KEEPALIVE");
    EXPECT_EQ(opcode_name(Opcode::MessageRead), "MESSAGEREAD");
    EXPECT_EQ(opcode_name(static_cast<Opcode>(0x42)), "opcode 0x42");
}

}  // namespace
}  // namespace legofeup::comms::nxt
