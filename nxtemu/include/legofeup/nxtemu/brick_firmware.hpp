#pragma once
// The standard LEGO firmware (1.29) as the host sees it over Bluetooth: direct commands in,
// replies out, with the firmware's status codes, its counters, its sensor timing, its
// mailboxes, and the relay program legofeup.rxe (resources/nxt/legofeup_relay.nxc) as the
// one program "installed" on the brick. Pure logic: no threads, no sockets, no clock of its
// own — the caller passes the time, so the tests step it by hand. Not thread-safe.
//
// What it does, as the firmware sources do (docs/nxt-emulator.md has the whole list):
//  - a reply keeps its length whatever the status; a bad port is 0xC0 with zeros;
//  - a command sent "no reply" (0x80) gets nothing back, not even an error;
//  - SETINPUTMODE makes the port's reading invalid for 20 ms when the type changes (1 ms
//    when it does not); NO_SENSOR stops updating the raw value (it goes stale);
//  - TachoCount, BlockTachoCount and RotationCount count the motor's tachometer (degrees on
//    a real NXT; the robot's counts_per_turn a turn on the simulated one);
//    RESETMOTORPOSITION zeroes RotationCount (relative = 0) or BlockTachoCount (relative =
//    1); TachoCount is reset only when a program starts or stops (as in the firmware:
//    SETOUTPUTSTATE does not reset it, it moves the tacho-limit target);
//  - a tacho limit adds to the motor's target; reaching it sets the run state to IDLE and
//    the motor coasts;
//  - starting or stopping a program resets the devices: inputs back to NO_SENSOR (raw 0),
//    motors coasting with every counter at 0, mailboxes emptied;
//  - mailboxes: 20 queues of 5 messages, the oldest dropped when a sixth arrives; reading or
//    writing one needs a running program.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "legofeup/comms/nxt/telegram.hpp"
#include "legofeup/nxtemu/brick_hardware.hpp"

namespace legofeup::nxtemu {

struct FirmwareOptions {
    std::uint16_t battery_millivolts = 7800;
    /// The KEEPALIVE reply: the brick's sleep timer (10 minutes, the firmware's default).
    std::uint32_t sleep_limit_ms = 600'000;
    /// The motors' no-load speed at 9 V, °/s (sim::RobotSpec::max_motor_rpm × 6: 170 rpm).
    /// Full power turns a motor at this × battery / 9 V; speed regulation cannot do more.
    double max_motor_degrees_per_second = 1020.0;
    /// legofeup.rxe is on the brick: STARTPROGRAM runs the emulated relay program.
    bool relay_installed = true;
    std::string relay_program = "legofeup.rxe";
    /// The ports the relay program reads and, after 500 ms unread, stops.
    BrickWiring wiring;
};

/// What the firmware has seen since it started.
struct FirmwareCounters {
    std::uint64_t requests = 0;        ///< telegrams handled
    std::uint64_t no_reply = 0;        ///< of them, sent "no reply" (nothing was answered)
    std::uint64_t error_statuses = 0;  ///< requests refused (a non-zero status, sent or not)
    std::uint64_t programs_started = 0;
    std::uint64_t relay_messages = 0;       ///< messages the relay program posted
    std::uint64_t relay_messages_read = 0;  ///< of them, taken by a MESSAGEREAD with remove
    std::uint64_t relay_safety_stops = 0;   ///< times the relay stopped the motors (unread)
};

class BrickFirmware {
  public:
    /// `hardware` must outlive the firmware.
    explicit BrickFirmware(BrickHardware& hardware, FirmwareOptions options = {});
    ~BrickFirmware();
    BrickFirmware(const BrickFirmware&) = delete;
    BrickFirmware& operator=(const BrickFirmware&) = delete;

    /// Handles one request telegram (without its length prefix) received at `now_seconds`
    /// (any monotonic clock, the same for every call). Returns the reply, or nullopt when the
    /// request asked for none. Never throws for what a host sends.
    std::optional<comms::nxt::Telegram> handle(std::span<const std::uint8_t> request,
                                               double now_seconds);

    /// Runs the firmware up to `now_seconds`: takes the tachometers' and A/D converters'
    /// news, ends invalid windows, applies tacho limits, runs the relay program's 10 ms
    /// ticks, and gives the hardware the motor speeds. handle() does this first too; call
    /// it whenever the hardware has news (each simulator frame). Earlier times are ignored.
    void advance(double now_seconds);

    /// As GETOUTPUTSTATE would answer now (run state: the motor's, e.g. IDLE after a
    /// reached tacho limit). `port` < kOutputCount.
    comms::nxt::OutputStateReply output(std::uint8_t port) const;
    /// As GETINPUTVALUES would answer at the last advance. `port` < kInputCount.
    comms::nxt::InputValues input(std::uint8_t port) const;
    /// The speeds last given to the hardware, °/s.
    const std::array<double, kOutputCount>& motor_speeds() const;
    /// The running program's file name, or nullopt.
    std::optional<std::string> running_program() const;
    const FirmwareCounters& counters() const;
    const FirmwareOptions& options() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::nxtemu
