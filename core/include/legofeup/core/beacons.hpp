#pragma once
// Bearing-only beacons at known places (paper 002): the map the beacon filter uses and the
// simulator's scanner sees.

#include <vector>

#include "legofeup/core/state.hpp"

namespace legofeup {

struct Beacon {
    int id = 0;                          ///< 0–255, unique in a map; what the scanner reports
    Vector2 position = Vector2::Zero();  ///< world frame, m
};

using BeaconMap = std::vector<Beacon>;

/// The beacon with this id, or nullptr.
inline const Beacon* find_beacon(const BeaconMap& map, int id) {
    for (const Beacon& beacon : map) {
        if (beacon.id == id) {
            return &beacon;
        }
    }
    return nullptr;
}

}  // namespace legofeup
