#pragma once
// The NXT's part of `legofeup-cli run` (docs/nxt.md): --link bt:…|serial:…|tcp:…, --relay,
// --truth and the robot profile's wiring. nxt_choice.cpp has it in a build with the NXT
// (LEGOFEUP_WITH_NXT); in one without, no_nxt_choice.cpp refuses those options as bad input.

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "commands.hpp"
#include "legofeup/lessons/robot_connection.hpp"
#include "legofeup/lessons/robot_profile.hpp"

namespace legofeup::cli {

/// The brick a run drives, real or emulated, ready to connect.
class NxtChoice {
  public:
    NxtChoice() = default;
    virtual ~NxtChoice() = default;
    NxtChoice(const NxtChoice&) = delete;
    NxtChoice& operator=(const NxtChoice&) = delete;

    /// Its address as the link names it ("bt:00:16:53:01:02:03").
    virtual std::string address() const = 0;
    /// The robot profile's wiring, motor constant and relay program (its geometry and IR
    /// curve go to the loop).
    virtual void apply_profile(const lessons::RobotProfile& profile) = 0;
    /// Connects (on this thread; may take seconds). Throws comms::LinkError.
    virtual std::unique_ptr<lessons::RobotConnection> connect() const = 0;
    /// What summary.json says of the link before the run's health: kind, address, mode, truth.
    virtual nlohmann::json to_json() const = 0;
};

/// The NXT `options` name, or null when their --link names none. Throws InputError naming the
/// option and its value: an address or a --truth the link cannot use; in a build without the
/// NXT, any NXT link, --relay or --truth.
std::unique_ptr<NxtChoice> choose_nxt(const RunOptions& options);

}  // namespace legofeup::cli
