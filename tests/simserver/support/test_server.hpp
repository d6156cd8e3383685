#pragma once
// A simulator server on free loopback ports, serving on its own thread, for tests.

#include <memory>

#include "legofeup/lessons/world_file.hpp"
#include "legofeup/simserver/sim_server.hpp"

namespace legofeup::testing {

inline std::unique_ptr<simserver::SimServer> start_test_server(
    double time_scale, simserver::SimServerOptions options = {},
    const sim::WorldSpec& world = lessons::built_in_world()) {
    options.bind = comms::Endpoint{0x7F000001, 0};
    options.time_scale = time_scale;
    auto server = std::make_unique<simserver::SimServer>(world, sim::RobotSpec{},
                                                         sim::SimulatorSettings{}, 1, options);
    server->start();
    return server;
}

inline comms::Endpoint loopback(std::uint16_t port) {
    return {0x7F000001, port};
}

}  // namespace legofeup::testing
