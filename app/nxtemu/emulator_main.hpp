#pragma once
// legofeup-nxt-emu's command line, parsed, and the program behind it.

#include <cstdint>
#include <optional>
#include <string>

namespace legofeup::nxtemu_app {

struct EmulatorCommand {
    std::optional<int> tcp_port;  ///< 0: a free port
    bool allow_remote = false;
    bool pty = false;
    std::string pty_link;
    std::optional<double> latency_ms;
    std::optional<double> latency_up_ms;
    std::optional<double> latency_down_ms;
    std::string experiment;
    std::string config_file;
    std::optional<std::uint64_t> seed;
    int battery_mv = 7800;
    bool no_relay = false;
    std::optional<double> drop_after;
    std::optional<double> freeze_after;
    std::string ready_file;
    bool quiet = false;
    double duration = 0.0;  ///< real seconds; 0: until Ctrl-C
    std::string right_motor = "C";
    std::string left_motor = "B";
    int front_ir = 1;
    int rear_ir = 2;
    bool reversed_motors = false;
};

/// Exit codes: 0 after a clean stop, 2 for bad options or configuration, 1 when the emulator
/// cannot start (a port in use, no pseudo-terminals, …).
inline constexpr int kExitBadOptions = 2;
int run_emulator(const EmulatorCommand& command);

}  // namespace legofeup::nxtemu_app
