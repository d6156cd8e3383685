#pragma once
// The simulated world as plain data: what a world file describes. Box2D never appears in
// this header (or any other public header of sim/).

#include <memory>
#include <string>
#include <vector>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup::sim {

/// A smooth indoor disturbance of the compass heading (steel in the floor, cables, radiators:
/// paper 004), as a field over the floor. It is the sum of three plane waves of the same
/// wavelength travelling at 0°, 60° and 120° with fixed phases (docs/sensors.md):
///   d(p) = A/3 · [sin(k·e₀·p) + sin(k·e₆₀·p) + cos(k·e₁₂₀·p)],  k = 2π/λ,
/// whose largest |d| over the plane is exactly A.
struct MagneticDisturbance {
    double amplitude_deg = 0.0;  ///< A: the largest heading error it causes, ° (0 = none)
    double wavelength = 3.0;     ///< λ, m: how fast it varies across the floor
};

/// The disturbance d(p) of the compass heading at `position`, degrees (added to the true
/// heading). Smooth: |∇d| ≤ A·2π/λ per metre.
double magnetic_disturbance_deg(const MagneticDisturbance& field, const Vector2& position);

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
    /// Bearing-only beacons the scanner can see (ids 0–255, unique); none by default.
    BeaconMap beacons;
    /// The compass's disturbance field; none by default.
    MagneticDisturbance magnetic;
    /// An occupancy-grid map (paper 001) whose occupied cells are solid in the world, beside
    /// the walls; none by default. Shared read-only (the filter may use the same map).
    std::shared_ptr<const OccupancyGrid> map;
    /// The map the robot's filter is given, as surveyed: coarser than the world it describes
    /// (resources/maps/office.pgm for the office as built). None: the filter is given `map`.
    /// The simulator does not use it.
    std::shared_ptr<const OccupancyGrid> surveyed_map;
};

/// Everything wrong with a world the simulator would run in: duplicate beacon ids, ids
/// outside 0–255, non-finite positions, a negative amplitude or non-positive wavelength; and
/// for a map: no cells, more than 10000 cells a side, a resolution outside 0.01 … 10 m, an
/// origin beyond ±1000 m (or a yaw beyond ±2π), an extent over 1000 m a side (Box2D computes
/// in floats) or a start pose inside an occupied cell.
/// Fields are named "world.beacon[<i>].id", "world.magnetic.amplitude_deg",
/// "world.map.resolution", "world.map.origin.x", ...
std::vector<ConfigIssue> validate(const WorldSpec& world);

/// The standard LegoFeup arena of the paper, built from the scenario's numbers, with four
/// beacons (ids 1–4, 0.1 m inside the corners of the walls' bounding box, counter-clockwise
/// from the lower left) and a 12° magnetic disturbance of 3 m wavelength. Runs read it
/// from resources/worlds/standard_arena.toml (lessons::built_in_world); a test keeps the two
/// the same.
WorldSpec standard_arena();

/// The square path of a world as FollowPath segments (corners CCW from the lower left).
std::vector<PathSegment> world_square_path(const WorldSpec& world);

}  // namespace legofeup::sim
