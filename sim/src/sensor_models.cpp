#include "sensor_models.hpp"

#include <algorithm>
#include <cmath>

#include "legofeup/core/angles.hpp"

namespace legofeup::sim {

std::int16_t gyro_raw(const GyroSpec& spec, double rate, double bias, double noise) {
    const double span = spec.range_dps * spec.counts_per_dps;
    const double value =
        std::round(spec.offset + radians_to_degrees(rate) * spec.counts_per_dps + bias + noise);
    return static_cast<std::int16_t>(
        std::clamp(value, std::round(spec.offset - span), std::round(spec.offset + span)));
}

std::int16_t accelerometer_raw(const AccelerometerSpec& spec, double specific_force, double bias,
                               double noise) {
    const double span = std::floor(spec.range_g * spec.counts_per_g);
    const double value =
        std::round(specific_force / spec.gravity * spec.counts_per_g + bias + noise);
    return static_cast<std::int16_t>(std::clamp(value, -span, span));
}

std::int16_t compass_raw(double heading, double disturbance_deg, double noise_deg) {
    const double measured = radians_to_degrees(heading) + disturbance_deg + noise_deg;
    double degrees = std::round(std::fmod(measured, 360.0));  // (−360, 360) before rounding
    if (degrees < 0.0) {
        degrees += 360.0;
    }
    return static_cast<std::int16_t>(degrees >= 360.0 ? degrees - 360.0 : degrees);
}

Vector2 mount_specific_force(const Vector2& velocity_before, const Vector2& velocity_after,
                             double heading_before, double heading_after, double dt) {
    const Vector2 world = (velocity_after - velocity_before) / dt;
    const double middle = 0.5 * (heading_before + heading_after);
    const double c = std::cos(middle);
    const double s = std::sin(middle);
    return {c * world.x() + s * world.y(), -s * world.x() + c * world.y()};  // Rᵀ(θ_mid)·a
}

}  // namespace legofeup::sim
