#include "legofeup/core/ir_geometry.hpp"

#include <cmath>

namespace legofeup {

namespace {

/// The beam of `sensor` from the heading's cosine c and sine s.
IrBeam beam_from_heading(const Pose2& pose, double c, double s, const IrMount& mount, int sensor) {
    const Vector2 forward(c, s);
    const Vector2 right(s, -c);  // the robot's −y axis: where the sensors look
    IrBeam beam;
    beam.origin =
        position_of(pose) + mount.longitudinal(sensor) * forward + mount.lateral_offset * right;
    beam.direction = right;
    return beam;
}

}  // namespace

IrBeam ir_beam(const Pose2& pose, const IrMount& mount, int sensor) {
    return beam_from_heading(pose, std::cos(pose.theta), std::sin(pose.theta), mount, sensor);
}

std::array<IrBeam, kIrSensorCount> ir_beams(const Pose2& pose, const IrMount& mount) {
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    return {beam_from_heading(pose, c, s, mount, kFrontSensor),
            beam_from_heading(pose, c, s, mount, kRearSensor)};
}

BeamHit cast_beam(const IrBeam& beam, const WallLine& wall, double segment_margin) {
    BeamHit result;
    // Line n·p = c, beam p(t) = o + t·u: t = (c − n·o) / (n·u).
    const double approach = wall.normal.dot(beam.direction);
    if (std::abs(approach) < 1e-12) {
        return result;  // beam parallel to the wall
    }
    result.range = -wall.signed_distance(beam.origin) / approach;
    const Vector2 point = beam.origin + result.range * beam.direction;
    result.along = wall.direction.dot(point - wall.start);
    result.hit = result.range > 0.0 && result.along >= -segment_margin
                 && result.along <= wall.length + segment_margin;
    return result;
}

WallObservation observe_wall(double ds_front, double ds_rear, const IrMount& mount) {
    WallObservation obs;
    obs.ds_front = ds_front;
    obs.ds_rear = ds_rear;
    const double separation = mount.separation();    // L
    const double e = mount.lateral_offset;           // sensors' distance from centre line
    const double m = mount.midpoint();               // sensors' midpoint along the axis
    const double difference = ds_front - ds_rear;    // d_s1 − d_s2
    const double mean = 0.5 * (ds_front + ds_rear);  // (d_s1 + d_s2)/2
    obs.angle = std::atan(difference / separation);  // ObsAng (eq. 3)
    const double c = std::cos(obs.angle);
    const double s = std::sin(obs.angle);
    obs.sensor_distance = mean * c;                // d_w (eq. 3)
    obs.centre_distance = (mean + e) * c - m * s;  // D_c

    // Eq. 18: dObsAng/dd_s1 = L / (L² + (d_s1 − d_s2)²) = −dObsAng/dd_s2.
    const double dangle = separation / (separation * separation + difference * difference);
    // D_c = (mean + e)·cos(ObsAng) − m·sin(ObsAng); with ∂mean/∂d_si = ½ and the chain rule
    // through ObsAng (eq. 19 generalised: a = ½cos(ObsAng), b = dD_c/dObsAng · dObsAng/dd_s1).
    const double a = 0.5 * c;
    const double b = (-(mean + e) * s - m * c) * dangle;
    obs.jacobian << a + b, a - b,  //
        dangle, -dangle;
    return obs;
}

}  // namespace legofeup
