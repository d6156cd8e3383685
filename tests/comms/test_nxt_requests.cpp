// NXT direct-command requests, host side (comms/src/nxt/telegram_requests.cpp): every
// encoder against its byte layout written out by hand from docs/nxt.md, with and without
// reply, and every field's range check with its exact message.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "nxt_test_support.hpp"

namespace legofeup::comms::nxt {
namespace {

using namespace test_support;

/// What the students' robot sends: port C (2), regulated speed, running, power −37.
OutputState regulated_port_c() {
    OutputState state;
    state.port = 2;
    state.power = -37;
    state.mode = kModeMotorOn | kModeRegulated;
    state.regulation = kRegulationMotorSpeed;
    state.turn_ratio = 0;
    state.run_state = kRunStateRunning;
    state.tacho_limit = 0;
    return state;
}

TEST(NxtRequests, StartProgramIsATwentyByteAsciizName) {
    Bytes expected = {0x00, 0x00};
    const Bytes name = text_bytes("legofeup.rxe");
    expected.insert(expected.end(), name.begin(), name.end());
    expected.resize(22, 0x00);  // NUL and padding up to the 20-byte field
    expect_bytes(encode_start_program("legofeup.rxe", true), expected);
    expected[0] = 0x80;
    expect_bytes(encode_start_program("legofeup.rxe", false), expected);
}

TEST(NxtRequests, StartProgramTakesNineteenCharactersAtMost) {
    const Bytes longest = encode_start_program("abcdefghijklmnopqrs", true);
    ASSERT_EQ(longest.size(), 22U);
    EXPECT_EQ(longest[20], 's');
    EXPECT_EQ(longest[21], 0x00);  // the NUL always fits
    EXPECT_EQ(message_of<std::invalid_argument>(
                  [] { encode_start_program("abcdefghijklmnopqrst", true); }),
              "STARTPROGRAM: file_name \"abcdefghijklmnopqrst\" has 20 characters, expected "
              "1..19 (e.g. \"legofeup.rxe\")");
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_start_program("", true); }),
              "STARTPROGRAM: file_name \"\" has 0 characters, expected 1..19 (e.g. "
              "\"legofeup.rxe\")");
    EXPECT_EQ(message_of<std::invalid_argument>(
                  [] { encode_start_program(std::string("ab\0c.rxe", 8), true); }),
              "STARTPROGRAM: file_name contains a NUL character");
}

TEST(NxtRequests, StopProgram) {
    expect_bytes(encode_stop_program(true), {0x00, 0x01});
    expect_bytes(encode_stop_program(false), {0x80, 0x01});
}

TEST(NxtRequests, SetOutputStatePortCRegulatedPowerMinus37) {
    // 80 04 | port 02 | power −37 = 0xDB | mode MOTORON|REGULATED = 05 | regulation speed 01
    // | turn ratio 00 | run state RUNNING 20 | tacho limit 0 (run forever) as u32 LE.
    expect_bytes(encode_set_output_state(regulated_port_c(), false),
                 {0x80, 0x04, 0x02, 0xDB, 0x05, 0x01, 0x00, 0x20, 0x00, 0x00, 0x00, 0x00});
}

TEST(NxtRequests, SetOutputStateEveryFieldInPlace) {
    OutputState state;
    state.port = kAllOutputs;
    state.power = 100;
    state.mode = kModeMotorOn | kModeBrake | kModeRegulated;
    state.regulation = kRegulationMotorSync;
    state.turn_ratio = -100;
    state.run_state = kRunStateRampUp;
    state.tacho_limit = 0x12345678;
    expect_bytes(encode_set_output_state(state, true),
                 {0x00, 0x04, 0xFF, 0x64, 0x07, 0x02, 0x9C, 0x10, 0x78, 0x56, 0x34, 0x12});
    state.power = -100;
    state.turn_ratio = 100;
    state.run_state = kRunStateRampDown;
    state.mode = 0;  // coast
    state.regulation = kRegulationIdle;
    expect_bytes(encode_set_output_state(state, true),
                 {0x00, 0x04, 0xFF, 0x9C, 0x00, 0x00, 0x64, 0x40, 0x78, 0x56, 0x34, 0x12});
}

