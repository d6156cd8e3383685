#pragma once
// An emulated LEGO NXT, whole: the firmware (brick_firmware.hpp) on the simulated robot
// (simulated_hardware.hpp), reachable over TCP and/or a pseudo-terminal with Bluetooth-like
// latency (brick_server.hpp). The GUI's "rehearse with an emulated brick" and the
// legofeup-nxt-emu program are this object. docs/nxt-emulator.md tells the whole story.
//
//   nxtemu::EmulatorOptions options;
//   options.run = lessons::find_experiment("f")->config;
//   nxtemu::EmulatedNxt brick(options);
//   const std::uint16_t port = brick.serve_tcp();        // tcp:127.0.0.1:<port>
//   ... NxtLink to tcp:127.0.0.1:<port>, TruthReceiver on brick.truth_endpoint() ...
//   brick.stop();

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/nxtemu/brick_firmware.hpp"
#include "legofeup/nxtemu/brick_server.hpp"
#include "legofeup/simserver/sim_server.hpp"

namespace legofeup::nxtemu {

struct EmulatorOptions {
    /// The simulated robot, its noise, the world, the seed and the true start (an
    /// experiment's preset, a configuration file, …).
    lessons::RunConfig run;
    BrickWiring wiring;
    /// Battery, sleep limit, relay program. Its wiring and motor speed are taken from
    /// `wiring` and the run's robot.
    FirmwareOptions firmware;
    /// Latency and injected failures. Its log is replaced by `log` below.
    BrickServerOptions link;
    /// Events worth telling a person, prefixed with the time since the start. May be empty.
    std::function<void(const std::string&)> log;
};

struct EmulatorCounters {
    BrickServerCounters link;
    FirmwareCounters firmware;
    std::uint64_t simulator_frames = 0;
    std::uint64_t simulator_frames_missed = 0;
};

class EmulatedNxt {
  public:
    /// Resolves the run, starts the simulator and the firmware. Throws lessons::InputError for
    /// a bad configuration, std::invalid_argument for bad wiring, comms::LinkError or
    /// std::system_error when the simulator cannot start.
    explicit EmulatedNxt(EmulatorOptions options);
    /// stop().
    ~EmulatedNxt();
    EmulatedNxt(const EmulatedNxt&) = delete;
    EmulatedNxt& operator=(const EmulatedNxt&) = delete;

    /// Listens on 127.0.0.1 (any address if `allow_remote`) and serves one client at a time
    /// on a thread of its own; port 0 picks a free one. Returns the port. Throws
    /// comms::LinkError when the port cannot be bound.
    std::uint16_t serve_tcp(std::uint16_t port = 0, bool allow_remote = false);
    /// Opens a pseudo-terminal and serves its master on a thread of its own. Returns the
    /// slave's path (/dev/pts/N), which a host opens as it would /dev/rfcomm0. If
    /// `link_path` is given, it is made a symbolic link to the slave (replaced if it is one
    /// already). After a drop or a framing error the pty is replaced by a new one (the link
    /// follows it; pty_path() tells the new path).
    std::string serve_pty(const std::string& link_path = {});
    /// The current pseudo-terminal's slave path; empty if none is served.
    std::string pty_path() const;

    /// Where the simulator publishes the ground truth (for the host's metrics).
    comms::Endpoint truth_endpoint() const;
    simserver::BoundPorts simulator_ports() const;

    /// Closes the connections, stops the simulator. Idempotent; never throws.
    void stop();
    EmulatorCounters counters() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::nxtemu
