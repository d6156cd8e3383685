#pragma once
// SETOUTPUTSTATE contents the emulator tests send.

#include <cstdint>

#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::testing {

/// Speed-regulated and running: the firmware aims for power × 10 °/s. Power 0 holds the
/// motor still (the host's stop).
inline comms::nxt::OutputState regulated_output(std::uint8_t port, std::int8_t power,
                                                std::uint32_t tacho_limit = 0) {
    comms::nxt::OutputState state;
    state.port = port;
    state.power = power;
    state.mode = comms::nxt::kModeMotorOn | comms::nxt::kModeRegulated;
    state.regulation = comms::nxt::kRegulationMotorSpeed;
    state.run_state = comms::nxt::kRunStateRunning;
    state.tacho_limit = tacho_limit;
    return state;
}

}  // namespace legofeup::testing
