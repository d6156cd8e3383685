#pragma once
// Raw readings of the further lessons' sensors → SI units, as the filters believe the
// sensors to be calibrated (ExtraSensorCalibration). The simulator's sensor models are the
// ground truth of these conversions; a miscalibration here is a lesson, not a bug.

#include <cstdint>

#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/motion.hpp"

namespace legofeup {

/// Gyroscope: (raw − offset) / (counts per °/s), in rad/s, counter-clockwise positive.
double gyro_rate_from_raw(std::int16_t raw, const ExtraSensorCalibration& calibration);

/// Accelerometer axis: raw / (counts per g) · g, in m/s².
double accel_from_raw(std::int16_t raw, const ExtraSensorCalibration& calibration);

/// Compass: whole degrees counter-clockwise from the world's x axis (SensorFrame::compass_deg)
/// → the heading θ in rad, wrapped to (−π, π] (so 270° reads −π/2 and 180° reads π).
double compass_heading_from_raw(std::int16_t degrees);

/// The body's linear and angular accelerations from the forward accelerations measured over
/// the right and left wheels (paper 003 eq. 14 differentiated):
///   a = (a_R + a_L)/2,   α = (a_R − a_L)/b
/// (the paper writes 1/(2r) with r half the wheel base, i.e. 1/b). Returned as
/// VelocityCommand{v = a (m/s²), w = α (rad/s²)}.
VelocityCommand body_acceleration(double a_right, double a_left, double wheel_base);

}  // namespace legofeup
