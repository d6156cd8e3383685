#pragma once
// The further lessons' simulated sensors (papers 002, 003, 004): what each one is like and how
// noisy. Each is off unless enabled, so runs that do not ask for them are unchanged. Their
// noise models, with formulas, are in docs/sensors.md.

#include <string>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/state.hpp"

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

/// A laser rangefinder modelled on the Hokuyo URG-04LX (paper 001): 682 beams over 240°,
/// one scan every 100 ms, ranges in whole millimetres from 20 mm to range_max, each beam a
/// closest-hit ray cast in the world. Range noise is Gaussian with σ = sigma_near up to
/// `noise_knee` and σ = sigma_relative·range beyond (≈10 mm under 1 m, 1 % beyond).
/// Beyond the range: kRangeNoEcho; nearer than range_min: kRangeTooNear; a beam drops out
/// (kRangeDropout) with probability dropout_probability.
/// The scan is taken at the pose at the end of the control period in which it completes (no
/// motion distortion), and that period's frame carries it (docs/sensors.md).
struct LaserScannerSpec {
    bool enabled = false;
    ScanGeometry geometry;
    Pose2 mount{};                     ///< the scanner's pose on the robot (robot frame)
    double scan_period = 0.1;          ///< s; a whole number of control periods
    double sigma_near = 0.01;          ///< m, σ of the range noise up to noise_knee
    double noise_knee = 1.0;           ///< m
    double sigma_relative = 0.01;      ///< σ/range beyond noise_knee
    double dropout_probability = 0.0;  ///< per beam that would report a distance
};

/// Everything wrong with a laser scanner (fields "<prefix>.<name>", the geometry's
/// "<prefix>.geometry.<name>"): the geometry (validate(ScanGeometry)), range_min of at least
/// 0.02 m (so every distance reads ≥ 20 mm, above the error codes), a finite mount, a scan
/// period of 1 ms … 10 s, noise σ of 0 … 1 m (relative 0 … 1), a probability in [0, 1]. That
/// an enabled scanner's period is a whole number of control periods is checked with the
/// settings (validate(RobotSpec, SimulatorSettings), simulator.hpp).
std::vector<ConfigIssue> validate(const LaserScannerSpec& spec, const std::string& prefix);

}  // namespace legofeup::sim
