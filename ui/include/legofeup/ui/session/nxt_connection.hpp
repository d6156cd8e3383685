#pragma once
// How a run takes a LEGO NXT (LinkKind::Nxt): the brick at the address typed (nxt_address.hpp)
// or an emulated brick inside the application to rehearse with, driven over loopback TCP
// through the whole NXT path. session/nxt_connection.cpp has it in a build with the NXT
// (LEGOFEUP_WITH_NXT); in one without, session/no_nxt_connection.cpp offers none:
// nxt_supported() is false, and the window shows no NXT to choose.

#include <QString>
#include <memory>

#include "legofeup/lessons/links/link_kind.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::ui {

struct LinkChoice;

/// Whether this build drives an NXT.
bool nxt_supported();

/// An emulated brick serving a run (on its simulated robot); destroying it switches it off.
class EmulatedBrick {
  public:
    EmulatedBrick() = default;
    virtual ~EmulatedBrick() = default;
    EmulatedBrick(const EmulatedBrick&) = delete;
    EmulatedBrick& operator=(const EmulatedBrick&) = delete;
};

/// What a run on an NXT needs before it starts.
struct NxtConnection {
    /// The link to the brick, from the link registry (its nxt entry), with the profile's
    /// wiring; the run connects it on its worker thread. Null when there is none (see problem).
    std::unique_ptr<lessons::LinkPlan> plan;
    /// The emulated brick, when the choice rehearses with one: kept while the run lasts.
    std::unique_ptr<EmulatedBrick> emulated_brick;
    /// Why there is no connection, in the user's words; empty when there is one.
    QString problem;
};

/// The connection `choice` names, with the wiring, motor constant and relay program of
/// `profile` (null: the nominal robot's). An emulated brick is started at once, on the
/// simulated robot, world, noise and seed of `config`, on a free loopback TCP port.
NxtConnection prepare_nxt_connection(const LinkChoice& choice, const lessons::RobotProfile* profile,
                                     const lessons::RunConfig& config);

}  // namespace legofeup::ui
