#pragma once
// The relay program legofeup.rxe (resources/nxt/legofeup_relay.nxc) as the emulated brick
// runs it: every 10 ms it posts the wheel motors' RotationCount, the IR ports' A/D values,
// their valid flags and the battery voltage as one message in response mailbox 10 (the
// format of comms/nxt/relay_message.hpp), after taking out the previous message if the host
// has not read it (the host wants the freshest). When no message has been taken for 500 ms,
// it stops both wheel motors (and keeps them stopped while the host stays silent). Private to
// nxtemu.

#include <cstdint>

#include "input_ports.hpp"
#include "legofeup/nxtemu/brick_firmware.hpp"
#include "mailboxes.hpp"
#include "output_ports.hpp"

namespace legofeup::nxtemu {

/// The brick's devices, as a program sees them.
struct ProgramDevices {
    InputPorts& inputs;
    OutputPorts& outputs;
    Mailboxes& mailboxes;
    const FirmwareOptions& options;
    FirmwareCounters& counters;
};

class RelayProgram {
  public:
    static constexpr double kPeriod = 0.010;              ///< s between messages
    static constexpr double kSensorSettle = 0.020;        ///< ResetSensor waits for valid data
    static constexpr double kSilenceStop = 0.500;         ///< s without a read before it stops
    static constexpr std::uint8_t kResponseMailbox = 10;  ///< MAILBOX1 + 10

    /// The program starts at `now` (the devices were just reset): it sets both IR ports to
    /// LIGHT_INACTIVE in raw mode and posts its first message once they are valid.
    void start(double now, ProgramDevices& devices);
    void stop() { running_ = false; }
    bool running() const { return running_; }

    /// Runs the program's ticks due by `now`. A tick missed by more than a period (the caller
    /// was late) is skipped, as a program waking late from Wait() would.
    void run_until(double now, ProgramDevices& devices);

  private:
    void tick(double time, ProgramDevices& devices);

    bool running_ = false;
    double next_tick_ = 0.0;
    double last_read_ = 0.0;  ///< the last tick that found the previous message taken
    bool motors_stopped_ = false;
    std::uint32_t sequence_ = 0;
};

}  // namespace legofeup::nxtemu
