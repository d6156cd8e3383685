#include "legofeup/sim/sensor_specs.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace legofeup::sim {
namespace {

// Raw values travel as int16 in the frame.
constexpr double kRawLimit = std::numeric_limits<std::int16_t>::max();

}  // namespace

std::vector<ConfigIssue> validate(const BeaconScannerSpec& spec, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range(prefix + ".period", spec.period, 0.001, 10.0);
    check.in_range(prefix + ".detection_probability", spec.detection_probability, 0.0, 1.0);
    check.in_range(prefix + ".bearing_noise", spec.bearing_noise, 0.0, kPi);
    return issues;
}

std::vector<ConfigIssue> validate(const GyroSpec& spec, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range(prefix + ".counts_per_dps", spec.counts_per_dps, 0.01, 100.0);
    check.in_range(prefix + ".range_dps", spec.range_dps, 1.0, 10000.0);
    check.in_range(prefix + ".noise", spec.noise, 0.0, 1000.0);
    check.in_range(prefix + ".bias_sigma", spec.bias_sigma, 0.0, 1000.0);
    check.in_range(prefix + ".bias_drift", spec.bias_drift, 0.0, 100.0);
    const double span = spec.range_dps * spec.counts_per_dps;
    check.require(std::isfinite(spec.offset) && std::abs(spec.offset) + span <= kRawLimit,
                  prefix + ".offset", spec.offset,
                  "offset ± range_dps·counts_per_dps must fit in −32767…32767");
    return issues;
}

std::vector<ConfigIssue> validate(const AccelerometerSpec& spec, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range(prefix + ".counts_per_g", spec.counts_per_g, 1.0, 10000.0);
    check.in_range(prefix + ".range_g", spec.range_g, 0.1, 100.0);
    check.in_range(prefix + ".noise", spec.noise, 0.0, 1000.0);
    check.in_range(prefix + ".bias_sigma", spec.bias_sigma, 0.0, 1000.0);
    check.in_range(prefix + ".gravity", spec.gravity, 1.0, 100.0);
    check.require(!(spec.range_g * spec.counts_per_g > kRawLimit), prefix + ".range_g",
                  spec.range_g, "range_g·counts_per_g must fit in 32767");
    return issues;
}

std::vector<ConfigIssue> validate(const CompassSpec& spec, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range(prefix + ".noise_deg", spec.noise_deg, 0.0, 180.0);
    return issues;
}

std::vector<ConfigIssue> validate(const LaserScannerSpec& spec, const std::string& prefix) {
    std::vector<ConfigIssue> issues = validate(spec.geometry, prefix + ".geometry");
    ConfigChecker check(issues);
    // Distances below 20 mm would read as error codes (kRangeFirstValid).
    check.require(!(spec.geometry.range_min < static_cast<double>(kRangeFirstValid) / 1000.0),
                  prefix + ".geometry.range_min", spec.geometry.range_min,
                  "must be at least 0.02 m (shorter distances read as error codes)");
    check.in_range(prefix + ".mount.x", spec.mount.x, -10.0, 10.0);
    check.in_range(prefix + ".mount.y", spec.mount.y, -10.0, 10.0);
    check.in_range(prefix + ".mount.theta", spec.mount.theta, -2.0 * kPi, 2.0 * kPi);
    check.in_range(prefix + ".scan_period", spec.scan_period, 0.001, 10.0);
    check.in_range(prefix + ".sigma_near", spec.sigma_near, 0.0, 1.0);
    check.in_range(prefix + ".noise_knee", spec.noise_knee, 0.0, 100.0);
    check.in_range(prefix + ".sigma_relative", spec.sigma_relative, 0.0, 1.0);
    check.in_range(prefix + ".dropout_probability", spec.dropout_probability, 0.0, 1.0);
    return issues;
}

}  // namespace legofeup::sim
