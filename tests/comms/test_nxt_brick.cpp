// NXT brick side (request_decoder.cpp, reply_encoders.cpp): every request decoded from bytes
// written out by hand, the status the firmware answers for each kind of garbage, replies
// against their layouts (zero-filled when refused), and round trips in both directions:
// host request → brick decode, brick reply → host decode.

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "nxt_test_support.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace test_support;

/// The body as `T`, failing the test (and returning a default) if it holds something else.
template <typename T>
T body_as(const DecodedRequest& request) {
    EXPECT_EQ(request.status, status::kOk);
    if (!request.body || !std::holds_alternative<T>(*request.body)) {
        ADD_FAILURE() << "body missing or of another request";
        return T{};
    }
    return std::get<T>(*request.body);
}

// --- Requests from bytes --------------------------------------------------------------------

TEST(NxtBrickRequests, SetOutputStateFromBytes) {
    const Bytes telegram = {0x80, 0x04, 0x02, 0xDB, 0x05, 0x01, 0x00, 0x20, 0x78, 0x56, 0x34, 0x12};
    const DecodedRequest request = decode_request(telegram);
    EXPECT_EQ(request.type, TelegramType::DirectNoReply);
    EXPECT_EQ(request.opcode, 0x04);
    EXPECT_FALSE(request.wants_reply());
    const OutputState state = body_as<SetOutputState>(request).state;
    EXPECT_EQ(state.port, 2);
    EXPECT_EQ(state.power, -37);
    EXPECT_EQ(state.mode, kModeMotorOn | kModeRegulated);
    EXPECT_EQ(state.regulation, kRegulationMotorSpeed);
    EXPECT_EQ(state.turn_ratio, 0);
    EXPECT_EQ(state.run_state, kRunStateRunning);
    EXPECT_EQ(state.tacho_limit, 0x12345678U);
}

TEST(NxtBrickRequests, EveryOtherRequestFromBytes) {
    Bytes start = {0x00, 0x00, 'a', '.', 'r', 'x', 'e'};
    start.resize(22, 0x00);
    const DecodedRequest start_request = decode_request(start);
    EXPECT_TRUE(start_request.wants_reply());
    EXPECT_EQ(body_as<StartProgram>(start_request).file_name, "a.rxe");

    EXPECT_EQ(decode_request(Bytes{0x00, 0x01}).body->index(), RequestBody(StopProgram{}).index());

    const auto mode = body_as<SetInputMode>(decode_request(Bytes{0x00, 0x05, 0x03, 0x06, 0x20}));
    EXPECT_EQ(mode.port, 3);
    EXPECT_EQ(mode.sensor_type, kSensorLightInactive);
    EXPECT_EQ(mode.sensor_mode, 0x20);

    EXPECT_EQ(body_as<GetOutputState>(decode_request(Bytes{0x00, 0x06, 0x01})).port, 1);
    EXPECT_EQ(body_as<GetInputValues>(decode_request(Bytes{0x00, 0x07, 0x02})).port, 2);

    const auto write =
        body_as<MessageWrite>(decode_request(Bytes{0x80, 0x09, 0x05, 0x03, 'h', 'i', 0x00}));
    EXPECT_EQ(write.inbox, 5);
    EXPECT_EQ(write.message, (Bytes{'h', 'i', 0x00}));  // as sent, NUL included

    const auto reset = body_as<ResetMotorPosition>(decode_request(Bytes{0x00, 0x0A, 0x02, 0x01}));
    EXPECT_EQ(reset.port, 2);
    EXPECT_TRUE(reset.relative);
    EXPECT_FALSE(
        body_as<ResetMotorPosition>(decode_request(Bytes{0x00, 0x0A, 0x02, 0x00})).relative);

    EXPECT_TRUE(std::holds_alternative<GetBatteryLevel>(*decode_request(Bytes{0x00, 0x0B}).body));
    EXPECT_TRUE(std::holds_alternative<KeepAlive>(*decode_request(Bytes{0x80, 0x0D}).body));

    const auto read = body_as<MessageRead>(decode_request(Bytes{0x00, 0x13, 0x0A, 0x01, 0x01}));
    EXPECT_EQ(read.remote_inbox, 10);
    EXPECT_EQ(read.local_inbox, 1);
    EXPECT_TRUE(read.remove);
}

