#pragma once
// The 360° bearing-only beacon scanner (paper 002) at the robot's axle midpoint. Private to
// sim/.

#include <box2d/box2d.h>

#include <cstdint>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/sim/sensor_specs.hpp"
#include "noise_streams.hpp"

namespace legofeup::sim {

class BeaconScanner {
  public:
    explicit BeaconScanner(std::uint64_t seed)
        : detection_(seed, NoiseStream::BeaconDetection),
          bearing_noise_(seed, NoiseStream::BeaconBearing) {}

    /// One scan. For every beacon of `beacons_by_id` (sorted by id) it draws one detection
    /// and one bearing noise sample whatever happens, so the realisation does not depend on
    /// the geometry. A beacon is reported when detected (probability p) and in line of sight
    /// (no wall between the axle midpoint and the beacon), at most kMaxBeaconSightings, as
    /// wrap(atan2(Δy, Δx) − θ + σ·n).
    BeaconScan scan(const BeaconScannerSpec& spec, const BeaconMap& beacons_by_id,
                    const b2World& world, const b2Body& chassis);

  private:
    UniformStream detection_;
    GaussianStream bearing_noise_;
};

}  // namespace legofeup::sim
