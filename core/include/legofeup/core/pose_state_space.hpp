#pragma once
// The state space of the LegoFeup filter: X = [x, y, θ] with θ wrapped to (−π, π].

#include "legofeup/core/angles.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct PoseStateSpace {
    static constexpr int kSize = kStateSize;

    static void normalize(StateVector& x) { x(kTheta) = wrap_angle(x(kTheta)); }

    /// a − b with the heading difference wrapped (used for errors, NEES and sigma points).
    static StateVector difference(const StateVector& a, const StateVector& b) {
        return {a(kX) - b(kX), a(kY) - b(kY), wrap_angle(a(kTheta) - b(kTheta))};
    }
};

}  // namespace legofeup