TEST(NxtBrickRequests, ValuesOutOfRangeAreForTheHandlerNotTheDecoder) {
    // The firmware's handler answers these with 0xC0; the telegram itself is well formed.
    EXPECT_EQ(body_as<GetOutputState>(decode_request(Bytes{0x00, 0x06, 0x07})).port, 7);
    EXPECT_EQ(body_as<GetInputValues>(decode_request(Bytes{0x00, 0x07, 0xFF})).port, 0xFF);
    const Bytes power = {0x00, 0x04, 0x00, 0x80, 0xFF, 0x09, 0x7F, 0x33, 0, 0, 0, 0};
    const OutputState state = body_as<SetOutputState>(decode_request(power)).state;
    EXPECT_EQ(state.power, -128);
    EXPECT_EQ(state.mode, 0xFF);
    EXPECT_EQ(state.turn_ratio, 127);
    EXPECT_EQ(
        body_as<MessageRead>(decode_request(Bytes{0x00, 0x13, 0x30, 0x40, 0x00})).remote_inbox,
        0x30);
}

TEST(NxtBrickRequests, AnyNonZeroByteIsTrueAsInTheFirmware) {
    EXPECT_TRUE(
        body_as<ResetMotorPosition>(decode_request(Bytes{0x00, 0x0A, 0x00, 0x07})).relative);
    EXPECT_TRUE(body_as<MessageRead>(decode_request(Bytes{0x00, 0x13, 0x00, 0x00, 0x80})).remove);
}

TEST(NxtBrickRequests, FileNameEndsAtItsNul) {
    Bytes start = {0x00, 0x00, 'a', 'b', 0x00, 'z', 'z'};
    start.resize(22, 0x00);
    EXPECT_EQ(body_as<StartProgram>(decode_request(start)).file_name, "ab");
    Bytes full = {0x00, 0x00};
    full.resize(22, 'x');  // 20 characters and no NUL
    const DecodedRequest request = decode_request(full);
    EXPECT_EQ(request.status, status::kBadArguments);
    EXPECT_FALSE(request.body.has_value());
}

// --- Garbage and the status the firmware answers ---------------------------------------------

void expect_refused(const Bytes& telegram, std::uint8_t expected_status, bool wants_reply) {
    const DecodedRequest request = decode_request(telegram);
    EXPECT_EQ(request.status, expected_status) << hex(telegram);
    EXPECT_FALSE(request.body.has_value()) << hex(telegram);
    EXPECT_EQ(request.wants_reply(), wants_reply) << hex(telegram);
}

TEST(NxtBrickRequests, WrongLengthOfEachKnownOpcodeIsAnInsanePacket) {
    const std::vector<std::pair<std::uint8_t, std::size_t>> sizes = {
        {0x00, 22}, {0x01, 2}, {0x04, 12}, {0x05, 5}, {0x06, 3},
        {0x07, 3},  {0x0A, 4}, {0x0B, 2},  {0x0D, 2}, {0x13, 5},
    };
    for (const auto& [opcode, size] : sizes) {
        for (const std::size_t wrong : {size - 1, size + 1}) {
            if (wrong < 2) {
                continue;
            }
            Bytes telegram(wrong, 0x00);
            telegram[1] = opcode;
            expect_refused(telegram, status::kInsanePacket, true);
            EXPECT_EQ(decode_request(telegram).opcode, opcode);
        }
    }
}

TEST(NxtBrickRequests, UnknownOpcodes) {
    for (const std::uint8_t opcode :
         Bytes{0x02, 0x03, 0x08, 0x0C, 0x0E, 0x10, 0x11, 0x12, 0x14, 0xFF}) {
        expect_refused({0x00, opcode, 0x00}, status::kUnknownOpcode, true);
        expect_refused({0x80, opcode}, status::kUnknownOpcode, false);
        EXPECT_EQ(decode_request(Bytes{0x00, opcode}).opcode, opcode);
    }
}

TEST(NxtBrickRequests, SystemCommandsAreNotEmulated) {
    // GETFIRMWAREVERSION (0x88) and OPENREAD (0x80), as system commands.
    expect_refused({0x01, 0x88}, status::kUnknownOpcode, true);
    expect_refused({0x81, 0x80, 'a', 0x00}, status::kUnknownOpcode, false);
    EXPECT_EQ(decode_request(Bytes{0x01, 0x88}).type, TelegramType::SystemWithReply);
}

