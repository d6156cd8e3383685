#pragma once
// Independent, seeded random streams, one per noise source. Each stream's seed is derived
// from the run's seed and the stream's number (SplitMix64), so switching one noise source on
// or off never changes the realisation of another, and the same seed always gives the same
// numbers from the same binary.

#include <cstdint>
#include <random>

#include "legofeup/core/splitmix64.hpp"

namespace legofeup::sim {

enum class NoiseStream : std::uint64_t {
    IrFront = 1,
    IrRear = 2,
    SlipRight = 3,
    SlipLeft = 4,
    // The further lessons' sensors (docs/sensors.md): new numbers, so the streams above keep
    // their realisations whichever of these sensors is on.
    BeaconDetection = 5,
    BeaconBearing = 6,
    GyroNoise = 7,
    GyroBias = 8,
    AccelNoise = 9,
    AccelBias = 10,
    CompassNoise = 11,
    LaserRange = 12,    ///< the laser scanner's Gaussian range noise, one sample per beam
    LaserDropout = 13,  ///< the laser scanner's dropouts, one uniform sample per beam
    // The realistic IR model's units (sim/ir_sensor_model.hpp): gain and offset of each
    // sensor, drawn at every reset whichever model is on.
    IrUnitFront = 14,
    IrUnitRear = 15,
};

/// The engine seed of one stream of a run.
inline std::uint64_t stream_seed(std::uint64_t run_seed, NoiseStream stream) {
    return splitmix64(run_seed ^ splitmix64(static_cast<std::uint64_t>(stream)));
}

class GaussianStream {
  public:
    GaussianStream(std::uint64_t run_seed, NoiseStream stream)
        : engine_(stream_seed(run_seed, stream)) {}

    /// A standard normal sample.
    double next() { return unit_(engine_); }

  private:
    std::mt19937_64 engine_;
    std::normal_distribution<double> unit_{0.0, 1.0};
};

class UniformStream {
  public:
    UniformStream(std::uint64_t run_seed, NoiseStream stream)
        : engine_(stream_seed(run_seed, stream)) {}

    /// A sample uniform in [0, 1).
    double next() { return unit_(engine_); }

  private:
    std::mt19937_64 engine_;
    std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

}  // namespace legofeup::sim
