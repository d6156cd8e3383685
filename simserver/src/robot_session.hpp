#pragma once
// Who drives the robot, and the command watchdog (docs/protocol.md, robot stream).
//
// One client at a time holds the robot: the first to Connect, until it disconnects or is
// silent for the peer timeout. Its commands pass a sequence window (new / duplicate / late).
// Watchdog: at each period boundary, two periods without an accepted command stop the motors.

#include <chrono>
#include <optional>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/comms/protocol.hpp"
#include "legofeup/comms/sequence_window.hpp"

namespace legofeup::simserver {

using Clock = std::chrono::steady_clock;

class RobotSession {
  public:
    explicit RobotSession(std::chrono::milliseconds peer_timeout) : peer_timeout_(peer_timeout) {}

    /// Accepted if nobody holds the robot, the caller does already, or the holder went silent.
    comms::ConnectResult connect(const comms::Endpoint& from, Clock::time_point now);
    void disconnect(const comms::Endpoint& from);
    /// Releases the robot if its client has been silent for the peer timeout.
    void expire(Clock::time_point now);

    bool is_client(const comms::Endpoint& from) const { return client_ && *client_ == from; }
    const std::optional<comms::Endpoint>& client() const { return client_; }
    void heard_from_client(Clock::time_point now) { last_heard_ = now; }

    /// Classifies a command of the client; New ones also feed the watchdog.
    comms::Arrival command(std::uint32_t sequence);
    const comms::SequenceCounts& command_counts() const { return commands_.counts(); }

    /// Called at each period boundary before stepping: true if the motors must stop now
    /// (two whole periods without a command). Counts each stop once.
    bool watchdog_due();
    void period_passed() { ++periods_without_command_; }
    /// After a reset: motors stopped, waiting for the first command.
    void motors_stopped() {
        watchdog_stopped_ = true;
        periods_without_command_ = 0;
    }
    bool watchdog_stopped() const { return watchdog_stopped_; }
    std::uint64_t watchdog_stops() const { return watchdog_stops_; }

  private:
    static constexpr int kWatchdogPeriods = 2;

    std::chrono::milliseconds peer_timeout_;
    std::optional<comms::Endpoint> client_;
    Clock::time_point last_heard_;
    comms::SequenceWindow commands_;
    int periods_without_command_ = 0;
    bool watchdog_stopped_ = true;  // the motors start still
    std::uint64_t watchdog_stops_ = 0;
};

}  // namespace legofeup::simserver
