#pragma once
// One kind of link a run can take the robot over (a simulator server over UDP, a LEGO NXT
// over Bluetooth, a serial port or TCP): the addresses it takes, and how an address becomes
// a plan that connects. The kinds are listed once, in link_registry.hpp; the CLI's --link
// and every robot the GUI offers go through that list, so a new kind of link is its own
// files plus one entry there, and nothing above asks which kind it got: the connection
// says what it can do (RobotConnection::capabilities) and how it is doing (health).

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "legofeup/lessons/robot_connection.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// What a user asked for: an address as typed (`--link`, the GUI's address) and the
/// options that go with some kinds. An option is named as the CLI names it.
struct LinkRequest {
    std::string address;    ///< "udp://127.0.0.1:5600", "bt:00:16:53:01:02:03", "tcp:host:port"
    bool relay = false;     ///< --relay: the NXT's relay program (docs/nxt.md)
    std::string truth_url;  ///< --truth udp://HOST:PORT: an emulated brick's ground truth
    int truth_port = 0;     ///< --truth-port: a simulator's truth port (0: robot port + 1)
    int control_port = 0;   ///< --control-port: its control port (0: robot port + 2)
};

/// A link named and checked but not yet taken.
class LinkPlan {
  public:
    LinkPlan() = default;
    virtual ~LinkPlan() = default;
    LinkPlan(const LinkPlan&) = delete;
    LinkPlan& operator=(const LinkPlan&) = delete;

    /// Where the robot is, as the run log and the messages name it ("udp://127.0.0.1:5600",
    /// "tcp:127.0.0.1:7000").
    virtual std::string describe() const = 0;
    /// A robot profile's wiring, motor constant and relay program (docs/calibration.md); a
    /// simulated robot has no wiring and keeps none of it. Its geometry and IR curve go to
    /// the loop, whatever the link (apply_robot_profile(profile, LoopConfig&)).
    virtual void apply_profile(const RobotProfile& profile) = 0;
    /// Takes the robot for `run` (on this thread; may take seconds). Throws comms::LinkError
    /// saying what failed and what to do.
    virtual std::unique_ptr<RobotConnection> connect(const ResolvedRun& run) const = 0;
};

/// One entry of the registry.
struct LinkKind {
    std::string_view name;  ///< "udp", "nxt": summary.json's link "kind"
    /// The addresses it takes, for help texts and for the error that lists every kind.
    std::string_view forms;
    /// Whether `address` is one of this kind's (its scheme; the plan checks the rest).
    bool (*takes)(std::string_view address);
    /// The plan for a request whose address this kind takes. Throws InputError naming the
    /// option and its value (a malformed address, an option this kind cannot use).
    std::unique_ptr<LinkPlan> (*plan)(const LinkRequest& request);
    /// Throws InputError when `request`, for a link of another kind (or lockstep), gives an
    /// option that only this kind uses (the NXT's --relay and --truth).
    void (*refuse_own_options)(const LinkRequest& request);
};

}  // namespace legofeup::lessons
