#pragma once
// The further lessons' simulated sensors (papers 002, 003, 004): what each one is like and how
// noisy. Each is off unless enabled, so runs that do not ask for them are unchanged. Their
// noise models, with formulas, are in docs/sensors.md.

#include <string>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/config_issue.hpp"

namespace legofeup::sim {

/// 360° bearing-only scanner at the axle midpoint (paper 002). Each scan sees each beacon
/// in line of sight with probability `detection_probability`, and reports its bearing from
/// the heading plus Gaussian noise.
struct BeaconScannerSpec {
    bool enabled = false;
    double period = 0.05;                       ///< s between scans (one per 50 ms control period)
    double detection_probability = 0.5;         ///< per beacon per scan (the paper's 50 %)
    double bearing_noise = 0.6266570686577501;  ///< σ, rad: √(π/8), the paper's variance π/8
};

/// Single-axis rate gyroscope (HiTechnic-like): raw = round(offset + rate·counts_per_dps +
/// bias + noise), clamped at offset ± range_dps·counts_per_dps.
struct GyroSpec {
    bool enabled = false;
    double offset = 600.0;        ///< raw value at rest with no bias, counts
    double counts_per_dps = 1.0;  ///< counts per °/s, counter-clockwise positive
    double range_dps = 360.0;     ///< saturation, °/s
    double noise = 1.0;           ///< σ of white noise per reading, counts
    double bias_sigma = 0.5;      ///< σ of the bias drawn at reset, counts
    double bias_drift = 0.01;     ///< random walk of the bias, counts/√s
};

/// Two two-axis accelerometers, one over each wheel (paper 003), axis 0 forward, axis 1 to
/// the left: raw = round(specific force/g·counts_per_g + bias + noise), clamped at ±range_g.
struct AccelerometerSpec {
    bool enabled = false;
    double counts_per_g = 200.0;
    double range_g = 2.0;      ///< saturation, g
    double noise = 2.0;        ///< σ of white noise per reading and axis, counts
    double bias_sigma = 0.5;   ///< σ of each axis's constant bias drawn at reset, counts
    double gravity = 9.80665;  ///< g, m/s²
};

/// Magnetic compass: whole degrees [0, 360), counter-clockwise from the world's x axis, with
/// the world's disturbance field and Gaussian noise.
struct CompassSpec {
    bool enabled = false;
    double noise_deg = 1.0;  ///< σ, degrees (before the 1° quantisation)
};

/// Everything wrong with each spec; fields are named "<prefix>.<name>".
std::vector<ConfigIssue> validate(const BeaconScannerSpec& spec, const std::string& prefix);
std::vector<ConfigIssue> validate(const GyroSpec& spec, const std::string& prefix);
std::vector<ConfigIssue> validate(const AccelerometerSpec& spec, const std::string& prefix);
std::vector<ConfigIssue> validate(const CompassSpec& spec, const std::string& prefix);

}  // namespace legofeup::sim
