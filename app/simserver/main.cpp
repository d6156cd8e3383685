// legofeup-sim: the arena simulator as a standalone UDP server (docs/protocol.md), so the
// LegoFeup loop, the GUI or a student's own Python/Octave/MATLAB code can drive the robot.
// No display, no Qt.

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "legofeup/version.hpp"
#include "server_main.hpp"

int main(int argc, char** argv) {
    using namespace legofeup::simserver_app;
    CLI::App app{
        "LegoFeup Lab simulator server: the arena and the NXT robot over UDP "
        "(protocol: docs/protocol.md)."};
    app.set_version_flag("--version", std::string("legofeup-sim ") + legofeup::kVersion);

    ServerCommand command;
    app.add_option("--world,-w", command.world_file,
                   "A built-in world (standard_arena, office, beacon_field) or a world file "
                   "(TOML); default: the built-in standard arena")
        ->check(world_name_or_file);
    app.add_option("--seed,-s", command.seed, "Seed of every noise stream");
    app.add_option("--bind,-b", command.bind_address,
                   "IPv4 address to listen on (non-loopback needs --allow-remote)");
    app.add_option("--port,-p", command.port,
                   "Robot port; truth and control default to port+1 and port+2 (0: free ports)")
        ->check(CLI::Range(0, 65533));
    app.add_option("--truth-port", command.truth_port, "Ground-truth port")
        ->check(CLI::Range(1, 65535));
    app.add_option("--control-port", command.control_port, "Control port")
        ->check(CLI::Range(1, 65535));
    app.add_option("--time-scale,-t", command.time_scale,
                   "Simulated seconds per real second; 0 = lockstep (as fast as the client "
                   "answers)");
    app.add_option("--control-period", command.settings.control_period,
                   "Simulated seconds between sensor frames");
    app.add_option("--physics-rate", command.settings.physics_rate, "Physics steps per second");
    app.add_option("--wheel-diameter-ratio", command.robot.wheel_diameter_ratio,
                   "E_d: right/left wheel diameter");
    app.add_option("--wheel-base-ratio", command.robot.wheel_base_ratio,
                   "E_b: actual/nominal wheel base");
    app.add_option("--slip-noise", command.robot.slip_noise, "Wheel slip noise, m^1/2");
    app.add_option("--ir-noise", command.robot.ir_noise, "σ of each IR distance, m");
    app.add_option("--counts-per-turn", command.robot.counts_per_turn,
                   "Encoder counts a wheel turn in the frames (default 360, the NXT's: 1 count = "
                   "1°); a client's robot.counts_per_turn must be the same");
    app.add_flag("--allow-remote", command.allow_remote,
                 "Allow a non-loopback --bind (the protocol has no authentication)");
    app.add_option("--ready-file", command.ready_file,
                   "Write the bound ports here (robot=, truth=, control=) once listening");
    app.add_option("--duration", command.duration,
                   "Stop after this many real seconds (0: run until Ctrl-C)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--status-every", command.status_every,
                   "Print a status line every this many real seconds (0: never)")
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--quiet,-q", command.quiet, "Print only errors");

    CLI11_PARSE(app, argc, argv);
    return run_server(command);
}
