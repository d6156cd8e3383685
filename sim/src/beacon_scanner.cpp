#include "beacon_scanner.hpp"

#include <cmath>

#include "box2d_convert.hpp"
#include "ir_ray.hpp"
#include "legofeup/core/angles.hpp"

namespace legofeup::sim {
namespace {

constexpr double kSameSpot = 1e-9;      // m: a beacon under the scanner has no bearing
constexpr double kHitTolerance = 1e-6;  // m: a wall hit this close to the beacon does not hide it

}  // namespace

BeaconScan BeaconScanner::scan(const BeaconScannerSpec& spec, const BeaconMap& beacons_by_id,
                               const b2World& world, const b2Body& chassis) {
    const Vector2 scanner = from_b2(chassis.GetPosition());
    const double heading = static_cast<double>(chassis.GetAngle());
    BeaconScan result;
    for (const Beacon& beacon : beacons_by_id) {
        const bool detected = detection_.next() < spec.detection_probability;
        const double noise = spec.bearing_noise * bearing_noise_.next();
        if (!detected || result.count >= kMaxBeaconSightings) {
            continue;
        }
        const Vector2 offset = beacon.position - scanner;
        const double distance = offset.norm();
        if (distance < kSameSpot) {
            continue;
        }
        // Line of sight: the closest hit on anything but the robot itself, along the segment.
        const double free =
            cast_ir_ray(world, &chassis, to_b2(scanner), to_b2(offset / distance), distance);
        if (free < distance - kHitTolerance) {
            continue;
        }
        BeaconSighting& sighting = result.sightings[result.count++];
        sighting.id = static_cast<std::uint8_t>(beacon.id);
        sighting.bearing = wrap_angle(std::atan2(offset.y(), offset.x()) - heading + noise);
    }
    return result;
}

}  // namespace legofeup::sim
