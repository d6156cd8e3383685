#include "laser_scanner.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "box2d_convert.hpp"
#include "ir_ray.hpp"

namespace legofeup::sim {

double laser_range_sigma(const LaserScannerSpec& spec, double distance) {
    return distance <= spec.noise_knee ? spec.sigma_near : spec.sigma_relative * distance;
}

std::uint16_t laser_reading(const LaserScannerSpec& spec, std::optional<double> distance,
                            double normal, double uniform) {
    if (!distance) {
        return kRangeNoEcho;
    }
    const double range = *distance + laser_range_sigma(spec, *distance) * normal;
    const std::uint16_t reading = range_reading(range, spec.geometry);
    // A dropout replaces only a distance (the beam's echo was too weak to measure).
    if (reading >= kRangeFirstValid && uniform < spec.dropout_probability) {
        return kRangeDropout;
    }
    return reading;
}

void LaserScanner::scan(const LaserScannerSpec& spec, const b2World& world, const b2Body& chassis,
                        LaserScan& out) {
    const Vector2 position = from_b2(chassis.GetPosition());
    const Pose2 robot{position.x(), position.y(), static_cast<double>(chassis.GetAngle())};
    const Pose2 scanner = compose(robot, spec.mount);  // T_world_scanner = T_world_robot ⊕ mount
    const b2Vec2 origin = to_b2(scanner.x, scanner.y);
    const ScanGeometry& geometry = spec.geometry;
    const int beams = std::clamp(geometry.beam_count, 0, kMaxScanBeams);
    for (int beam = 0; beam < beams; ++beam) {
        const double angle = scanner.theta + geometry.angle_of(beam);
        const b2Vec2 direction = to_b2(std::cos(angle), std::sin(angle));
        const std::optional<double> distance =
            closest_hit(world, &chassis, origin, direction, geometry.range_max);
        const double normal = range_noise_.next();
        const double uniform = dropout_.next();
        out.range_mm[static_cast<std::size_t>(beam)] =
            laser_reading(spec, distance, normal, uniform);
    }
    out.beam_count = static_cast<std::uint16_t>(beams);
    std::fill(out.range_mm.begin() + beams, out.range_mm.end(), std::uint16_t{0});
}

}  // namespace legofeup::sim
