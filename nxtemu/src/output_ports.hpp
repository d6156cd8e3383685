#pragma once
// The three motor outputs as the firmware's output module keeps them (c_output / d_output in
// the firmware sources): the state last set by SETOUTPUTSTATE, the motor driver's run state,
// and the three tacho counters fed by the tachometer. Private to nxtemu.

#include <array>
#include <cstdint>

#include "legofeup/comms/nxt/telegram.hpp"
#include "legofeup/nxtemu/brick_hardware.hpp"

namespace legofeup::nxtemu {

/// How the motors turn power into speed.
struct MotorModel {
    double max_degrees_per_second = 1020.0;  ///< no load, 9 V
    double battery_volts = 7.8;
    /// Speed regulation aims for this many °/s per unit of power (the firmware's PID counts
    /// power × MAX_CAPTURE_COUNT (100) / 100 counts per 100 ms regulation period).
    static constexpr double kRegulatedDegreesPerPower = 10.0;
    static constexpr double kNominalVolts = 9.0;
};

class OutputPorts {
  public:
    explicit OutputPorts(MotorModel model) : model_(model) {}

    /// SETOUTPUTSTATE for one port (< kOutputCount): as the firmware applies it — speed
    /// and run state, then mode and regulation, then the tacho limit (added to the target).
    void set(std::uint8_t port, const comms::nxt::OutputState& state);
    /// RESETMOTORPOSITION: relative = false zeroes RotationCount, true BlockTachoCount.
    void reset_position(std::uint8_t port, bool relative);
    /// A program starts or stops: every motor coasts, every counter and target is 0.
    void reset_all();

    /// The tachometers now read `counts` (cumulative, BrickHardware::tacho_counts): the
    /// counters move by the whole counts since the last update; then tacho limits are applied.
    void update(const std::array<double, kOutputCount>& counts);

    comms::nxt::OutputStateReply reply(std::uint8_t port) const;
    /// What each motor's driver does now, °/s.
    std::array<double, kOutputCount> speeds() const;

  private:
    struct Port {
        comms::nxt::OutputState set;  ///< as last set (power, mode, regulation, limit, ...)
        std::uint8_t run_state = comms::nxt::kRunStateIdle;  ///< the driver's
        std::int8_t power = 0;                               ///< the driver's set speed
        bool regulated = false;   ///< speed regulation (MOTORON | REGULATED, MOTOR_SPEED)
        bool run_forever = true;  ///< tacho limit 0
        std::int64_t target = 0;  ///< MotorTachoCountToRun: where a tacho limit stops
        std::int32_t tacho_count = 0;
        std::int32_t block_tacho_count = 0;
        std::int32_t rotation_count = 0;
    };

    double speed(const Port& port) const;
    static bool moving(const Port& port);
    void apply_tacho_limit(Port& port) const;

    MotorModel model_;
    std::array<Port, kOutputCount> ports_{};
    std::array<std::int64_t, kOutputCount> last_whole_counts_{};
    bool have_counts_ = false;
};

}  // namespace legofeup::nxtemu
