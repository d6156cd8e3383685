// The emulated brick on the simulated robot: regulated power moves the robot as the firmware's
// speed regulation would, the tachometers count at the robot's encoder resolution, the IR
// ports read the simulator's A/D values, and the whole brick answers over TCP.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <numbers>
#include <thread>

#include "legofeup/comms/nxt/framing.hpp"
#include "legofeup/comms/nxt/relay_message.hpp"
#include "legofeup/comms/nxt/transport.hpp"
#include "legofeup/comms/truth_receiver.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/nxtemu/emulated_nxt.hpp"
#include "legofeup/nxtemu/simulated_hardware.hpp"
#include "support/output_states.hpp"

namespace legofeup {
namespace {

namespace nxt = comms::nxt;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

/// The firmware on the simulated robot, advanced on every simulator frame.
class SimulatedBrick {
  public:
    explicit SimulatedBrick(const lessons::RunConfig& config = {})
        : run_(nxtemu::resolve_emulated_run(config)),
          hardware_(run_, nxtemu::BrickWiring{},
                    [this] {
                        const std::lock_guard lock(mutex_);
                        if (firmware_) {
                            firmware_->advance(seconds());
                        }
                    }),
          truth_(hardware_.truth_endpoint()) {
        const std::lock_guard lock(mutex_);
        firmware_.emplace(hardware_);
    }

    std::optional<nxt::Telegram> send(const nxt::Telegram& request) {
        const std::lock_guard lock(mutex_);
        return firmware_->handle(request, seconds());
    }

    /// The newest ground truth.
    GroundTruth truth() {
        truth_.poll(200ms);
        const auto deadline = Clock::now() + 2s;
        while (!truth_.latest() && Clock::now() < deadline) {
            truth_.poll(50ms);
        }
        EXPECT_TRUE(truth_.latest().has_value());
        return truth_.latest().value_or(GroundTruth{});
    }

    const lessons::ResolvedRun& run() const { return run_; }
    nxtemu::SimulatedHardware& hardware() { return hardware_; }