TEST(NxtBrickRequests, RepliesAndUnknownTypesGetNoAnswer) {
    const DecodedRequest reply = decode_request(Bytes{0x02, 0x06, 0x00, 0x01});
    EXPECT_EQ(reply.type, TelegramType::Reply);
    EXPECT_FALSE(reply.wants_reply());
    EXPECT_FALSE(reply.body.has_value());
    EXPECT_NE(reply.status, status::kOk);
    for (const std::uint8_t type : Bytes{0x03, 0x40, 0x7F, 0x82, 0xFF}) {
        expect_refused({type, 0x0D}, status::kInsanePacket, false);
    }
    expect_refused({}, status::kInsanePacket, false);
    expect_refused({0x00}, status::kInsanePacket, true);  // a type but no opcode
}

TEST(NxtBrickRequests, MessageWriteSizeMustMatch) {
    expect_refused({0x00, 0x09, 0x05, 0x03, 'h', 0x00}, status::kIllegalSize, true);  // short
    expect_refused({0x00, 0x09, 0x05, 0x01, 'h', 0x00}, status::kIllegalSize, true);  // long
    expect_refused({0x00, 0x09, 0x05, 0x00}, status::kIllegalSize, true);             // size 0
    Bytes sixty = {0x00, 0x09, 0x05, 60};
    sixty.resize(64, 'x');
    sixty.back() = 0x00;
    expect_refused(sixty, status::kIllegalSize, true);  // fits a telegram, not a mailbox
    expect_refused({0x00, 0x09, 0x05, 0x02, 'h', 'i'}, status::kInvalidField, true);  // no NUL
    expect_refused({0x00, 0x09, 0x05}, status::kInsanePacket, true);  // no size byte
    Bytes longest = {0x80, 0x09, 0x05, 59};
    longest.resize(63, 'x');
    longest.back() = 0x00;
    EXPECT_EQ(body_as<MessageWrite>(decode_request(longest)).message.size(), 59U);
}

TEST(NxtBrickRequests, RandomGarbageNeverThrowsAndBodyMeansOk) {
    // Half the inputs are random bytes of random length; the other half are valid requests
    // with a few bytes changed, so that the checks past the length are reached too.
    const std::vector<Telegram> valid = {
        encode_start_program("a.rxe", true),
        encode_stop_program(true),
        encode_set_output_state(OutputState{}, false),
        encode_set_input_mode(0, kSensorSwitch, kSensorModeRaw, true),
        encode_get_output_state(0),
        encode_get_input_values(0),
        encode_message_write(0, Bytes(10, 'x'), true),
        encode_reset_motor_position(0, true, true),
        encode_get_battery_level(),
        encode_keep_alive(true),
        encode_message_read(0, 0, true)};
    std::mt19937 random(20240611);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<std::size_t> length(0, 70);
    int decoded = 0;
    for (int i = 0; i < 20000; ++i) {
        Bytes telegram;
        if (i % 2 == 0) {
            telegram = valid[static_cast<std::size_t>(i / 2) % valid.size()];
            for (int change = i % 3; change > 0; --change) {
                telegram[static_cast<std::size_t>(byte(random)) % telegram.size()] =
                    static_cast<std::uint8_t>(byte(random));
            }
        } else {
            telegram.resize(length(random));
            for (auto& b : telegram) {
                b = static_cast<std::uint8_t>(byte(random));
            }
        }
        DecodedRequest request;
        ASSERT_NO_THROW(request = decode_request(telegram)) << hex(telegram);
        EXPECT_EQ(request.body.has_value(), request.status == status::kOk);
        if (!telegram.empty()) {
            EXPECT_EQ(static_cast<std::uint8_t>(request.type), telegram[0]);
        }
        decoded += request.body.has_value() ? 1 : 0;
    }
    EXPECT_GT(decoded, 3000);  // the inputs reached the field decoders, not only the checks
}

// --- Replies --------------------------------------------------------------------------------

