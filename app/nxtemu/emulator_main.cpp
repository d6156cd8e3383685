#include "emulator_main.hpp"

#include <pthread.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/nxtemu/emulated_nxt.hpp"

namespace legofeup::nxtemu_app {
namespace {

namespace fs = std::filesystem;
using lessons::InputError;

/// The robot behind the brick: the experiment's preset, then the file, then --seed.
lessons::RunConfig robot_config(const EmulatorCommand& command, std::string& title) {
    lessons::RunConfig config =
        lessons::compose_config({command.experiment, command.config_file, command.seed});
    title = "default robot";
    if (const lessons::Experiment* experiment = lessons::find_experiment(command.experiment)) {
        title = "experiment " + experiment->id;
    }
    if (!command.config_file.empty()) {
        title += " + " + fs::path(command.config_file).filename().string();
    }
    return config;
}

std::chrono::microseconds milliseconds(double ms) {
    return std::chrono::microseconds(static_cast<std::int64_t>(ms * 1000.0 + 0.5));
}

std::uint8_t motor_port(const std::string& letter) {
    return static_cast<std::uint8_t>(std::toupper(static_cast<unsigned char>(letter.at(0))) - 'A');
}

/// The options as the library takes them; nullopt (after saying why) when they contradict.
std::optional<nxtemu::EmulatorOptions> emulator_options(const EmulatorCommand& command,
                                                        std::string& title) {
    if (!command.tcp_port && !command.pty) {
        std::cerr << "legofeup-nxt-emu: nothing to serve: give --tcp PORT (0: a free port) "
                     "and/or --pty\n";
        return std::nullopt;
    }
    nxtemu::EmulatorOptions options;
    options.run = robot_config(command, title);
    options.wiring.right_motor = motor_port(command.right_motor);
    options.wiring.left_motor = motor_port(command.left_motor);
    options.wiring.front_ir = static_cast<std::uint8_t>(command.front_ir - 1);
    options.wiring.rear_ir = static_cast<std::uint8_t>(command.rear_ir - 1);
    options.wiring.reversed_motors = command.reversed_motors;
    if (options.wiring.right_motor == options.wiring.left_motor) {
        std::cerr << "legofeup-nxt-emu: --right-motor and --left-motor are both "
                  << command.right_motor << "\n";
        return std::nullopt;
    }
    if (options.wiring.front_ir == options.wiring.rear_ir) {
        std::cerr << "legofeup-nxt-emu: --front-ir and --rear-ir are both " << command.front_ir
                  << "\n";
        return std::nullopt;
    }
    options.firmware.battery_millivolts = static_cast<std::uint16_t>(command.battery_mv);
    options.firmware.relay_installed = !command.no_relay;
    const double both = command.latency_ms.value_or(30.0);
    options.link.latency_up = milliseconds(command.latency_up_ms.value_or(both));
    options.link.latency_down = milliseconds(command.latency_down_ms.value_or(both));
    options.link.drop_after = command.drop_after;
    options.link.freeze_after = command.freeze_after;
    if (!command.quiet) {
        options.log = [](const std::string& message) {
            std::printf("%s\n", message.c_str());
            std::fflush(stdout);
        };
    }
    return options;
}

/// Written atomically: a reader polling for the file never sees half of it.
void write_ready_file(const std::string& path, const nlohmann::json& ready) {
    fileio::write_file_atomically(path, ready.dump(2) + '\n');
}

/// Waits for SIGINT or SIGTERM (blocked in every thread, so only this wait takes them), or
/// until `duration` real seconds have passed (0: no limit).
void wait_for_stop(const sigset_t& signals, double duration) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(duration);
    constexpr timespec kSlice{0, 200'000'000};
    while (sigtimedwait(&signals, nullptr, &kSlice) < 0) {
        if (duration > 0.0 && std::chrono::steady_clock::now() >= end) {
            return;
        }
    }
}

void print_counters(const nxtemu::EmulatorCounters& c) {
    const auto n = [](std::uint64_t value) { return static_cast<unsigned long long>(value); };
    std::printf(
        "link: %llu sessions, %llu telegrams in (%llu no-reply), %llu replies out, "
        "%llu framing errors, %llu hosts gone, %llu injected drops, %llu replies frozen, "
        "%llu stop commands while frozen, %llu lost in flight\n"
        "firmware: %llu requests, %llu refused, %llu programs started; relay: %llu messages "
        "posted, %llu read, %llu safety stops\n"
        "simulator: %llu frames, %llu missed\n",
        n(c.link.sessions), n(c.link.telegrams_in), n(c.link.no_reply_telegrams),
        n(c.link.replies_out), n(c.link.framing_errors), n(c.link.clients_gone),
        n(c.link.injected_drops), n(c.link.replies_frozen), n(c.link.stop_commands_while_frozen),
        n(c.link.lost_in_flight), n(c.firmware.requests), n(c.firmware.error_statuses),
        n(c.firmware.programs_started), n(c.firmware.relay_messages),
        n(c.firmware.relay_messages_read), n(c.firmware.relay_safety_stops), n(c.simulator_frames),
        n(c.simulator_frames_missed));
    std::fflush(stdout);
}

}  // namespace

