// Benchmarks of the UDP link (Google Benchmark). Run from a release build:
//   build/release/bench/legofeup_comms_bench
//
// BM_FrameToCommandLatency: a stand-in server sends a sensor frame over loopback; a client
//   thread receives it through UdpSimulatorLink, runs the LegoFeup loop step and sends the
//   wheel command back; the server side times frame-out → command-in. Percentiles in µs.
// BM_ServerFrameRate: the real SimServer paced at N frames per second, with a client that
//   answers every frame through the loop; counts the frames that never arrived.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "legofeup/comms/control_client.hpp"
#include "legofeup/comms/udp_link.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/lessons/world_file.hpp"
#include "legofeup/sim/simulator.hpp"
#include "legofeup/simserver/sim_server.hpp"

namespace {

using namespace legofeup;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr comms::Endpoint kLoopback{0x7F000001, 0};

/// Real frames of experiment f, so the loop does its real work (updates at the walls).
std::vector<SensorFrame> recorded_frames(const lessons::ResolvedRun& run, std::size_t count) {
    sim::WorldSpec world = run.world;
    world.start = run.true_start;
    sim::Simulator simulator(world, run.robot, run.config.simulator, run.config.seed);
    std::vector<SensorFrame> frames;
    for (std::size_t i = 0; i < count; ++i) {
        frames.push_back(simulator.sensor_frame());
        simulator.set_wheel_command({0.1, 0.09});
        simulator.step_control_period();
    }
    return frames;
}

void add_percentiles(benchmark::State& state, std::vector<double> microseconds) {
    std::sort(microseconds.begin(), microseconds.end());
    const auto at = [&](double q) {
        return microseconds[static_cast<std::size_t>(
            q * static_cast<double>(microseconds.size() - 1))];
    };
    state.counters["p50_us"] = at(0.50);
    state.counters["p99_us"] = at(0.99);
    state.counters["max_us"] = microseconds.back();
}

void BM_FrameToCommandLatency(benchmark::State& state) {
    const lessons::ResolvedRun run = lessons::resolve(lessons::find_experiment("f")->config);
    const std::vector<SensorFrame> frames = recorded_frames(run, 3000);

    comms::UdpSocket server(kLoopback);
    comms::UdpLinkOptions options;
    options.server = server.local_endpoint();
    options.frame_timeout = 1s;
    comms::UdpSimulatorLink link(options);
    std::atomic<bool> stop = false;
    std::jthread client([&] {
        link.connect();
        LegoFeupLoop loop(run.loop);
        while (!stop) {
            if (const auto frame = link.next_frame()) {
                link.send_command(loop.step(*frame).wheels);
            }
        }
    });
    // The handshake: answer the client's Connect.
    const auto hello = server.receive(2s);
    const comms::Endpoint client_address = hello->from;
    comms::ConnectReplyPacket reply;
    reply.holder = client_address;
    reply.control_period = 0.05;
    reply.time_scale = 1.0;
    server.send_to(encode(reply), client_address);

    std::vector<double> latencies;
    std::size_t next = 0;
    std::uint32_t sequence = 0;
    for (auto _ : state) {
        comms::FramePacket packet;
        packet.frame = frames[next++ % frames.size()];
        packet.frame.sequence = ++sequence;
        const comms::Bytes bytes = encode(packet);
        const auto sent = Clock::now();
        server.send_to(bytes, client_address);
        for (;;) {  // the command for this frame (skip nothing else: there is nothing else)
            const auto datagram = server.receive(1s);
            comms::CommandPacket command;
            if (!datagram || decode(datagram->bytes, command) == comms::DecodeError::None) {
                break;
            }
        }
        latencies.push_back(std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
    }
    stop = true;
    server.send_to(encode(comms::FramePacket{}), client_address);  // wake the client to stop
    add_percentiles(state, latencies);
}
BENCHMARK(BM_FrameToCommandLatency)->Iterations(3000)->Unit(benchmark::kMicrosecond)->UseRealTime();

// Args: time scale, control period in ms. 20× with 20 ms periods = 1 kHz of frames;
// 20× with the standard 50 ms periods = 400 Hz.
void BM_ServerFrameRate(benchmark::State& state) {
    const double time_scale = static_cast<double>(state.range(0));
    sim::SimulatorSettings settings;
    settings.control_period = static_cast<double>(state.range(1)) / 1000.0;
    simserver::SimServerOptions options;
    options.bind = kLoopback;
    options.time_scale = time_scale;
    simserver::SimServer server(lessons::built_in_world(), sim::RobotSpec{}, settings, 1, options);
    server.start();
    const lessons::ResolvedRun run = lessons::resolve(lessons::find_experiment("f")->config);

    comms::UdpLinkOptions link_options;
    link_options.server = {0x7F000001, server.ports().robot};
    comms::UdpSimulatorLink link(link_options);
    link.connect();
    LegoFeupLoop loop(run.loop);
    std::uint64_t received = 0;
    double simulated = 0.0;
    for (auto _ : state) {
        const auto until = Clock::now() + 3s;
        while (Clock::now() < until) {
            if (const auto frame = link.next_frame()) {
                ++received;
                simulated = frame->time;
                link.send_command(loop.step(*frame).wheels);
            }
        }
    }
    link.disconnect();
    const comms::LinkCounters counters = link.counters();
    const comms::ServerStatus status = server.status();
    state.counters["frames_per_s"] =
        benchmark::Counter(static_cast<double>(received), benchmark::Counter::kIsRate);
    state.counters["frames"] = static_cast<double>(received);
    state.counters["lost"] = static_cast<double>(counters.frames.missing);
    state.counters["late"] = static_cast<double>(counters.frames.late);
    state.counters["server_overruns"] = static_cast<double>(status.counters.overruns);
    state.counters["commands_lost"] = static_cast<double>(status.counters.commands_missing);
    state.counters["simulated_s"] = simulated;
}
BENCHMARK(BM_ServerFrameRate)
    ->Args({20, 20})
    ->Args({20, 50})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
