#pragma once
// What legofeup-sim was asked to do, and doing it.

#include <cstdint>
#include <optional>
#include <string>

#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::simserver_app {

struct ServerCommand {
    std::string world_file;  ///< empty: the built-in standard arena
    std::uint64_t seed = 1;
    std::string bind_address = "127.0.0.1";
    int port = 5600;
    std::optional<int> truth_port;
    std::optional<int> control_port;
    double time_scale = 1.0;
    sim::SimulatorSettings settings;
    sim::RobotSpec robot;
    bool allow_remote = false;
    std::string ready_file;
    double duration = 0.0;
    double status_every = 0.0;
    bool quiet = false;
};

/// Serves until Ctrl-C, SIGTERM or the duration. Returns the exit code: 0, or 1 with a
/// message on stderr for bad input (world file, options, a port in use), as legofeup-cli.
int run_server(const ServerCommand& command);

/// --world's check: "" when `value` is a built-in world's name or an existing file, else why
/// not (CLI11's validator convention).
std::string world_name_or_file(const std::string& value);

}  // namespace legofeup::simserver_app
