#pragma once
// A robot taken for a run, whatever it is: a simulator server over UDP, or a LEGO NXT (real
// or emulated) over Bluetooth, a serial port or TCP. The CLI's runs and the GUI's live runs
// talk to this, so the loop runs on the robot exactly as on the simulator. A connection says
// what it can do (capabilities) and how it is doing (health): callers ask it, they never
// decide from the kind of link.

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "legofeup/core/robot_link.hpp"
#include "legofeup/core/truth_source.hpp"
#include "legofeup/lessons/link_health.hpp"

namespace legofeup::lessons {

class RobotConnection {
  public:
    virtual ~RobotConnection() = default;

    /// Frames in, wheel commands out.
    virtual RobotLink& robot_link() = 0;
    /// Where the ground truth comes from; nullptr for a real robot (nobody knows its pose).
    virtual TruthSource* truth_source() = 0;
    /// A simulated robot's noise (E_d, E_b, slip, IR), live. A real robot ignores it.
    virtual void set_noise(const RobotNoise& noise) = 0;
    /// A simulator stops its clock; a real robot stops its motors and ignores wheel commands
    /// until resumed (its clock cannot stop: frames keep coming, the robot stands still).
    virtual void set_paused(bool paused) = 0;
    /// Lifts a simulated robot to `pose` (a kidnapping; the filter is not told) and returns
    /// an empty string. A real robot cannot be lifted: it returns why and changes nothing.
    /// Throws comms::LinkError when the simulator refuses the pose or does not answer.
    virtual std::string teleport(const Pose2& pose) = 0;
    /// Stops the motors and lets the robot go (once; never throws).
    virtual void close() = 0;
    /// "udp://127.0.0.1:5600", "NXT at bt:00:16:53:01:02:03 (direct commands)".
    virtual std::string describe() const = 0;
    /// What it can do: truth, live noise, teleport, a stopping clock, a robot's own health.
    virtual LinkCapabilities capabilities() const = 0;
    /// How it is doing now (state, address, counters, battery where there is one).
    virtual LinkHealth health() const = 0;
    /// What summary.json says of the link after the run (docs/cli.md): its "kind" (the
    /// registry's name), where it went, and its own counters; after close().
    virtual nlohmann::json summary() = 0;
};

}  // namespace legofeup::lessons
