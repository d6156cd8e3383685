#include "server_main.hpp"

#include <pthread.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/world_file.hpp"
#include "legofeup/simserver/sim_server.hpp"

namespace legofeup::simserver_app {
namespace {

simserver::SimServerOptions server_options(const ServerCommand& command,
                                           const comms::Endpoint& bind) {
    simserver::SimServerOptions options;
    options.bind = bind.with_port(static_cast<std::uint16_t>(command.port));
    options.truth_port = static_cast<std::uint16_t>(
        command.truth_port.value_or(command.port == 0 ? 0 : command.port + 1));
    options.control_port = static_cast<std::uint16_t>(
        command.control_port.value_or(command.port == 0 ? 0 : command.port + 2));
    options.time_scale = command.time_scale;
    options.allow_remote = command.allow_remote;
    return options;
}

std::string pace(double time_scale) {
    if (time_scale == 0.0) {
        return "lockstep (as fast as the client answers)";
    }
    return format_config_number(time_scale) + "× real time";
}

void print_status(const comms::ServerStatus& status) {
    const comms::ServerCounters& c = status.counters;
    const std::uint64_t dropped = c.truncated + c.bad_magic + c.bad_version + c.unknown_type
                                  + c.bad_length + c.oversized + c.non_finite + c.wrong_stream;
    std::printf(
        "t = %.2f s  client %s  frames %llu  commands %llu (dup %llu, late %llu, lost %llu)  "
        "malformed %llu  other peers %llu  watchdog stops %llu%s\n",
        static_cast<double>(status.steps) * status.control_period,
        status.client_connected ? status.client.to_string().c_str() : "none",
        static_cast<unsigned long long>(c.frames_sent),
        static_cast<unsigned long long>(c.commands_accepted),
        static_cast<unsigned long long>(c.commands_duplicate),
        static_cast<unsigned long long>(c.commands_late),
        static_cast<unsigned long long>(c.commands_missing),
        static_cast<unsigned long long>(dropped),
        static_cast<unsigned long long>(c.unexpected_peer),
        static_cast<unsigned long long>(c.watchdog_stops), status.paused ? "  [paused]" : "");
    std::fflush(stdout);
}

/// Waits for SIGINT/SIGTERM (blocked in every thread, so only this wait takes them) up to
/// `seconds`; true if one came.
bool wait_for_signal(const sigset_t& signals, double seconds) {
    timespec timeout{
        static_cast<time_t>(seconds),
        static_cast<long>((seconds - static_cast<double>(static_cast<time_t>(seconds))) * 1e9)};
    return sigtimedwait(&signals, nullptr, &timeout) > 0;
}

}  // namespace

std::string world_name_or_file(const std::string& value) {
    if (lessons::find_built_in_world(value) != nullptr || std::filesystem::is_regular_file(value)) {
        return "";
    }
    std::string names;
    for (const std::string& name : lessons::built_in_world_names()) {
        names += (names.empty() ? "" : ", ") + name;
    }
    return "'" + value + "': neither a built-in world (" + names + ") nor a world file";
}

int run_server(const ServerCommand& command) {
    const auto bind = comms::parse_endpoint(command.bind_address, 0);
    if (!bind || command.bind_address.find(':') != std::string::npos) {
        std::cerr << "legofeup-sim: --bind " << command.bind_address
                  << ": not an IPv4 address such as 127.0.0.1\n";
        return 1;
    }
    // Block the stop signals before any thread starts, so the server thread inherits the
    // mask and the main thread alone receives them in sigtimedwait.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);

    std::optional<simserver::SimServer> server;
    try {
        sim::WorldSpec world = command.world_file.empty() ? lessons::built_in_world()
                                                          : lessons::load_world(command.world_file);
        server.emplace(std::move(world), command.robot, command.settings, command.seed,
                       server_options(command, *bind));
    } catch (const std::exception& error) {
        std::cerr << "legofeup-sim: " << error.what() << '\n';
        return 1;
    }
    const simserver::BoundPorts ports = server->ports();
    if (!command.ready_file.empty()) {
        // Written atomically: a reader polling for the file never sees half of it.
        try {
            fileio::write_file_atomically(
                command.ready_file, "robot=" + std::to_string(ports.robot)
                                        + "\ntruth=" + std::to_string(ports.truth)
                                        + "\ncontrol=" + std::to_string(ports.control) + '\n');
        } catch (const fileio::WriteError& error) {
            std::cerr << "legofeup-sim: --ready-file: " << error.what() << '\n';
            return 1;
        }
    }
    if (!command.quiet) {
        const comms::ServerStatus status = server->status();
        std::printf(
            "legofeup-sim: world '%s', seed %llu, control period %g s, encoders %s counts a "
            "turn, %s\n"
            "  robot   udp://%s:%u  (sensor frames out, wheel commands in)\n"
            "  truth   udp://%s:%u  (ground truth, for displays and metrics)\n"
            "  control udp://%s:%u  (reset, pause, noise, teleport, status)\n"
            "Ctrl-C stops.\n",
            status.world_name.c_str(), static_cast<unsigned long long>(command.seed),
            status.control_period, format_config_number(command.robot.counts_per_turn).c_str(),
            pace(command.time_scale).c_str(), command.bind_address.c_str(), ports.robot,
            command.bind_address.c_str(), ports.truth, command.bind_address.c_str(), ports.control);
        std::fflush(stdout);
    }
    server->start();

    const auto started = std::chrono::steady_clock::now();
    auto next_status = started;
    for (;;) {
        const auto now = std::chrono::steady_clock::now();
        const double elapsed = std::chrono::duration<double>(now - started).count();
        if (command.duration > 0.0 && elapsed >= command.duration) {
            break;
        }
        if (!command.quiet && command.status_every > 0.0 && now >= next_status) {
            print_status(server->status());
            next_status = now
                          + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(command.status_every));
        }
        double wait = 0.2;
        if (command.duration > 0.0) {
            wait = std::min(wait, command.duration - elapsed);
        }
        if (wait_for_signal(signals, std::max(wait, 0.001))) {
            break;
        }
    }
    server->stop();
    if (!command.quiet) {
        print_status(server->status());
    }
    return 0;
}

}  // namespace legofeup::simserver_app