  private:
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    Clock::time_point start_ = Clock::now();
    lessons::ResolvedRun run_;
    // Before the hardware: its pump calls back into them from its first frame on.
    std::mutex mutex_;
    std::optional<nxtemu::BrickFirmware> firmware_;
    nxtemu::SimulatedHardware hardware_;
    comms::TruthReceiver truth_;
};

nxt::Telegram regulated_both(std::int8_t power) {
    return nxt::encode_set_output_state(testing::regulated_output(nxt::kAllOutputs, power), false);
}

TEST(SimulatedHardware, RegulatedPower26DrivesTheRobotAt10DegreesPerSecondPerUnit) {
    SimulatedBrick brick;
    std::this_thread::sleep_for(100ms);
    const GroundTruth before = brick.truth();
    brick.send(regulated_both(26));
    std::this_thread::sleep_for(2s);
    brick.send(regulated_both(0));
    const auto counts =
        nxt::decode_output_state_reply(*brick.send(nxt::encode_get_output_state(2)));
    std::this_thread::sleep_for(200ms);  // the wheels spin down
    const GroundTruth after = brick.truth();

    // 26 × 10 °/s on 43.2 mm wheels: 0.098 m/s, so 0.196 m in 2 s (less the motors' 50 ms lag).
    const double wheel_speed = 260.0 * std::numbers::pi / 180.0 * 0.5 * 0.0432;
    const double dx = after.pose.x - before.pose.x;
    const double dy = after.pose.y - before.pose.y;
    const double along = dx * std::cos(before.pose.theta) + dy * std::sin(before.pose.theta);
    std::printf("power 26 for 2 s: %.3f m forward (%.3f m expected), RotationCount %d\n", along,
                wheel_speed * 2.0, counts.rotation_count);
    EXPECT_NEAR(along, wheel_speed * 2.0, 0.035);
    EXPECT_NEAR(std::hypot(dx, dy), std::abs(along), 0.01);  // straight
    EXPECT_NEAR(counts.rotation_count, 520, 40);
    EXPECT_GT(brick.hardware().frames(), 150U);  // a frame every 10 ms
}

// A robot whose encoders count 180 or 720 a turn: power 26 for 2 s turns every motor the same
// 520° as on the NXT's 360-count tachometer (the test above), and each of the three counters
// reads 520° · counts_per_turn / 360 — the wheels' (B, C) from the simulator's encoders, the
// free motor's (A) from its speed. Degrees would read 520 for either.
class EncoderResolution : public ::testing::TestWithParam<double> {};

TEST_P(EncoderResolution, RotationCountsCountTheRobotsCountsPerTurn) {
    lessons::RunConfig config;
    config.robot.counts_per_turn = GetParam();
    SimulatedBrick brick(config);
    std::this_thread::sleep_for(100ms);
    brick.send(regulated_both(26));
    std::this_thread::sleep_for(2s);
    brick.send(regulated_both(0));
    const double scale = GetParam() / 360.0;
    for (const std::uint8_t port : {std::uint8_t{0}, std::uint8_t{1}, std::uint8_t{2}}) {
        const auto counts =
            nxt::decode_output_state_reply(*brick.send(nxt::encode_get_output_state(port)));
        EXPECT_NEAR(counts.rotation_count, 520.0 * scale, 40.0 * scale) << "port " << int{port};
    }
}

INSTANTIATE_TEST_SUITE_P(CountsPerTurn, EncoderResolution, ::testing::Values(180.0, 720.0));

TEST(SimulatedHardware, IrPortsReadTheSimulatorsAdcValues) {
    SimulatedBrick brick;
    for (const std::uint8_t port : std::initializer_list<std::uint8_t>{0, 1, 2}) {
        brick.send(nxt::encode_set_input_mode(port, nxt::kSensorLightInactive, nxt::kSensorModeRaw,
                                              false));
    }
    std::this_thread::sleep_for(150ms);
    const GroundTruth truth = brick.truth();  // the robot stands still: no noise by default
    const SharpIrCurve& curve = brick.run().robot.ir_curve;
    for (const std::uint8_t port : std::initializer_list<std::uint8_t>{0, 1}) {
        const nxt::InputValues values =
            nxt::decode_input_values_reply(*brick.send(nxt::encode_get_input_values(port)));
        EXPECT_TRUE(values.valid);
        const std::uint16_t expected =
            quantize_adc(adc_from_distance(truth.ir_distances.at(port), curve), curve.adc_max);
        EXPECT_NEAR(values.raw, expected, 1) << "port " << int{port};
    }
    EXPECT_EQ(nxt::decode_input_values_reply(*brick.send(nxt::encode_get_input_values(2))).raw,
              nxtemu::kOpenInputAdc);  // nothing attached
}

TEST(EmulatedNxt, ServesTheSimulatedRobotOverTcpWithTheRelayProgram) {
    nxtemu::EmulatorOptions options;
    options.link.latency_up = 5ms;
    options.link.latency_down = 5ms;
    nxtemu::EmulatedNxt brick(options);
    const std::uint16_t port = brick.serve_tcp();
    const auto stream = nxt::open_transport({nxt::TransportKind::Tcp, "127.0.0.1", port}, 2000ms);
    const auto ask = [&](const nxt::Telegram& request) {
        nxt::write_telegram(*stream, request);
        return nxt::read_telegram(*stream, Clock::now() + 2s);
    };
    EXPECT_EQ(nxt::decode_keep_alive_reply(ask(nxt::encode_keep_alive(true))), 600'000U);
    nxt::decode_status_reply(ask(nxt::encode_start_program("legofeup.rxe", true)),
                             nxt::Opcode::StartProgram);
    std::this_thread::sleep_for(100ms);
    const auto message = nxt::decode_message_read_reply(ask(nxt::encode_message_read(10, 0, true)));
    ASSERT_TRUE(message);
    const nxt::RelayReading reading = nxt::parse_relay_message(message->data);
    EXPECT_GE(reading.sequence, 3U);
    EXPECT_TRUE(reading.front_valid && reading.rear_valid);
    EXPECT_NE(brick.truth_endpoint().port, 0);
    stream->close();
    std::this_thread::sleep_for(50ms);
    brick.stop();
    const nxtemu::EmulatorCounters counters = brick.counters();
    EXPECT_EQ(counters.link.telegrams_in, 3U);
    EXPECT_EQ(counters.firmware.relay_messages_read, 1U);
    EXPECT_GT(counters.simulator_frames, 5U);
}

}  // namespace
}  // namespace legofeup
