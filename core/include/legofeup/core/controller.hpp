#pragma once
// The routine the control module is running: one of the paper's routines or manual driving
// (keyboard), held by value so switching routines never allocates in the loop step.

#include <cstdint>
#include <variant>

#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/path_controllers.hpp"
#include "legofeup/core/visit_waypoints.hpp"

namespace legofeup {

/// Remote driving: whatever (V, W) the user last set, limited to ±V_ref and ±W_ref.
class ManualDrive {
  public:
    void set_command(const VelocityCommand& command) { command_ = command; }
    const VelocityCommand& command() const { return command_; }
    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains) const;

  private:
    VelocityCommand command_;
};

using Controller =
    std::variant<ManualDrive, GoXYTheta, FollowLine, FollowCircle, FollowPath, VisitWaypoints>;

enum class ControllerKind : std::uint8_t {
    Manual,
    GoXYTheta,
    FollowLine,
    FollowCircle,
    FollowPath,
    VisitWaypoints
};

ControllerKind kind_of(const Controller& controller);
const char* to_string(ControllerKind kind);

/// What the control module did this period, for the snapshot.
struct ControllerStatus {
    ControllerKind kind = ControllerKind::Manual;
    bool finished = false;
    int segment = -1;  ///< FollowPath: segment being followed; VisitWaypoints: waypoint index
    int lap = 0;       ///< FollowPath, VisitWaypoints: laps completed
    double cross_track_error = 0.0;
    double heading_error = 0.0;
};

/// Runs the active routine for one period (`period`, s: how long the command will be
/// applied; the routines that wait, VisitWaypoints, count it) and reports its command and
/// status.
ControlOutput run_controller(Controller& controller, const Pose2& estimate,
                             const MotionLimits& limits, const ControllerGains& gains,
                             double period, ControllerStatus& status);

}  // namespace legofeup
