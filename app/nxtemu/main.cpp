// legofeup-nxt-emu: an emulated LEGO NXT brick (standard firmware and the relay program) on
// the simulated robot, over TCP or a pseudo-terminal with Bluetooth-like latency, so the
// real-robot path runs on one machine (docs/nxt-emulator.md). No display, no Qt.

#include <CLI/CLI.hpp>
#include <iostream>

#include "emulator_main.hpp"
#include "legofeup/version.hpp"

int main(int argc, char** argv) {
    using namespace legofeup::nxtemu_app;
    CLI::App app{
        "LegoFeup Lab emulated NXT brick: the NXT direct-command protocol over TCP or a "
        "pseudo-terminal, backed by the simulator (docs/nxt-emulator.md)."};
    app.set_version_flag("--version", std::string("legofeup-nxt-emu ") + legofeup::kVersion);

    EmulatorCommand command;
    app.add_option("--tcp", command.tcp_port,
                   "Serve on this TCP port of 127.0.0.1 (0: a free port)")
        ->check(CLI::Range(0, 65535));
    app.add_flag("--allow-remote", command.allow_remote,
                 "Listen on every address, not only 127.0.0.1 (no authentication!)");
    app.add_flag("--pty", command.pty,
                 "Serve a pseudo-terminal; its path is printed (open it like /dev/rfcomm0)");
    app.add_option("--pty-link", command.pty_link,
                   "Make this path a symbolic link to the pseudo-terminal (implies --pty)");
    app.add_option("--latency-ms", command.latency_ms,
                   "One-way latency of the link, both directions, ms (default 30)")
        ->check(CLI::Range(0.0, 10000.0));
    app.add_option("--latency-up-ms", command.latency_up_ms, "Host → brick latency, ms")
        ->check(CLI::Range(0.0, 10000.0));
    app.add_option("--latency-down-ms", command.latency_down_ms, "Brick → host latency, ms")
        ->check(CLI::Range(0.0, 10000.0));
    app.add_option("--experiment,-e", command.experiment,
                   "Guided experiment a … h: its robot, noise, world and true start");
    app.add_option("--config,-c", command.config_file,
                   "TOML configuration applied over the experiment's preset")
        ->check(CLI::ExistingFile);
    app.add_option("--seed,-s", command.seed, "Seed of the simulator's noise");
    app.add_option("--battery-mv", command.battery_mv, "Battery voltage the brick reports, mV")
        ->check(CLI::Range(4000, 10000));
    app.add_flag("--no-relay", command.no_relay,
                 "legofeup.rxe is not on the brick (STARTPROGRAM answers 0xC0)");
    app.add_option("--right-motor", command.right_motor, "Output port of the right wheel: A, B, C")
        ->check(CLI::IsMember({"A", "B", "C"}, CLI::ignore_case));
    app.add_option("--left-motor", command.left_motor, "Output port of the left wheel: A, B, C")
        ->check(CLI::IsMember({"A", "B", "C"}, CLI::ignore_case));
    app.add_option("--front-ir", command.front_ir, "Input port of the front IR sensor: 1–4")
        ->check(CLI::Range(1, 4));
    app.add_option("--rear-ir", command.rear_ir, "Input port of the rear IR sensor: 1–4")
        ->check(CLI::Range(1, 4));
    app.add_flag("--reversed-motors", command.reversed_motors,
                 "Positive power drives the robot backwards");
    app.add_option("--drop-after", command.drop_after,
                   "Pull the plug this many seconds after the first telegram (once)")
        ->check(CLI::PositiveNumber);
    app.add_option("--freeze-after", command.freeze_after,
                   "Stop answering (but keep reading) this many seconds after the first "
                   "telegram, for the rest of that connection")
        ->check(CLI::PositiveNumber);
    app.add_option("--ready-file", command.ready_file,
                   "Write the ports and paths here as JSON once serving");
    app.add_option("--duration", command.duration,
                   "Stop after this many real seconds (0: run until Ctrl-C)")
        ->check(CLI::NonNegativeNumber);
    app.add_flag("--quiet,-q", command.quiet, "Print only errors");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);  // prints help, the version, or the error
        return code == 0 ? 0 : kExitBadOptions;
    }
    if (!command.pty_link.empty()) {
        command.pty = true;
    }
    return run_emulator(command);
}
