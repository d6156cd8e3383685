#pragma once
// The subcommands of legofeup-cli. Each returns the process exit code:
// 0 success, 1 invalid input (configuration, files, options), 2 output could not be written,
// 3 the link failed (no simulator answering, robot held by another client, frames stopped).

#include <cstdint>
#include <optional>
#include <string>

#include "config_choice.hpp"

namespace legofeup::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;
inline constexpr int kExitOutputFailed = 2;
inline constexpr int kExitLinkFailed = 3;

struct RunOptions : ConfigChoice {
    std::string out_directory;
    bool plots = true;
    bool quiet = false;
    /// "lockstep" (the in-process simulator), "udp://a.b.c.d:port" (a legofeup-sim), or an
    /// NXT: "bt:XX:XX:XX:XX:XX:XX", "serial:/dev/rfcomm0", "tcp:HOST:PORT" (docs/nxt.md).
    std::string link = "lockstep";
    bool relay = false;     ///< NXT: read through the relay program on the brick
    std::string truth_url;  ///< NXT: an emulated brick's truth stream, udp://HOST:PORT
    std::string profile;    ///< robot profile TOML: geometry and IR curve; NXT wiring
    int truth_port = 0;     ///< 0: the robot port + 1
    int control_port = 0;   ///< 0: the robot port + 2

    /// --record: the run log every step goes to ("": none), docs/recording.md.
    std::string record_file;
};

int run_command(const RunOptions& options);

/// Lists the experiments with their instructions.
int experiments_command();

/// Prints the configuration a run would use, as a TOML file to start from.
int config_command(const RunOptions& options);

}  // namespace legofeup::cli
