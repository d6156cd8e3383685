#pragma once
// Small worlds and statistics shared by the simulator's tests.

#include <cmath>
#include <cstddef>
#include <vector>

#include "legofeup/core/state.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::sim::test {

/// A world with no walls, no map and no beacons: the robot alone on the floor at `start`.
inline WorldSpec open_floor(const Pose2& start = {0.0, 0.0, 0.0}) {
    WorldSpec world;
    world.name = "open floor";
    world.start = start;
    return world;
}

/// Sample mean and standard deviation (n − 1 in the denominator) of `values`.
struct SampleStats {
    double mean = 0.0;
    double sd = 0.0;
    std::size_t n = 0;
};

inline SampleStats sample_stats_of(const std::vector<double>& values) {
    SampleStats s;
    s.n = values.size();
    const auto n = static_cast<double>(values.size());
    for (double v : values) {
        s.mean += v / n;
    }
    for (double v : values) {
        s.sd += (v - s.mean) * (v - s.mean) / (n - 1.0);
    }
    s.sd = std::sqrt(s.sd);
    return s;
}

}  // namespace legofeup::sim::test
