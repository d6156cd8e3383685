#pragma once
// The arena simulator as a UDP server (docs/protocol.md): it owns time, publishes a sensor
// frame every control period, takes wheel commands from one client, sends ground truth to
// subscribers on its own stream and serves control requests. The standalone legofeup-sim
// and the GUI (on its own thread) both run this.

#include <chrono>
#include <cstdint>
#include <memory>
#include <stop_token>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/simulator.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::simserver {

struct SimServerOptions {
    /// The robot port's address; truth and control use the same address. Port 0 picks free
    /// ports for all three streams (tests, and the --ready-file of legofeup-sim).
    comms::Endpoint bind{comms::kLoopbackAddress, comms::kDefaultRobotPort};
    std::uint16_t truth_port = comms::kDefaultTruthPort;
    std::uint16_t control_port = comms::kDefaultControlPort;
    /// Simulated seconds per real second; 0 = lockstep (as fast as the client answers).
    double time_scale = 1.0;
    /// A non-loopback address exposes an unauthenticated robot: it must be asked for.
    bool allow_remote = false;
    /// The robot is released when its client has been silent this long.
    std::chrono::milliseconds peer_timeout{3000};
    /// Lockstep: advance after this long without an answer to the latest frame.
    std::chrono::milliseconds lockstep_patience{100};
};

struct BoundPorts {
    std::uint16_t robot = 0;
    std::uint16_t truth = 0;
    std::uint16_t control = 0;
};

/// Everything wrong with the options (absurd time scale, remote bind not allowed, ...).
std::vector<ConfigIssue> validate(const SimServerOptions& options);

class SimServer {
  public:
    /// Builds the simulator and binds the three sockets. Throws std::invalid_argument for
    /// bad options or settings and std::system_error when a port cannot be bound.
    SimServer(sim::WorldSpec world, sim::RobotSpec robot, sim::SimulatorSettings settings,
              std::uint64_t seed, SimServerOptions options);
    ~SimServer();
    SimServer(const SimServer&) = delete;
    SimServer& operator=(const SimServer&) = delete;

    BoundPorts ports() const;

    /// Serves in the calling thread until `stop` is requested.
    void run(std::stop_token stop);
    /// Serves on a thread of its own until stop() or destruction.
    void start();
    void stop();

    /// A consistent copy of the status and counters, from any thread.
    comms::ServerStatus status() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::simserver
