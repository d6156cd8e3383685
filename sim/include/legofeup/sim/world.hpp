#pragma once
// The simulated world as plain data: what a world file describes. Box2D never appears in
// this header (or any other public header of sim/).

#include <string>
#include <vector>

#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup::sim {

/// A world: named walls (thin, two-sided, reflecting exactly on their line), the robot's
/// usual start pose and the path the standard routine follows there.
struct WorldSpec {
    std::string name;
    std::vector<Wall> walls;
    Pose2 start{-1.0, -1.0, 0.0};
    /// The square path of the world: side and centre. The robot drives it counter-clockwise
    /// from its lower-left corner.
    double path_side = 2.0;
    Vector2 path_centre = Vector2::Zero();
};

/// The standard LegoFeup arena of the paper, built from the scenario's numbers. Runs read it
/// from resources/worlds/standard_arena.toml (lessons::built_in_world); a test keeps the two
/// the same.
WorldSpec standard_arena();

/// The square path of a world as FollowPath segments (corners CCW from the lower left).
std::vector<PathSegment> world_square_path(const WorldSpec& world);

}  // namespace legofeup::sim