OutputStateReply sample_output_state() {
    OutputStateReply reply;
    reply.state.port = 1;
    reply.state.power = -30;
    reply.state.mode = kModeMotorOn | kModeRegulated;
    reply.state.regulation = kRegulationMotorSpeed;
    reply.state.run_state = kRunStateRunning;
    reply.tacho_count = 1234;
    reply.block_tacho_count = -5;
    reply.rotation_count = -123456;
    return reply;
}

InputValues sample_input_values() {
    InputValues values;
    values.port = 3;
    values.valid = true;
    values.calibrated = false;
    values.type = kSensorSwitch;
    values.mode = kSensorModeRaw;
    values.raw = 0x3FF;
    values.normalized = 0x1234;
    values.scaled = -300;
    values.calibrated_value = 7;
    return values;
}

TEST(NxtBrickReplies, Layouts) {
    expect_bytes(encode_status_reply(0x04, status::kOk), {0x02, 0x04, 0x00});
    expect_bytes(encode_status_reply(0x42, status::kUnknownOpcode), {0x02, 0x42, 0xBE});
    expect_bytes(encode_output_state_reply(status::kOk, sample_output_state()),
                 {0x02, 0x06, 0x00, 0x01, 0xE2, 0x05, 0x01, 0x00, 0x20, 0x00, 0x00, 0x00, 0x00,
                  0xD2, 0x04, 0x00, 0x00, 0xFB, 0xFF, 0xFF, 0xFF, 0xC0, 0x1D, 0xFE, 0xFF});
    expect_bytes(encode_input_values_reply(status::kOk, sample_input_values()),
                 {0x02, 0x07, 0x00, 0x03, 0x01, 0x00, 0x01, 0x00, 0xFF, 0x03, 0x34, 0x12, 0xD4,
                  0xFE, 0x07, 0x00});
    expect_bytes(encode_battery_level_reply(status::kOk, 7250), {0x02, 0x0B, 0x00, 0x52, 0x1C});
    expect_bytes(encode_keep_alive_reply(status::kOk, 0x01020304),
                 {0x02, 0x0D, 0x00, 0x04, 0x03, 0x02, 0x01});
    Bytes read = {0x02, 0x13, 0x00, 0x0B, 0x03, 'o', 'k', 0x00};
    read.resize(64, 0x00);
    expect_bytes(encode_message_read_reply(status::kOk, {11, text_bytes(std::string("ok\0", 3))}),
                 read);
}

TEST(NxtBrickReplies, ARefusalKeepsTheLengthWithAZeroPayload) {
    const auto expect_zero_filled = [](const Bytes& reply, std::uint8_t opcode, std::size_t size) {
        Bytes expected(size, 0x00);
        expected[0] = 0x02;
        expected[1] = opcode;
        expected[2] = status::kOutOfRange;
        expect_bytes(reply, expected);
    };
    expect_zero_filled(encode_output_state_reply(status::kOutOfRange, sample_output_state()), 0x06,
                       25);
    expect_zero_filled(encode_input_values_reply(status::kOutOfRange, sample_input_values()), 0x07,
                       16);
    expect_zero_filled(encode_battery_level_reply(status::kOutOfRange, 7000), 0x0B, 5);
    expect_zero_filled(encode_keep_alive_reply(status::kOutOfRange, 60000), 0x0D, 7);
    expect_zero_filled(encode_message_read_reply(status::kOutOfRange, {3, Bytes(59, 'x')}), 0x13,
                       64);
    // A refused MESSAGEREAD needs no valid message: nothing of it is sent.
    expect_zero_filled(encode_message_read_reply(status::kOutOfRange, {3, {}}), 0x13, 64);
}

TEST(NxtBrickReplies, MessageReadReplyRefusesMessagesThatDoNotFit) {
    EXPECT_EQ(message_of<std::invalid_argument>([] {
                  encode_message_read_reply(status::kOk, {0, {}});
              }),
              "MESSAGEREAD reply: message.data has 0 bytes, expected 1..59 (NUL included)");
    EXPECT_EQ(message_of<std::invalid_argument>([] {
                  encode_message_read_reply(status::kOk, {0, Bytes(60, 'x')});
              }),
              "MESSAGEREAD reply: message.data has 60 bytes, expected 1..59 (NUL included)");
    EXPECT_EQ(encode_message_read_reply(status::kOk, {0, Bytes(59, 'x')}).size(), 64U);
}

