#pragma once
// Where the two IR sensors sit on the robot and what they see (paper Fig. 6).
//
// Both sensors are on the robot's right side and look along −90° in the robot frame
// (robot frame: x forward, y to the left). Sensor 1 (reading d_s1) is the front one and
// sensor 2 (d_s2) the rear one; they are L apart along the robot's axis, so a robot turned
// away from the wall reads d_s1 > d_s2 and ObsAng = atan((d_s1 − d_s2)/L) > 0.

#include <array>

#include "legofeup/core/state.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup {

enum IrSensor : int { kFrontSensor = 0, kRearSensor = 1 };
inline constexpr int kIrSensorCount = 2;

struct IrMount {
    double front_longitudinal = 0.05;  ///< sensor 1 position along the robot's x axis, metres
    double rear_longitudinal = -0.05;  ///< sensor 2 position along the robot's x axis, metres
    double lateral_offset = 0.06;      ///< distance of both sensors from the centre line, metres

    /// L: the separation of the two sensors along the robot's axis (eq. 3).
    double separation() const { return front_longitudinal - rear_longitudinal; }
    /// m: where the midpoint between the sensors sits along the robot's axis.
    double midpoint() const { return 0.5 * (front_longitudinal + rear_longitudinal); }
    double longitudinal(int sensor) const {
        return sensor == kFrontSensor ? front_longitudinal : rear_longitudinal;
    }
};

/// A sensor's beam in the world: where it starts and which way it points (unit vector).
struct IrBeam {
    Vector2 origin = Vector2::Zero();
    Vector2 direction = Vector2::UnitX();
};

IrBeam ir_beam(const Pose2& pose, const IrMount& mount, int sensor);
/// Both sensors' beams, indexed by IrSensor: the same bits as ir_beam for each, with one
/// cosine and sine of the heading between them (the wall association's hot path).
std::array<IrBeam, kIrSensorCount> ir_beams(const Pose2& pose, const IrMount& mount);

/// Where a beam meets a wall's line.
struct BeamHit {
    bool hit = false;    ///< in front of the sensor and within the segment (± margin)
    double range = 0.0;  ///< distance from the sensor along the beam, metres
    double along = 0.0;  ///< position of the hit along the wall from its start, metres
};

/// Intersects a beam with a wall. `segment_margin` widens the segment at both ends, so a
/// prediction from a slightly wrong estimate still finds the wall it is next to.
BeamHit cast_beam(const IrBeam& beam, const WallLine& wall, double segment_margin);

/// Paper eq. 3 with the sensors' mounting offsets: d_s1, d_s2 → (ObsAng, d_w) and the
/// distance from the robot centre to the wall.
///
///   ObsAng = atan((d_s1 − d_s2) / L)
///   d_w    = (d_s1 + d_s2)/2 · cos(ObsAng)                       (sensor line to wall)
///   D_c    = d_w + e·cos(ObsAng) − m·sin(ObsAng)                 (robot centre to wall)
///
/// with e the lateral offset and m the sensors' midpoint along the axis. The formula for D_c
/// is exact for two parallel beams perpendicular to the robot axis hitting a straight wall.
struct WallObservation {
    double ds_front = 0.0;         ///< d_s1, metres
    double ds_rear = 0.0;          ///< d_s2, metres
    double angle = 0.0;            ///< ObsAng, radians
    double sensor_distance = 0.0;  ///< d_w, metres
    double centre_distance = 0.0;  ///< D_c, metres
    /// ∂(D_c, ObsAng)/∂(d_s1, d_s2): row 0 is D_c, row 1 is ObsAng (paper eq. 18–19).
    Eigen::Matrix2d jacobian = Eigen::Matrix2d::Zero();
};

WallObservation observe_wall(double ds_front, double ds_rear, const IrMount& mount);

}  // namespace legofeup
