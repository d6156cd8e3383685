#pragma once
// The state space of the LegoFeup filter: X = [x, y, θ] with θ wrapped to (−π, π].

#include <array>
#include <cstddef>

#include "legofeup/core/angle_mean.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct PoseStateSpace {
    static constexpr int kSize = kStateSize;

    static void normalize(StateVector& x) { x(kTheta) = wrap_angle(x(kTheta)); }

    /// a − b with the heading difference wrapped (sigma points; a pose's error against the
    /// truth is pose_error.hpp's).
    static StateVector difference(const StateVector& a, const StateVector& b) {
        return {a(kX) - b(kX), a(kY) - b(kY), wrap_angle(a(kTheta) - b(kTheta))};
    }

    /// The weighted mean of sigma points (UKF, paper 002 eq. 14; weights sum to 1):
    /// positions by Σ wᵢ·pᵢ, the heading by the wrapped-difference mean of angle_mean.hpp.
    template <std::size_t K>
    static StateVector weighted_mean(const std::array<StateVector, K>& points,
                                     const std::array<double, K>& weights) {
        StateVector mean = StateVector::Zero();
        for (std::size_t i = 0; i < K; ++i) {
            mean += weights[i] * points[i];
        }
        mean(kTheta) = weighted_angle_mean(points, weights, kTheta);
        return mean;
    }
};

}  // namespace legofeup
