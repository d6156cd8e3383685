// The emulated firmware answers every direct command as the LEGO firmware's sources do:
// status codes, bad ports, no-reply silence, counters, tacho limits, sensor timing, programs
// and mailboxes.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "legofeup/comms/nxt/nxt_link.hpp"
#include "support/output_states.hpp"
#include "support/scripted_hardware.hpp"

namespace legofeup {
namespace {

namespace nxt = comms::nxt;
namespace status = nxt::status;
using testing::regulated_output;
using testing::ScriptedBrick;

nxt::OutputState unregulated(std::uint8_t port, std::int8_t power) {
    nxt::OutputState state = regulated_output(port, power);
    state.mode = nxt::kModeMotorOn;
    state.regulation = nxt::kRegulationIdle;
    return state;
}

/// The status byte of a reply.
std::uint8_t status_of(const nxt::Telegram& reply) {
    return reply.at(2);
}

/// Everything after type, opcode and status is zero.
bool zero_payload(const nxt::Telegram& reply) {
    return std::all_of(reply.begin() + 3, reply.end(), [](std::uint8_t b) { return b == 0; });
}

std::vector<std::uint8_t> text_message(const std::string& text) {
    return {text.begin(), text.end()};
}

TEST(BrickFirmware, KeepAliveAndBatteryAnswerTheConfiguredValues) {
    nxtemu::FirmwareOptions options;
    options.battery_millivolts = 7123;
    options.sleep_limit_ms = 120'000;
    ScriptedBrick brick(options);
    EXPECT_EQ(nxt::decode_keep_alive_reply(brick.ask(nxt::encode_keep_alive(true))), 120'000U);
    EXPECT_EQ(nxt::decode_battery_level_reply(brick.ask(nxt::encode_get_battery_level())), 7123);
}

TEST(BrickFirmware, DefaultsAreTheFirmwaresAndTheHostsWiring) {
    const nxtemu::FirmwareOptions options;
    EXPECT_EQ(options.sleep_limit_ms, 600'000U);  // 10 minutes
    const nxtemu::BrickWiring brick;
    const nxt::NxtWiring host;
    EXPECT_EQ(brick.right_motor, host.right_motor);
    EXPECT_EQ(brick.left_motor, host.left_motor);
    EXPECT_EQ(brick.front_ir, host.front_ir);
    EXPECT_EQ(brick.rear_ir, host.rear_ir);
    EXPECT_EQ(brick.reversed_motors, host.reversed_motors);
}

TEST(BrickFirmware, NoReplyCommandsProduceNothingEvenOnError) {
    ScriptedBrick brick;
    EXPECT_FALSE(brick.send(nxt::encode_keep_alive(false)));
    EXPECT_FALSE(brick.send(nxt::encode_set_output_state(regulated_output(0, 30), false)));
    EXPECT_EQ(brick.hardware.speeds[0], 300.0);  // it was carried out all the same
    EXPECT_FALSE(brick.send({0x80, 0x04, 0x07, 30, 5, 1, 0, 0x20, 0, 0, 0, 0}));  // port 7
    EXPECT_FALSE(brick.send({0x80, 0x55}));                                       // unknown
    EXPECT_FALSE(brick.send({0x80, 0x01}));                                       // STOP: none
    EXPECT_FALSE(brick.send({0x02, 0x0B, 0x00, 0x10, 0x1E}));                     // a reply
    EXPECT_EQ(brick.firmware.counters().no_reply, 6U);
    EXPECT_EQ(brick.firmware.counters().error_statuses, 4U);
}

TEST(BrickFirmware, BadPortsAreOutOfRangeWithAZeroPayloadOfFullLength) {
    ScriptedBrick brick;
    const nxt::Telegram output = brick.ask({0x00, 0x06, 0x03});  // GETOUTPUTSTATE port 3
    EXPECT_EQ(output.size(), 25U);
    EXPECT_EQ(status_of(output), status::kOutOfRange);
    EXPECT_TRUE(zero_payload(output));
    const nxt::Telegram input = brick.ask({0x00, 0x07, 0x04});  // GETINPUTVALUES port 4
    EXPECT_EQ(input.size(), 16U);
    EXPECT_EQ(status_of(input), status::kOutOfRange);
    EXPECT_TRUE(zero_payload(input));
    try {
        nxt::decode_output_state_reply(output);
        ADD_FAILURE() << "a refused GETOUTPUTSTATE decoded";
    } catch (const nxt::ReplyError& error) {
        EXPECT_EQ(error.status(), status::kOutOfRange);
    }
    // SETOUTPUTSTATE port 3, SETINPUTMODE port 4, RESETMOTORPOSITION port 3.
    for (const nxt::Telegram& request :
         {nxt::Telegram{0x00, 0x04, 0x03, 30, 5, 1, 0, 0x20, 0, 0, 0, 0},
          nxt::Telegram{0x00, 0x05, 0x04, 0x06, 0x00}, nxt::Telegram{0x00, 0x0A, 0x03, 0x00}}) {
        const nxt::Telegram reply = brick.ask(request);
        EXPECT_EQ(reply.size(), 3U);
        EXPECT_EQ(reply.at(1), request.at(1));
        EXPECT_EQ(status_of(reply), status::kOutOfRange);
    }
    EXPECT_EQ(brick.hardware.speeds, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

TEST(BrickFirmware, UnknownOpcodesAndWrongLengthsAreRefused) {
    ScriptedBrick brick;
    EXPECT_EQ(brick.ask({0x00, 0x55}), (nxt::Telegram{0x02, 0x55, status::kUnknownOpcode}));
    const nxt::Telegram battery = brick.ask({0x00, 0x0B, 0x00});  // one byte too many
    EXPECT_EQ(battery.size(), 5U);
    EXPECT_EQ(status_of(battery), status::kInsanePacket);
    EXPECT_TRUE(zero_payload(battery));
    EXPECT_EQ(status_of(brick.ask({0x01, 0x88})), status::kUnknownOpcode);  // a system command
}

TEST(BrickFirmware, AllPortsAtOnceAndTheMotorModels) {
    ScriptedBrick brick;  // 7.8 V: full power is 1020 °/s × 7.8 / 9 = 884 °/s
    nxt::decode_status_reply(
        brick.ask(nxt::encode_set_output_state(regulated_output(nxt::kAllOutputs, 26), true)),
        nxt::Opcode::SetOutputState);
    EXPECT_EQ(brick.hardware.speeds, (std::array<double, 3>{260.0, 260.0, 260.0}));
    brick.send(nxt::encode_set_output_state(regulated_output(0, 100), false));
    EXPECT_NEAR(brick.hardware.speeds[0], 884.0, 0.1);  // regulation cannot beat the battery
    brick.send(nxt::encode_set_output_state(unregulated(1, -50), false));
    EXPECT_NEAR(brick.hardware.speeds[1], -442.0, 0.1);  // PWM duty cycle
    nxt::OutputState brake = regulated_output(2, 40);
    brake.mode = nxt::kModeBrake;  // no MOTORON: stopped
    brick.send(nxt::encode_set_output_state(brake, false));
    EXPECT_EQ(brick.hardware.speeds[2], 0.0);
    EXPECT_EQ(brick.firmware.output(2).state.run_state, nxt::kRunStateIdle);
}

TEST(BrickFirmware, CountersCountDegreesAndResetAsTheFirmwareDoes) {
    ScriptedBrick brick;
    brick.send(nxt::encode_set_output_state(regulated_output(2, 26), false));
    brick.run(1.0);
    nxt::OutputStateReply reply =
        nxt::decode_output_state_reply(brick.ask(nxt::encode_get_output_state(2)));
    EXPECT_EQ(reply.state, regulated_output(2, 26));
    EXPECT_NEAR(reply.rotation_count, 260, 1);
    EXPECT_EQ(reply.tacho_count, reply.rotation_count);
    EXPECT_EQ(reply.block_tacho_count, reply.rotation_count);

    brick.ask(nxt::encode_reset_motor_position(2, false, true));  // relative 0: RotationCount
    reply = brick.firmware.output(2);
    EXPECT_EQ(reply.rotation_count, 0);
    EXPECT_NEAR(reply.block_tacho_count, 260, 1);
    brick.ask(nxt::encode_reset_motor_position(2, true, true));  // relative 1: BlockTachoCount
    EXPECT_EQ(brick.firmware.output(2).block_tacho_count, 0);

    // A new SETOUTPUTSTATE leaves TachoCount alone (the firmware resets it only when a
    // program starts or stops); backwards, every counter goes down.
    brick.send(nxt::encode_set_output_state(regulated_output(2, -26), false));
    brick.run(0.5);
    reply = brick.firmware.output(2);
    EXPECT_NEAR(reply.tacho_count, 130, 1);
    EXPECT_NEAR(reply.rotation_count, -130, 1);
    EXPECT_NEAR(reply.block_tacho_count, -130, 1);
}

TEST(BrickFirmware, AReachedTachoLimitIdlesTheMotorAndTheTargetAccumulates) {
    ScriptedBrick brick;
    brick.send(nxt::encode_set_output_state(regulated_output(0, 50, 90), false));
    brick.run(0.1);
    EXPECT_EQ(brick.firmware.output(0).state.run_state, nxt::kRunStateRunning);
    brick.run(0.2);  // 500 °/s: 90° after 0.18 s
    nxt::OutputStateReply reply = brick.firmware.output(0);
    EXPECT_EQ(reply.state.run_state, nxt::kRunStateIdle);
    EXPECT_EQ(reply.state.tacho_limit, 90U);
    EXPECT_GE(reply.tacho_count, 90);
    EXPECT_LE(reply.tacho_count, 91);
    EXPECT_EQ(brick.hardware.speeds[0], 0.0);  // coasting

    // The same command again: the target grows by another 90 from the last one.
    brick.send(nxt::encode_set_output_state(regulated_output(0, 50, 90), false));
    brick.run(0.5);
    reply = brick.firmware.output(0);
    EXPECT_EQ(reply.state.run_state, nxt::kRunStateIdle);
    EXPECT_GE(reply.tacho_count, 180);
    EXPECT_LE(reply.tacho_count, 181);

    brick.send(nxt::encode_set_output_state(regulated_output(0, -50, 45), false));  // backwards
    brick.run(0.5);
    EXPECT_LE(brick.firmware.output(0).tacho_count, 135);
    EXPECT_GE(brick.firmware.output(0).tacho_count, 134);
}

TEST(BrickFirmware, InputsAreInvalidFor20msAfterATypeChange) {
    ScriptedBrick brick;
    brick.hardware.readings = {345, 456, 1023, 1023};
    brick.ask(nxt::encode_set_input_mode(0, nxt::kSensorLightInactive, nxt::kSensorModeRaw, true));
    brick.run(0.019);
    nxt::InputValues values =
        nxt::decode_input_values_reply(brick.ask(nxt::encode_get_input_values(0)));
    EXPECT_FALSE(values.valid);
    EXPECT_EQ(values.raw, 0);  // not refreshed while invalid
    EXPECT_EQ(values.type, nxt::kSensorLightInactive);
    brick.run(0.002);
    values = nxt::decode_input_values_reply(brick.ask(nxt::encode_get_input_values(0)));
    EXPECT_TRUE(values.valid);
    EXPECT_EQ(values.raw, 345);
    EXPECT_FALSE(values.calibrated);
    EXPECT_EQ(values.normalized, 1023 - (345 - 200) * 100 / 68);  // the light sensor's span
    EXPECT_EQ(values.scaled, values.normalized);                  // raw mode

    // The same type again: one 1 ms tick of the input module, not 20.
    brick.ask(nxt::encode_set_input_mode(0, nxt::kSensorLightInactive, nxt::kSensorModeRaw, true));
    EXPECT_FALSE(brick.firmware.input(0).valid);
    brick.run(0.002);
    EXPECT_TRUE(brick.firmware.input(0).valid);

    // SWITCH reads the A/D unchanged; a port with nothing attached reads full scale.
    brick.ask(nxt::encode_set_input_mode(3, nxt::kSensorSwitch, nxt::kSensorModeRaw, true));
    brick.run(0.03);
    values = brick.firmware.input(3);
    EXPECT_EQ(values.raw, 1023);
    EXPECT_EQ(values.normalized, 1023);
}

TEST(BrickFirmware, NoSensorKeepsTheLastRawValue) {
    ScriptedBrick brick;
    brick.hardware.readings[1] = 300;
    brick.ask(nxt::encode_set_input_mode(1, nxt::kSensorSwitch, nxt::kSensorModeRaw, true));
    brick.run(0.03);
    EXPECT_EQ(brick.firmware.input(1).raw, 300);
    brick.ask(nxt::encode_set_input_mode(1, nxt::kSensorNone, nxt::kSensorModeRaw, true));
    brick.hardware.readings[1] = 600;
    brick.run(0.05);
    const nxt::InputValues values = brick.firmware.input(1);
    EXPECT_TRUE(values.valid);
    EXPECT_EQ(values.raw, 300);  // stale
}

TEST(BrickFirmware, ProgramsAnswerTheFirmwaresStatusCodes) {
    ScriptedBrick brick;
    const auto status_for = [&](const nxt::Telegram& request) {
        return status_of(brick.ask(request));
    };
    EXPECT_EQ(status_for(nxt::encode_start_program("other.rxe", true)), status::kOutOfRange);
    EXPECT_EQ(status_for(nxt::encode_stop_program(true)), status::kNoActiveProgram);
    EXPECT_EQ(status_for(nxt::encode_message_read(10, 0, true)), status::kNoActiveProgram);
    EXPECT_EQ(status_for(nxt::encode_message_write(0, text_message("hi"), true)),
              status::kNoActiveProgram);
    EXPECT_FALSE(brick.firmware.running_program());

    EXPECT_EQ(status_for(nxt::encode_start_program("legofeup.rxe", true)), status::kOk);
    EXPECT_EQ(brick.firmware.running_program(), "legofeup.rxe");
    EXPECT_EQ(status_for(nxt::encode_stop_program(true)), status::kOk);
    EXPECT_EQ(status_for(nxt::encode_stop_program(true)), status::kNoActiveProgram);
    EXPECT_EQ(brick.firmware.counters().programs_started, 1U);

    nxtemu::FirmwareOptions without_relay;
    without_relay.relay_installed = false;
    ScriptedBrick bare(without_relay);
    EXPECT_EQ(status_of(bare.ask(nxt::encode_start_program("legofeup.rxe", true))),
              status::kOutOfRange);
}

TEST(BrickFirmware, StartingAProgramResetsTheDevices) {
    ScriptedBrick brick;
    brick.send(nxt::encode_set_output_state(regulated_output(1, 40), false));
    brick.send(nxt::encode_set_input_mode(3, nxt::kSensorSwitch, nxt::kSensorModeRaw, false));
    brick.run(0.5);
    ASSERT_GT(brick.firmware.output(1).rotation_count, 100);
    brick.ask(nxt::encode_start_program("legofeup.rxe", true));
    const nxt::OutputStateReply motor = brick.firmware.output(1);
    EXPECT_EQ(motor.state, nxt::OutputState{.port = 1});
    EXPECT_EQ(motor.tacho_count, 0);
    EXPECT_EQ(motor.rotation_count, 0);
    EXPECT_EQ(brick.hardware.speeds[1], 0.0);
    EXPECT_EQ(brick.firmware.input(3).type, nxt::kSensorNone);
    EXPECT_EQ(brick.firmware.input(3).raw, 0);
    // The relay program set its own ports.
    EXPECT_EQ(brick.firmware.input(0).type, nxt::kSensorLightInactive);
    EXPECT_EQ(brick.firmware.input(1).type, nxt::kSensorLightInactive);
}

TEST(BrickFirmware, MailboxesQueueFiveMessagesAndDropTheOldest) {
    ScriptedBrick brick;
    brick.ask(nxt::encode_start_program("legofeup.rxe", true));
    for (int i = 1; i <= 6; ++i) {
        brick.ask(nxt::encode_message_write(3, text_message("message " + std::to_string(i)), true));
    }
    // A peek leaves the message where it is; the local inbox is echoed.
    auto peeked = nxt::decode_message_read_reply(brick.ask(nxt::encode_message_read(3, 7, false)));
    ASSERT_TRUE(peeked);
    EXPECT_EQ(peeked->local_inbox, 7);
    EXPECT_EQ(peeked->data, text_message(std::string("message 2") + '\0'));
    for (int i = 2; i <= 6; ++i) {
        const auto message =
            nxt::decode_message_read_reply(brick.ask(nxt::encode_message_read(3, 0, true)));
        ASSERT_TRUE(message) << i;
        EXPECT_EQ(message->data, text_message("message " + std::to_string(i) + '\0'));
    }
    const nxt::Telegram empty = brick.ask(nxt::encode_message_read(3, 0, true));
    EXPECT_EQ(status_of(empty), status::kMailboxEmpty);
    EXPECT_EQ(empty.size(), 64U);
    EXPECT_FALSE(nxt::decode_message_read_reply(empty));

    EXPECT_EQ(status_of(brick.ask({0x00, 0x13, 20, 0, 1})), status::kIllegalMailbox);
    EXPECT_EQ(status_of(brick.ask({0x00, 0x09, 20, 2, 'x', 0})), status::kIllegalMailbox);
}

}  // namespace
}  // namespace legofeup
