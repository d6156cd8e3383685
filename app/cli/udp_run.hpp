#pragma once
// `legofeup-cli run --link udp://HOST:PORT`: the same run as the lockstep one, against a
// running legofeup-sim (docs/protocol.md) instead of the in-process simulator.

#include <string>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/lessons/link_run.hpp"

namespace legofeup::cli {

struct UdpTarget {
    comms::Endpoint robot;
    comms::Endpoint truth;
    comms::Endpoint control;
};

/// Parses "udp://a.b.c.d[:port]"; truth and control default to port+1 and port+2.
/// Throws lessons::InputError naming the option for anything else.
UdpTarget parse_udp_target(const std::string& url, int truth_port, int control_port);

struct UdpRunReport {
    lessons::RunResult result;
    comms::ServerStatus server;  ///< the server's status and counters after the run
    std::uint64_t frames_received = 0;
    std::uint64_t frames_duplicate = 0;
    std::uint64_t frames_late = 0;
    std::uint64_t frames_timed_out = 0;
};

/// Checks the server runs the run's control period, gives it the run's noise, takes the
/// robot, resets it to the run's seed and true start, and runs. Throws comms::LinkError
/// (or lessons::LinkSilent) with what went wrong and what to do.
UdpRunReport run_over_udp(const lessons::ResolvedRun& run, const UdpTarget& target,
                          lessons::RunObserver* observer,
                          const lessons::ProgressCallback& progress);

}  // namespace legofeup::cli
