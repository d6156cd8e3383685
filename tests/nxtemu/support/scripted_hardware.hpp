#pragma once
// Hardware for firmware tests: motors that turn exactly at the speed the firmware sets, A/D
// values the test chooses, and a clock the test steps in the firmware's 1 ms ticks.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "legofeup/comms/nxt/telegram.hpp"
#include "legofeup/nxtemu/brick_firmware.hpp"

namespace legofeup::testing {

class ScriptedHardware final : public nxtemu::BrickHardware {
  public:
    void set_motor_speeds(const std::array<double, nxtemu::kOutputCount>& wanted) override {
        speeds = wanted;
    }
    /// The NXT's tachometers: 1 count = 1°.
    std::array<double, nxtemu::kOutputCount> tacho_counts() override { return degrees; }
    std::array<std::uint16_t, nxtemu::kInputCount> adc() override { return readings; }

    std::array<double, nxtemu::kOutputCount> speeds{};
    std::array<double, nxtemu::kOutputCount> degrees{};
    std::array<std::uint16_t, nxtemu::kInputCount> readings{
        nxtemu::kOpenInputAdc, nxtemu::kOpenInputAdc, nxtemu::kOpenInputAdc, nxtemu::kOpenInputAdc};
};

/// A brick on scripted hardware, with its own clock.
class ScriptedBrick {
  public:
    explicit ScriptedBrick(nxtemu::FirmwareOptions options = {}) : firmware(hardware, options) {}

    /// Sends a request; the reply (nullopt for none).
    std::optional<comms::nxt::Telegram> send(const comms::nxt::Telegram& request) {
        return firmware.handle(request, time);
    }
    /// Sends a request that must be answered.
    comms::nxt::Telegram ask(const comms::nxt::Telegram& request) {
        std::optional<comms::nxt::Telegram> reply = send(request);
        EXPECT_TRUE(reply.has_value());
        return reply.value_or(comms::nxt::Telegram{});
    }
    /// `seconds` pass in 1 ms ticks: the motors turn, the firmware runs.
    void run(double seconds) {
        const long ticks = std::lround(seconds / kTick);
        for (long i = 0; i < ticks; ++i) {
            for (std::size_t port = 0; port < nxtemu::kOutputCount; ++port) {
                hardware.degrees.at(port) += hardware.speeds.at(port) * kTick;
            }
            time += kTick;
            firmware.advance(time);
        }
    }

    static constexpr double kTick = 0.001;
    ScriptedHardware hardware;
    nxtemu::BrickFirmware firmware;
    double time = 0.0;
};

}  // namespace legofeup::testing
