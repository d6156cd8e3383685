#pragma once
// What a robot connection can do and how well it is doing, in words that fit every link (a
// simulator over UDP, an NXT over Bluetooth, a serial port or TCP), so that the GUI and the
// CLI ask the connection instead of deciding from which kind of link they chose, and no
// simulator or NXT type crosses the RobotConnection interface.

#include <cstdint>
#include <optional>
#include <string>

namespace legofeup::lessons {

/// What a connection can do beyond frames in and commands out.
struct LinkCapabilities {
    bool ground_truth = false;  ///< truth_source() gives the true pose (a simulator)
    bool live_noise = false;    ///< set_noise() changes the robot's noise while it runs
    bool teleport = false;      ///< teleport() lifts the robot to a pose (a kidnapping)
    bool stops_clock = false;   ///< set_paused() stops time; otherwise the robot only stands
    /// The robot has a battery and a command cycle of its own to report (an NXT, real or
    /// emulated): the Robot dock and the status bar show its health.
    bool robot_health = false;
};

/// A simulated robot's noise, as a link with live noise takes it while it runs: the
/// odometry's systematic errors E_d and E_b (paper 000 eq. 6), the slip, and the IR sensors'
/// σ (docs/simulator.md). A real robot has its own and takes none.
struct RobotNoise {
    double wheel_diameter_ratio = 1.0;  ///< E_d
    double wheel_base_ratio = 1.0;      ///< E_b
    double slip_noise = 0.0;            ///< m^½
    double ir_noise = 0.0;              ///< σ of each IR distance, m

    friend bool operator==(const RobotNoise&, const RobotNoise&) = default;
};

enum class LinkState : std::uint8_t { Disconnected, Connecting, Connected, Failed };

/// How a link is doing: its state, where it goes, its counters and, where there is one,
/// the robot's battery. Counters a link does not keep stay 0.
struct LinkHealth {
    LinkState state = LinkState::Disconnected;
    std::string address;            ///< where the robot is: "udp://127.0.0.1:5600", "bt:00:16:…"
    std::string last_error;         ///< why it failed or closed (empty if it did not)
    std::uint64_t frames = 0;       ///< frames delivered
    std::uint64_t frames_lost = 0;  ///< frames that never came (sequence gaps)
    std::uint64_t timeouts = 0;     ///< waits for a frame or a reply that ran out
    std::uint64_t rejected_replies = 0;  ///< malformed datagrams or replies
    std::uint64_t invalid_readings = 0;  ///< readings the robot flagged not valid
    double last_cycle_seconds = 0.0;     ///< 0: the link does not time its cycle
    double mean_cycle_seconds = 0.0;     ///< mean interval between frames since connect
    double max_cycle_seconds = 0.0;
    std::optional<int> battery_millivolts;
    /// Cycles per second (1 / mean cycle time), 0 before the first frame or when untimed.
    double rate_hz() const { return mean_cycle_seconds > 0 ? 1.0 / mean_cycle_seconds : 0.0; }
};

}  // namespace legofeup::lessons
