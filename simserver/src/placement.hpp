#pragma once
// Where a Reset or Teleport request may put the robot (docs/protocol.md, "Where the robot may
// be put"). The chassis, at any heading, lies in the circle of radius r (its reach) around the
// axle midpoint, so a pose is accepted when
//   1. the axle midpoint lies in the world's extent (the bounding box of the walls' end
//      points and of the map, if any) shrunk by r on every side, and
//   2. no wall and no occupied cell of the map comes nearer than r to it.
// The heading plays no part.

#include <string>
#include <string_view>

#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::simserver {

/// r = hypot(max(chassis_front, chassis_rear), chassis_half_width): the farthest the chassis
/// reaches from the axle midpoint, m (0.1063 m for the default robot).
double chassis_reach(const sim::RobotSpec& robot);

/// Rule 1's box: where the axle midpoint may lie, m.
struct PlacementBox {
    double low_x = 0.0;
    double high_x = 0.0;
    double low_y = 0.0;
    double high_y = 0.0;
};
PlacementBox placement_box(const sim::WorldSpec& world, double reach);

/// Why the robot may not be put at `pose`, prefixed by `request` ("teleport", "reset"), or ""
/// if it may. The message names the coordinate and the limits it broke, in at most
/// comms::kReplyMessageMaxBytes bytes for any pose and any world.
std::string placement_problem(const sim::WorldSpec& world, const sim::RobotSpec& robot,
                              const Pose2& pose, std::string_view request);

}  // namespace legofeup::simserver
