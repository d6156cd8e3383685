// The emulated relay program legofeup.rxe: a message in the format the host parses every
// 10 ms in response mailbox 10 (the newest only), and the motors stopped after 500 ms in
// which the host read nothing.

#include <gtest/gtest.h>

#include <string>

#include "legofeup/comms/nxt/relay_message.hpp"
#include "support/output_states.hpp"
#include "support/scripted_hardware.hpp"

namespace legofeup {
namespace {

namespace nxt = comms::nxt;
using testing::regulated_output;
using testing::ScriptedBrick;

constexpr std::uint8_t kRelayMailbox = 10;

/// The relay's message, read as the host reads it (and taken out); nullopt if none.
std::optional<nxt::MailboxMessage> read_relay(ScriptedBrick& brick) {
    return nxt::decode_message_read_reply(
        brick.ask(nxt::encode_message_read(kRelayMailbox, 0, true)));
}

class RelayProgram : public ::testing::Test {
  protected:
    void SetUp() override {
        brick.hardware.readings = {177, 31, 1023, 1023};
        ASSERT_EQ(brick.ask(nxt::encode_start_program("legofeup.rxe", true)).at(2),
                  nxt::status::kOk);
    }
    ScriptedBrick brick;
};

TEST_F(RelayProgram, PostsTheFormatTheHostParsesEvery10ms) {
    brick.run(0.015);
    EXPECT_FALSE(read_relay(brick));  // the sensors settle for 20 ms first
    brick.send(nxt::encode_set_output_state(regulated_output(2, 30), false));   // right wheel: C
    brick.send(nxt::encode_set_output_state(regulated_output(1, -20), false));  // left wheel: B
    brick.run(0.010);
    const auto first = read_relay(brick);
    ASSERT_TRUE(first);
    ASSERT_FALSE(first->data.empty());
    EXPECT_EQ(first->data.back(), 0);  // NUL-terminated
    EXPECT_LE(first->data.size(), 59U);
    const nxt::RelayReading reading = nxt::parse_relay_message(first->data);
    EXPECT_EQ(reading.sequence, 1U);
    EXPECT_EQ(reading.front_raw, 177);
    EXPECT_EQ(reading.rear_raw, 31);
    EXPECT_TRUE(reading.front_valid);
    EXPECT_TRUE(reading.rear_valid);
    EXPECT_EQ(reading.battery_millivolts, 7800);
    const std::string text(first->data.begin(), first->data.end() - 1);
    EXPECT_EQ(text, nxt::format_relay_message(reading));
    EXPECT_EQ(text.rfind("L1 1 ", 0), 0U) << text;

    brick.run(0.5);
    const auto later = read_relay(brick);
    ASSERT_TRUE(later);
    const nxt::RelayReading newest = nxt::parse_relay_message(later->data);
    EXPECT_EQ(newest.sequence, 51U);  // one message per 10 ms tick
    EXPECT_NEAR(newest.right_count, 300 * 0.5, 4);
    EXPECT_NEAR(newest.left_count, -200 * 0.5, 4);
    EXPECT_FALSE(read_relay(brick));  // the older ones were taken out: only the newest stays
    EXPECT_EQ(brick.firmware.counters().relay_messages, 51U);
    EXPECT_EQ(brick.firmware.counters().relay_messages_read, 2U);
}

TEST_F(RelayProgram, StopsTheWheelsWhenNothingIsReadFor500ms) {
    brick.send(nxt::encode_set_output_state(regulated_output(2, 30), false));
    brick.send(nxt::encode_set_output_state(regulated_output(1, 30), false));
    brick.run(0.005);
    for (int i = 0; i < 30; ++i) {  // a host reading every 20 ms
        brick.run(0.020);
        ASSERT_TRUE(read_relay(brick)) << i;
    }
    EXPECT_EQ(brick.hardware.speeds[2], 300.0);
    brick.run(0.480);  // silence
    EXPECT_EQ(brick.hardware.speeds[2], 300.0);
    brick.run(0.040);
    EXPECT_EQ(brick.hardware.speeds[2], 0.0);
    EXPECT_EQ(brick.hardware.speeds[1], 0.0);
    EXPECT_EQ(brick.firmware.counters().relay_safety_stops, 1U);

    // The host comes back: it reads and commands again, and the wheels turn.
    ASSERT_TRUE(read_relay(brick));
    brick.run(0.010);
    brick.send(nxt::encode_set_output_state(regulated_output(2, 30), false));
    brick.run(0.010);
    EXPECT_EQ(brick.hardware.speeds[2], 300.0);
    EXPECT_EQ(brick.firmware.counters().relay_safety_stops, 1U);
}

TEST_F(RelayProgram, StopProgramEndsTheMessagesAndCoastsTheMotors) {
    brick.send(nxt::encode_set_output_state(regulated_output(2, 30), false));
    brick.run(0.1);
    ASSERT_TRUE(read_relay(brick));
    brick.ask(nxt::encode_stop_program(true));
    EXPECT_EQ(brick.hardware.speeds[2], 0.0);
    EXPECT_EQ(brick.firmware.output(2).rotation_count, 0);
    brick.run(0.1);
    EXPECT_EQ(brick.ask(nxt::encode_message_read(kRelayMailbox, 0, true)).at(2),
              nxt::status::kNoActiveProgram);
}

TEST_F(RelayProgram, CountsMayBeNegativeAndTheMessageStaysShort) {
    brick.hardware.degrees[2] = -2'000'000'000.0;  // an extreme position, for the length
    brick.run(0.03);
    const auto message = read_relay(brick);
    ASSERT_TRUE(message);
    const nxt::RelayReading reading = nxt::parse_relay_message(message->data);
    EXPECT_LT(reading.right_count, 0);
    EXPECT_LE(message->data.size(), 59U);
}

}  // namespace
}  // namespace legofeup