TEST(NxtRequests, SetOutputStateRefusesEachFieldOutOfRange) {
    const auto refusal = [](auto change) {
        OutputState state = regulated_port_c();
        change(state);
        return message_of<std::invalid_argument>([&] { encode_set_output_state(state, true); });
    };
    // int8 can hold −128…127: the encoder must refuse both ends beyond ±100.
    for (const int power : {101, 127, -101, -128}) {
        EXPECT_EQ(refusal([&](OutputState& s) { s.power = static_cast<std::int8_t>(power); }),
                  "SETOUTPUTSTATE: power = " + std::to_string(power) + ", expected -100..100");
    }
    EXPECT_EQ(refusal([](OutputState& s) { s.port = 3; }),
              "SETOUTPUTSTATE: port = 3, expected 0..2 (A, B, C) or 255 (all)");
    EXPECT_EQ(refusal([](OutputState& s) { s.port = 0xFE; }),
              "SETOUTPUTSTATE: port = 254, expected 0..2 (A, B, C) or 255 (all)");
    EXPECT_EQ(refusal([](OutputState& s) { s.mode = 0x08; }),
              "SETOUTPUTSTATE: mode = 8, expected a combination of MOTORON 1, BRAKE 2, "
              "REGULATED 4");
    EXPECT_EQ(refusal([](OutputState& s) { s.regulation = 3; }),
              "SETOUTPUTSTATE: regulation = 3, expected 0 (idle), 1 (motor speed) or 2 (motor "
              "sync)");
    EXPECT_EQ(refusal([](OutputState& s) { s.turn_ratio = 101; }),
              "SETOUTPUTSTATE: turn_ratio = 101, expected -100..100");
    EXPECT_EQ(refusal([](OutputState& s) { s.turn_ratio = -101; }),
              "SETOUTPUTSTATE: turn_ratio = -101, expected -100..100");
    EXPECT_EQ(refusal([](OutputState& s) { s.run_state = 0x30; }),
              "SETOUTPUTSTATE: run_state = 48, expected 0 (idle), 16 (ramp up), 32 (running) "
              "or 64 (ramp down)");
}

TEST(NxtRequests, SetInputMode) {
    expect_bytes(encode_set_input_mode(0, kSensorLightInactive, kSensorModeRaw, true),
                 {0x00, 0x05, 0x00, 0x06, 0x00});
    expect_bytes(encode_set_input_mode(3, kSensorSwitch, 0x20, false),
                 {0x80, 0x05, 0x03, 0x01, 0x20});
    expect_bytes(encode_set_input_mode(1, 0x11, 0xFF, true), {0x00, 0x05, 0x01, 0x11, 0xFF});
    EXPECT_EQ(message_of<std::invalid_argument>(
                  [] { encode_set_input_mode(4, kSensorSwitch, kSensorModeRaw, true); }),
              "SETINPUTMODE: port = 4, expected 0..3 (sensor ports 1..4)");
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_set_input_mode(0, 0x12, 0, true); }),
              "SETINPUTMODE: sensor_type = 18, expected 0..17 (e.g. 1 SWITCH, 6 LIGHT_INACTIVE)");
}

TEST(NxtRequests, GetOutputStateAndGetInputValuesAlwaysWantAReply) {
    expect_bytes(encode_get_output_state(0), {0x00, 0x06, 0x00});
    expect_bytes(encode_get_output_state(2), {0x00, 0x06, 0x02});
    expect_bytes(encode_get_input_values(0), {0x00, 0x07, 0x00});
    expect_bytes(encode_get_input_values(3), {0x00, 0x07, 0x03});
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_get_output_state(3); }),
              "GETOUTPUTSTATE: port = 3, expected 0..2 (A, B, C)");
    // "All outputs" exists for SETOUTPUTSTATE only: one reply describes one motor.
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_get_output_state(kAllOutputs); }),
              "GETOUTPUTSTATE: port = 255, expected 0..2 (A, B, C)");
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_get_input_values(4); }),
              "GETINPUTVALUES: port = 4, expected 0..3 (sensor ports 1..4)");
}

