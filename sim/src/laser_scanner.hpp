#pragma once
// The laser rangefinder (paper 001; Hokuyo URG-04LX-like, docs/sensors.md): one closest-hit
// Box2D ray cast per beam from the scanner's world pose, Gaussian range noise, whole
// millimetres and the URG's error codes. Private to sim/.

#include <box2d/box2d.h>

#include <cstdint>
#include <optional>

#include "legofeup/core/laser_scan.hpp"
#include "legofeup/sim/sensor_specs.hpp"
#include "noise_streams.hpp"

namespace legofeup::sim {

/// σ(d) of the range noise at true distance d: sigma_near up to noise_knee, sigma_relative·d
/// beyond (10 mm under 1 m and 1 % beyond for the URG-04LX).
double laser_range_sigma(const LaserScannerSpec& spec, double distance);

/// One beam's reading from the true distance d to the closest hit (nullopt: nothing within
/// range_max), a standard normal sample n and a uniform sample u in [0, 1):
///   nothing hit                      → kRangeNoEcho
///   r = d + σ(d)·n < range_min       → kRangeTooNear
///   r > range_max                    → kRangeNoEcho
///   u < dropout_probability          → kRangeDropout (only a beam that had a distance)
///   otherwise                        → round(1000·r) mm (≥ 20 since range_min ≥ 0.02 m)
std::uint16_t laser_reading(const LaserScannerSpec& spec, std::optional<double> distance,
                            double normal, double uniform);

class LaserScanner {
  public:
    explicit LaserScanner(std::uint64_t seed)
        : range_noise_(seed, NoiseStream::LaserRange), dropout_(seed, NoiseStream::LaserDropout) {}

    /// One scan from the scanner's pose, chassis pose ⊕ spec.mount, at this instant (no motion
    /// during the sweep). Beam i points at θ_scanner + geometry.angle_of(i); its ray skips the
    /// chassis' own fixtures and stops at range_max. Every beam draws one normal and one
    /// uniform sample whatever it hits, so the realisation never depends on the geometry.
    /// Entries of `out` from beam_count on are zero.
    void scan(const LaserScannerSpec& spec, const b2World& world, const b2Body& chassis,
              LaserScan& out);

  private:
    GaussianStream range_noise_;
    UniformStream dropout_;
};

}  // namespace legofeup::sim
