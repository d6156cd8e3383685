#pragma once
// A run against a running simulator server over UDP (docs/protocol.md) instead of the
// in-process simulator: `legofeup-cli run --link udp://HOST:PORT`, and the tests.

#include <string>

#include <memory>

#include "legofeup/comms/control_client.hpp"
#include "legofeup/comms/truth_receiver.hpp"
#include "legofeup/comms/udp_link.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/robot_connection.hpp"

namespace legofeup::lessons {

struct UdpTarget {
    comms::Endpoint robot;
    comms::Endpoint truth;
    comms::Endpoint control;
};

/// Parses "udp://a.b.c.d[:port]"; truth and control default to port+1 and port+2.
/// Throws InputError naming the --link option for anything else.
UdpTarget parse_udp_target(const std::string& url, int truth_port, int control_port);

/// The robot of a simulator server, taken for a run: the robot, truth and control streams.
/// Opening it checks the server runs the run's control period, subscribes to the truth,
/// gives the server the run's noise, takes the robot and resets it to the run's seed and true
/// start; the first frame link() delivers is the reset one. Closing (or destroying) it stops
/// the motors and releases the robot. Throws comms::LinkError with what went wrong and what
/// to do.
class UdpRobotConnection final : public RobotConnection {
  public:
    UdpRobotConnection(const ResolvedRun& run, const UdpTarget& target);
    ~UdpRobotConnection() override;
    UdpRobotConnection(const UdpRobotConnection&) = delete;
    UdpRobotConnection& operator=(const UdpRobotConnection&) = delete;

    comms::UdpSimulatorLink& link() { return link_; }
    comms::TruthReceiver& truth() { return truth_; }
    comms::ControlClient& control() { return control_; }

    RobotLink& robot_link() override { return link_; }
    TruthSource* truth_source() override { return &truth_; }
    void set_noise(const RobotNoise& noise) override;
    /// Pauses or resumes the server's clock.
    void set_paused(bool paused) override;
    std::string teleport(const Pose2& pose) override {
        control_.teleport(pose);
        return {};
    }
    /// Stops the motors and releases the robot (once).
    void close() override;
    std::string describe() const override { return "udp://" + robot_.to_string(); }
    /// A simulator server can do everything but report a battery.
    LinkCapabilities capabilities() const override { return {true, true, true, true, false}; }
    /// The robot stream's counters: frames accepted and missing, timeouts, malformed.
    LinkHealth health() const override;
    /// kind "udp", the three ports, the robot stream's counters and the server's own
    /// (asked for now: its time scale, commands accepted and missing, overruns).
    nlohmann::json summary() override;

  private:
    UdpTarget target_;
    comms::Endpoint robot_;
    comms::ControlClient control_;
    comms::TruthReceiver truth_;
    comms::UdpSimulatorLink link_;
};

/// The noise a run asks of the simulated robot, as the control stream sets it.
comms::NoiseSettings noise_settings_of(const RobotNoise& noise);

struct UdpRunReport {
    RunResult result;
    comms::ServerStatus server;  ///< the server's status and counters after the run
    comms::LinkCounters link;    ///< what the client's end of the robot stream counted
};

/// Checks the server runs the run's control period, gives it the run's noise, takes the
/// robot, resets it to the run's seed and true start, and runs. Throws comms::LinkError
/// (or LinkSilent) with what went wrong and what to do.
UdpRunReport run_over_udp(const ResolvedRun& run, const UdpTarget& target,
                          RunObserver* observer = nullptr, const ProgressCallback& progress = {});

}  // namespace legofeup::lessons
