#pragma once
// The emulated brick's motors and sensors are the simulated robot's: a simulator server
// (simserver::SimServer, real time, free loopback ports) runs the run's world, robot, noise
// and true start, and this drives it as a UDP client (lessons::UdpRobotConnection) on a thread
// of its own — the "firmware tick": every simulator frame it stores the wheel encoders and IR
// A/D values, calls back (the firmware advances), and sends the motors' speeds as wheel
// speeds. The simulator's truth port stays open for the host's metrics.
//
// Units: a motor turning at ω °/s drives its wheel at ω·π/180·r m/s with the nominal wheel
// radius r, which is how the simulator turns a wheel-speed command back into rotation — so
// regulated power P turns the simulated wheel at P·10 °/s (up to the motor's 170 rpm). The
// tachometers count at the robot's encoder resolution, counts_per_turn a turn (the NXT's 360:
// 1 count = 1°): the wheels' are the simulator's encoder counts, a free motor's ω·t ·
// counts_per_turn/360.

#include <array>
#include <cstdint>
#include <functional>
#include <memory>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/nxtemu/brick_hardware.hpp"
#include "legofeup/simserver/sim_server.hpp"

namespace legofeup::nxtemu {

/// The simulator's control period behind an emulated brick: its counters change every 10 ms
/// (a run's loop period, 50 ms, would make them jump).
inline constexpr double kEmulatedControlPeriod = 0.01;

/// Resolves `config` for the simulator behind a brick: the same robot, noise, world, seed and
/// true start, with the simulator's control period set to `control_period`. Throws
/// lessons::InputError like lessons::resolve.
lessons::ResolvedRun resolve_emulated_run(lessons::RunConfig config,
                                          double control_period = kEmulatedControlPeriod);

class SimulatedHardware final : public BrickHardware {
  public:
    /// Starts the simulator server for `run`, takes its robot (noise, seed and true start
    /// set, as a UDP run does) and starts pumping frames. `on_frame` is called on the pump
    /// thread after each frame is stored (it may call this object back). Throws
    /// comms::LinkError or std::system_error if the simulator cannot be started or reached.
    SimulatedHardware(const lessons::ResolvedRun& run, BrickWiring wiring,
                      std::function<void()> on_frame = {});
    ~SimulatedHardware() override;
    SimulatedHardware(const SimulatedHardware&) = delete;
    SimulatedHardware& operator=(const SimulatedHardware&) = delete;

    void set_motor_speeds(const std::array<double, kOutputCount>& degrees_per_second) override;
    /// The wheel motors' counts from the simulator's encoders; a motor with no wheel turns
    /// freely at its speed and counts at the same resolution.
    std::array<double, kOutputCount> tacho_counts() override;
    /// The IR sensors' A/D values on their ports; kOpenInputAdc elsewhere.
    std::array<std::uint16_t, kInputCount> adc() override;

    /// The simulator's ports: truth for the host's ground truth, control for a teacher.
    simserver::BoundPorts simulator_ports() const;
    comms::Endpoint truth_endpoint() const;
    /// Simulator frames received, and periods in which none came.
    std::uint64_t frames() const;
    std::uint64_t missed_frames() const;

    /// Stops the pump and the simulator (the destructor does it too).
    void stop();

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::nxtemu
