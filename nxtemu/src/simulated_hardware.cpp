#include "legofeup/nxtemu/simulated_hardware.hpp"

#include <algorithm>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>

#include "legofeup/lessons/udp_run.hpp"

namespace legofeup::nxtemu {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

simserver::SimServerOptions server_options() {
    simserver::SimServerOptions options;
    options.bind = comms::Endpoint{comms::kLoopbackAddress, 0};  // free ports for all three streams
    options.truth_port = 0;
    options.control_port = 0;
    options.time_scale = 1.0;  // a brick lives in real time
    return options;
}

void check_wiring(const BrickWiring& wiring) {
    if (wiring.right_motor >= kOutputCount || wiring.left_motor >= kOutputCount
        || wiring.right_motor == wiring.left_motor) {
        throw std::invalid_argument(
            "wheel motors on output ports " + std::to_string(wiring.right_motor) + " and "
            + std::to_string(wiring.left_motor) + ": expected two different ports 0–2 (A–C)");
    }
    if (wiring.front_ir >= kInputCount || wiring.rear_ir >= kInputCount
        || wiring.front_ir == wiring.rear_ir) {
        throw std::invalid_argument("IR sensors on input ports " + std::to_string(wiring.front_ir)
                                    + " and " + std::to_string(wiring.rear_ir)
                                    + ": expected two different ports 0–3 (1–4)");
    }
}

}  // namespace

lessons::ResolvedRun resolve_emulated_run(lessons::RunConfig config, double control_period) {
    config.simulator.control_period = control_period;
    return lessons::resolve(config);
}

struct SimulatedHardware::State {
    State(const lessons::ResolvedRun& run, BrickWiring w, std::function<void()> callback)
        : wiring(w),
          on_frame(std::move(callback)),
          wheel_radius(0.5 * run.robot.wheel_diameter),
          counts_per_degree(run.robot.counts_per_turn / 360.0),
          server(run.world, run.robot, run.config.simulator, run.config.seed, server_options()) {
        check_wiring(wiring);
        server.start();
        const simserver::BoundPorts ports = server.ports();
        const comms::Endpoint robot{comms::kLoopbackAddress, ports.robot};
        connection = std::make_unique<lessons::UdpRobotConnection>(
            run, lessons::UdpTarget{robot, robot.with_port(ports.truth),
                                    robot.with_port(ports.control)});
        pump = std::jthread([this](std::stop_token stop) { pump_frames(stop); });
    }

    ~State() { stop(); }

    void stop() {
        if (pump.joinable()) {
            pump.request_stop();
            pump.join();
        }
        if (connection) {
            connection->close();  // stops the motors, releases the robot
            connection.reset();
        }
        server.stop();
    }

    void pump_frames(const std::stop_token& stop) {
        comms::UdpSimulatorLink& link = connection->link();
        while (!stop.stop_requested()) {
            const std::optional<SensorFrame> frame = link.next_frame();
            if (frame) {
                store(*frame);
                if (on_frame) {
                    on_frame();
                }
            } else {
                const std::lock_guard lock(mutex);
                ++missed;
            }
            link.send_command(wheel_command());  // also after a missed frame, as clients do
        }
    }

    double sign() const { return wiring.reversed_motors ? -1.0 : 1.0; }

    void store(const SensorFrame& frame) {
        const std::lock_guard lock(mutex);
        const double dt = frames == 0 ? 0.0 : std::max(frame.time - frame_time, 0.0);
        for (std::size_t port = 0; port < kOutputCount; ++port) {
            counts.at(port) += speeds.at(port) * dt * counts_per_degree;  // free motors
        }
        counts.at(wiring.right_motor) = sign() * frame.encoder_counts[0];  // the wheels
        counts.at(wiring.left_motor) = sign() * frame.encoder_counts[1];
        readings.fill(kOpenInputAdc);
        readings.at(wiring.front_ir) = frame.ir_adc[0];
        readings.at(wiring.rear_ir) = frame.ir_adc[1];
        frame_time = frame.time;
        ++frames;
    }

    WheelSpeeds wheel_command() const {
        const std::lock_guard lock(mutex);
        const double metres_per_degree = sign() * kRadiansPerDegree * wheel_radius;
        return {speeds.at(wiring.right_motor) * metres_per_degree,
                speeds.at(wiring.left_motor) * metres_per_degree};
    }

    const BrickWiring wiring;
    const std::function<void()> on_frame;
    const double wheel_radius;       ///< nominal, m: as the simulator's motors convert
    const double counts_per_degree;  ///< the robot's counts_per_turn / 360
    simserver::SimServer server;
    std::unique_ptr<lessons::UdpRobotConnection> connection;

    mutable std::mutex mutex;  // guards what follows
    std::array<double, kOutputCount> speeds{};
    std::array<double, kOutputCount> counts{};  ///< the tachometers, BrickHardware's units
    std::array<std::uint16_t, kInputCount> readings{kOpenInputAdc, kOpenInputAdc, kOpenInputAdc,
                                                    kOpenInputAdc};
    double frame_time = 0.0;
    std::uint64_t frames = 0;
    std::uint64_t missed = 0;

    std::jthread pump;  // last: started when everything else exists
};

SimulatedHardware::SimulatedHardware(const lessons::ResolvedRun& run, BrickWiring wiring,
                                     std::function<void()> on_frame)
    : state_(std::make_unique<State>(run, wiring, std::move(on_frame))) {}

SimulatedHardware::~SimulatedHardware() = default;

void SimulatedHardware::set_motor_speeds(
    const std::array<double, kOutputCount>& degrees_per_second) {
    const std::lock_guard lock(state_->mutex);
    state_->speeds = degrees_per_second;
}

std::array<double, kOutputCount> SimulatedHardware::tacho_counts() {
    const std::lock_guard lock(state_->mutex);
    return state_->counts;
}

std::array<std::uint16_t, kInputCount> SimulatedHardware::adc() {
    const std::lock_guard lock(state_->mutex);
    return state_->readings;
}

simserver::BoundPorts SimulatedHardware::simulator_ports() const {
    return state_->server.ports();
}

comms::Endpoint SimulatedHardware::truth_endpoint() const {
    return {comms::kLoopbackAddress, state_->server.ports().truth};
}

std::uint64_t SimulatedHardware::frames() const {
    const std::lock_guard lock(state_->mutex);
    return state_->frames;
}

std::uint64_t SimulatedHardware::missed_frames() const {
    const std::lock_guard lock(state_->mutex);
    return state_->missed;
}

void SimulatedHardware::stop() {
    state_->stop();
}

}  // namespace legofeup::nxtemu
