#pragma once
// The state space of the 5-state EKF of paper 003 §3.4: X = [x, y, θ, v, ω] (m, m, rad,
// m/s, rad/s), θ wrapped to (−π, π].

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "legofeup/core/angle_mean.hpp"
#include "legofeup/core/angles.hpp"

namespace legofeup {

/// Named indices into the motion state (never index with bare numbers).
enum MotionIndex : int { kMotionX = 0, kMotionY, kMotionTheta, kMotionV, kMotionW };
inline constexpr int kMotionStateSize = 5;

using MotionStateVector = Eigen::Matrix<double, kMotionStateSize, 1>;
using MotionCovariance = Eigen::Matrix<double, kMotionStateSize, kMotionStateSize>;

struct MotionStateSpace {
    static constexpr int kSize = kMotionStateSize;

    static void normalize(MotionStateVector& x) { x(kMotionTheta) = wrap_angle(x(kMotionTheta)); }

    /// a − b with the heading difference wrapped.
    static MotionStateVector difference(const MotionStateVector& a, const MotionStateVector& b) {
        MotionStateVector d = a - b;
        d(kMotionTheta) = wrap_angle(d(kMotionTheta));
        return d;
    }

    /// Weighted mean of sigma points: Σ wᵢ·Xᵢ, the heading as in angle_mean.hpp.
    template <std::size_t K>
    static MotionStateVector weighted_mean(const std::array<MotionStateVector, K>& points,
                                           const std::array<double, K>& weights) {
        MotionStateVector mean = MotionStateVector::Zero();
        for (std::size_t i = 0; i < K; ++i) {
            mean += weights[i] * points[i];
        }
        mean(kMotionTheta) = weighted_angle_mean(points, weights, kMotionTheta);
        return mean;
    }
};

}  // namespace legofeup
