#pragma once
// What the emulated brick's firmware drives and reads: three motors with tachometers and four
// analog input ports. The simulator stands behind it (simulated_hardware.hpp); tests use a
// scripted one. The firmware (brick_firmware.hpp) turns its output states into motor speeds
// and reads the tachometers and the A/D values; the hardware knows nothing of the protocol.

#include <array>
#include <cstddef>
#include <cstdint>

namespace legofeup::nxtemu {

inline constexpr std::size_t kOutputCount = 3;  ///< ports A, B, C = 0, 1, 2
inline constexpr std::size_t kInputCount = 4;   ///< ports 1–4 = 0–3
/// An input port with nothing plugged in: pin 1's pull-up reads full scale.
inline constexpr std::uint16_t kOpenInputAdc = 1023;

/// Which ports the robot uses. The defaults are those of the host's comms::nxt::NxtWiring
/// (tests/nxtemu checks they agree): right wheel on C, left wheel on B, the front IR sensor on
/// port 1 and the rear one on port 2.
struct BrickWiring {
    std::uint8_t right_motor = 2;  ///< output port of wheel 1 (right)
    std::uint8_t left_motor = 1;   ///< output port of wheel 2 (left)
    std::uint8_t front_ir = 0;     ///< input port of IR sensor 1 (front)
    std::uint8_t rear_ir = 1;      ///< input port of IR sensor 2 (rear)
    /// The motors are mounted so that positive power drives the robot backwards.
    bool reversed_motors = false;
};

class BrickHardware {
  public:
    virtual ~BrickHardware() = default;

    /// The speed each output's motor is to turn at from now on, degrees per second
    /// (positive: the direction positive power turns it). The firmware calls this whenever
    /// an output changes; 0 stops the motor.
    virtual void set_motor_speeds(const std::array<double, kOutputCount>& degrees_per_second) = 0;
    /// Each motor's tachometer since the hardware started, in its counts (cumulative, not
    /// yet rounded): the NXT's counts 360 a turn, 1 count = 1°; an emulated robot's counts
    /// its configured robot.counts_per_turn. The firmware's counters move by its whole counts.
    virtual std::array<double, kOutputCount> tacho_counts() = 0;
    /// The A/D value (0–1023) of pin 1 of each input port now; kOpenInputAdc for a port
    /// with nothing attached.
    virtual std::array<std::uint16_t, kInputCount> adc() = 0;
};

}  // namespace legofeup::nxtemu