int run_emulator(const EmulatorCommand& command) {
    std::string title;
    std::optional<nxtemu::EmulatorOptions> options;
    try {
        options = emulator_options(command, title);
    } catch (const InputError& error) {
        for (const lessons::InputProblem& problem : error.problems()) {
            std::cerr << "legofeup-nxt-emu: error: " << problem.message() << '\n';
        }
        return kExitBadOptions;
    }
    if (!options) {
        return kExitBadOptions;
    }
    // Block the stop signals before any thread starts: the threads inherit the mask and the
    // main thread alone takes them, in wait_for_stop().
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);

    const std::uint64_t seed = options->run.seed;
    const std::chrono::microseconds up = options->link.latency_up;
    const std::chrono::microseconds down = options->link.latency_down;
    std::optional<nxtemu::EmulatedNxt> brick;
    nlohmann::json ready;
    try {
        brick.emplace(std::move(*options));
        if (command.tcp_port) {
            const std::uint16_t port = brick->serve_tcp(
                static_cast<std::uint16_t>(*command.tcp_port), command.allow_remote);
            ready["tcp_port"] = port;
            ready["tcp"] = "tcp:127.0.0.1:" + std::to_string(port);  // what a host here opens
        }
        if (command.pty) {
            ready["pty"] = brick->serve_pty(command.pty_link);
            if (!command.pty_link.empty()) {
                ready["pty_link"] = command.pty_link;
            }
        }
    } catch (const InputError& error) {
        for (const lessons::InputProblem& problem : error.problems()) {
            std::cerr << "legofeup-nxt-emu: error: " << problem.message() << '\n';
        }
        return kExitBadOptions;
    } catch (const std::exception& error) {
        std::cerr << "legofeup-nxt-emu: " << error.what() << '\n';
        return 1;
    }
    const simserver::BoundPorts sim = brick->simulator_ports();
    const std::string truth = "udp://" + brick->truth_endpoint().to_string();
    ready["simulator"] = {{"robot", sim.robot}, {"truth", sim.truth}, {"control", sim.control}};
    ready["truth"] = truth;
    ready["pid"] = static_cast<long>(getpid());
    if (!command.ready_file.empty()) {
        try {
            write_ready_file(command.ready_file, ready);
        } catch (const std::exception& error) {
            std::cerr << "legofeup-nxt-emu: --ready-file: " << error.what() << '\n';
            return 1;
        }
    }
    if (!command.quiet) {
        std::printf(
            "legofeup-nxt-emu: %s, seed %llu, battery %d mV, latency %.1f ms up / %.1f "
            "ms down, relay %s\n",
            title.c_str(), static_cast<unsigned long long>(seed), command.battery_mv,
            static_cast<double>(up.count()) / 1000.0, static_cast<double>(down.count()) / 1000.0,
            command.no_relay ? "not installed" : "legofeup.rxe installed");
        if (ready.contains("tcp")) {
            std::printf("  brick   %s\n", ready["tcp"].get<std::string>().c_str());
        }
        if (ready.contains("pty")) {
            std::printf("  brick   serial:%s\n", ready["pty"].get<std::string>().c_str());
        }
        std::printf(
            "  truth   %s  (ground truth for the host's metrics)\n"
            "  control udp://127.0.0.1:%u  (the simulator's control stream)\n"
            "Ctrl-C stops.\n",
            truth.c_str(), sim.control);
        std::fflush(stdout);
    }
    wait_for_stop(signals, command.duration);
    brick->stop();
    if (!command.quiet) {
        print_counters(brick->counters());
    }
    return 0;
}

}  // namespace legofeup::nxtemu_app
