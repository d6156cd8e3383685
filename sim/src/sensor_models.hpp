#pragma once
// The further lessons' sensor models as pure functions: true quantity + noise → the raw value
// the hardware reports (docs/sensors.md). Private to sim/.

#include <cstdint>

#include "legofeup/core/state.hpp"
#include "legofeup/sim/sensor_specs.hpp"

namespace legofeup::sim {

/// Gyroscope: round(offset + ω[°/s]·counts_per_dps + bias + noise), clamped at
/// offset ± range_dps·counts_per_dps. `rate` in rad/s, bias and noise in counts.
std::int16_t gyro_raw(const GyroSpec& spec, double rate, double bias, double noise);

/// One accelerometer axis: round(f/g·counts_per_g + bias + noise), clamped at
/// ±range_g·counts_per_g. `specific_force` in m/s², bias and noise in counts.
std::int16_t accelerometer_raw(const AccelerometerSpec& spec, double specific_force, double bias,
                               double noise);

/// Compass: round(wrap₃₆₀(θ[°] + disturbance + noise)) in whole degrees [0, 360).
std::int16_t compass_raw(double heading, double disturbance_deg, double noise_deg);

/// Specific force at a point fixed on the robot, in the robot's frame ([0] forward, [1] left),
/// from the point's world velocities at the start and end of a step of `dt` seconds and the
/// headings then: (v₁ − v₀)/dt rotated by −θ_mid, θ_mid = (θ₀ + θ₁)/2 (the direction of the
/// chord of a circular arc, exact for constant ω).
Vector2 mount_specific_force(const Vector2& velocity_before, const Vector2& velocity_after,
                             double heading_before, double heading_after, double dt);

}  // namespace legofeup::sim
