#pragma once
// A run on a LEGO NXT (docs/nxt.md): `legofeup-cli run --link bt:…|serial:…|tcp:…` and the
// GUI's "NXT robot" link. The brick may be real or emulated (legofeup-nxt-emu); with an
// emulated brick the simulator's truth stream can be given for metrics.

#include <memory>
#include <optional>
#include <string>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/comms/nxt/nxt_link.hpp"
#include "legofeup/lessons/nxt_link_text.hpp"  // is_nxt_link
#include "legofeup/lessons/robot_connection.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

struct NxtTarget {
    comms::nxt::NxtLinkOptions link;
    /// An emulated brick's ground truth (its simulator's truth port); unset for a real robot.
    std::optional<comms::Endpoint> truth;
};

/// The target for `--link TEXT [--relay] [--truth udp://HOST:PORT]`. Throws InputError naming
/// the option and the value.
NxtTarget parse_nxt_target(const std::string& link, bool relay, const std::string& truth_url);

/// The robot profile's wiring, motor constant and relay program name (docs/calibration.md);
/// its geometry and IR curve go to the loop with apply_robot_profile(profile, LoopConfig&).
void apply_robot_profile(const RobotProfile& profile, NxtTarget& target);

/// Connects to the brick (on this thread; may take seconds), sets it up and returns the
/// connection. Throws comms::LinkError saying what failed and what to do.
std::unique_ptr<RobotConnection> connect_nxt(const NxtTarget& target);

}  // namespace legofeup::lessons