// --- Round trips ----------------------------------------------------------------------------

TEST(NxtRoundTrip, BrickRepliesDecodeOnTheHost) {
    EXPECT_EQ(decode_output_state_reply(encode_output_state_reply(0, sample_output_state())),
              sample_output_state());
    EXPECT_EQ(decode_input_values_reply(encode_input_values_reply(0, sample_input_values())),
              sample_input_values());
    EXPECT_EQ(decode_battery_level_reply(encode_battery_level_reply(0, 65535)), 65535);
    EXPECT_EQ(decode_keep_alive_reply(encode_keep_alive_reply(0, 0xFFFFFFFF)), 0xFFFFFFFFU);
    const MailboxMessage message{19, Bytes(59, 0xAB)};
    EXPECT_EQ(decode_message_read_reply(encode_message_read_reply(0, message)), message);
    EXPECT_EQ(decode_message_read_reply(encode_message_read_reply(status::kMailboxEmpty, {})),
              std::nullopt);
    for (std::uint8_t opcode = 0; opcode < 0x14; ++opcode) {
        EXPECT_NO_THROW(
            decode_status_reply(encode_status_reply(opcode, 0), static_cast<Opcode>(opcode)));
    }
    const auto refused = caught<ReplyError>(
        [] { decode_output_state_reply(encode_output_state_reply(status::kBadPort, {})); });
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->status(), status::kBadPort);
}

TEST(NxtRoundTrip, HostRequestsDecodeOnTheBrick) {
    for (const bool reply : {true, false}) {
        const TelegramType type =
            reply ? TelegramType::DirectWithReply : TelegramType::DirectNoReply;
        const auto decoded = [&](const Telegram& telegram) {
            const DecodedRequest request = decode_request(telegram);
            EXPECT_EQ(request.type, type);
            EXPECT_EQ(request.opcode, telegram[1]);
            EXPECT_EQ(request.wants_reply(), reply);
            return request;
        };
        EXPECT_EQ(
            body_as<StartProgram>(decoded(encode_start_program("legofeup.rxe", reply))).file_name,
            "legofeup.rxe");
        EXPECT_TRUE(std::holds_alternative<StopProgram>(*decoded(encode_stop_program(reply)).body));
        OutputState state;
        state.port = kAllOutputs;
        state.power = -100;
        state.mode = kModeBrake;
        state.turn_ratio = 55;
        state.run_state = kRunStateRampDown;
        state.tacho_limit = 360;
        EXPECT_EQ(body_as<SetOutputState>(decoded(encode_set_output_state(state, reply))).state,
                  state);
        const auto mode = body_as<SetInputMode>(decoded(encode_set_input_mode(2, 9, 0xE0, reply)));
        EXPECT_EQ(mode.port, 2);
        EXPECT_EQ(mode.sensor_type, 9);
        EXPECT_EQ(mode.sensor_mode, 0xE0);
        const auto write =
            body_as<MessageWrite>(decoded(encode_message_write(7, Bytes(58, 'm'), reply)));
        EXPECT_EQ(write.inbox, 7);
        Bytes expected(58, 'm');
        expected.push_back(0x00);
        EXPECT_EQ(write.message, expected);
        const auto reset =
            body_as<ResetMotorPosition>(decoded(encode_reset_motor_position(1, reply, reply)));
        EXPECT_EQ(reset.port, 1);
        EXPECT_EQ(reset.relative, reply);
        EXPECT_TRUE(std::holds_alternative<KeepAlive>(*decoded(encode_keep_alive(reply)).body));
    }
    // The reading requests always want their reply.
    EXPECT_EQ(body_as<GetOutputState>(decode_request(encode_get_output_state(2))).port, 2);
    EXPECT_EQ(body_as<GetInputValues>(decode_request(encode_get_input_values(3))).port, 3);
    EXPECT_TRUE(decode_request(encode_get_battery_level()).wants_reply());
    const auto read = body_as<MessageRead>(decode_request(encode_message_read(10, 2, true)));
    EXPECT_EQ(read.remote_inbox, 10);
    EXPECT_EQ(read.local_inbox, 2);
    EXPECT_TRUE(read.remove);
}

}  // namespace
}  // namespace legofeup::comms::nxt