TEST(NxtRequests, MessageWriteAppendsTheNulAndCountsIt) {
    const Bytes hi = text_bytes("hi");
    expect_bytes(encode_message_write(5, hi, true), {0x00, 0x09, 0x05, 0x03, 'h', 'i', 0x00});
    expect_bytes(encode_message_write(19, {}, false), {0x80, 0x09, 0x13, 0x01, 0x00});
    // Binary messages may hold zeros: the size byte, not a NUL, delimits them.
    const Bytes binary = {0x00, 0xFF, 0x00};
    expect_bytes(encode_message_write(0, binary, true),
                 {0x00, 0x09, 0x00, 0x04, 0x00, 0xFF, 0x00, 0x00});
}

TEST(NxtRequests, MessageWriteLimits) {
    const Bytes longest(58, 'x');
    const Bytes telegram = encode_message_write(1, longest, true);
    ASSERT_EQ(telegram.size(), 4U + 59U);
    EXPECT_EQ(telegram[3], 59);
    EXPECT_EQ(telegram.back(), 0x00);
    EXPECT_EQ(
        message_of<std::invalid_argument>([] { encode_message_write(1, Bytes(59, 'x'), true); }),
        "MESSAGEWRITE: message has 59 bytes, expected at most 58 (59 with its NUL)");
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_message_write(20, {}, true); }),
              "MESSAGEWRITE: inbox = 20, expected 0..19");
}

TEST(NxtRequests, ResetMotorPosition) {
    expect_bytes(encode_reset_motor_position(1, true, false), {0x80, 0x0A, 0x01, 0x01});
    expect_bytes(encode_reset_motor_position(2, false, true), {0x00, 0x0A, 0x02, 0x00});
    EXPECT_EQ(
        message_of<std::invalid_argument>([] { encode_reset_motor_position(3, false, true); }),
        "RESETMOTORPOSITION: port = 3, expected 0..2 (A, B, C)");
}

TEST(NxtRequests, BatteryLevelAndKeepAlive) {
    expect_bytes(encode_get_battery_level(), {0x00, 0x0B});
    expect_bytes(encode_keep_alive(true), {0x00, 0x0D});
    expect_bytes(encode_keep_alive(false), {0x80, 0x0D});
}

TEST(NxtRequests, MessageRead) {
    expect_bytes(encode_message_read(10, 0, true), {0x00, 0x13, 0x0A, 0x00, 0x01});
    expect_bytes(encode_message_read(19, 9, false), {0x00, 0x13, 0x13, 0x09, 0x00});
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_message_read(20, 0, true); }),
              "MESSAGEREAD: remote_inbox = 20, expected 0..19");
    EXPECT_EQ(message_of<std::invalid_argument>([] { encode_message_read(0, 20, true); }),
              "MESSAGEREAD: local_inbox = 20, expected 0..19");
}

TEST(NxtRequests, EveryRequestFitsATelegram) {
    const Bytes longest_message(58, 'x');
    for (const Telegram& telegram :
         {encode_start_program("abcdefghijklmnopqrs", true), encode_stop_program(true),
          encode_set_output_state(regulated_port_c(), true),
          encode_set_input_mode(0, kSensorSwitch, kSensorModeRaw, true), encode_get_output_state(0),
          encode_get_input_values(0), encode_message_write(0, longest_message, true),
          encode_reset_motor_position(0, true, true), encode_get_battery_level(),
          encode_keep_alive(true), encode_message_read(0, 0, true)}) {
        EXPECT_GE(telegram.size(), 2U);
        EXPECT_LE(telegram.size(), kMaxTelegramSize);
    }
}

}  // namespace
}  // namespace legofeup::comms::nxt
