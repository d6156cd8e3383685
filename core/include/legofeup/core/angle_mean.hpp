#pragma once
// The weighted mean of angles, for the unscented transform's sigma points.
//
// A plain Σ wᵢ·θᵢ is wrong near ±π: headings π − 0.1 and −π + 0.1 average to 0, the
// opposite direction. We average the wrapped differences from a reference angle θ_ref
// (the central sigma point):
//
//   θ̄ = wrap(θ_ref + Σᵢ wᵢ·wrap(θᵢ − θ_ref)),        Σᵢ wᵢ = 1
//
// Why this form and not atan2(Σ wᵢ·sin θᵢ, Σ wᵢ·cos θᵢ): the unscented weights may be
// negative (W₀ = κ/(n+κ) < 0 for κ < 0), and then the weighted resultant vector can shrink
// to nothing or point the wrong way, so the circular mean is undefined or flips by π. The
// difference form is linear in the angles, so a negative weight means what it means for
// positions; it is exact whenever no wrap occurs (then it equals Σ wᵢ·θᵢ, which keeps the
// UKF identical to the EKF on linear models) and needs only that the sigma points lie
// within π of the reference, i.e. a heading spread well under 180°.

#include <array>
#include <cstddef>

#include "legofeup/core/angles.hpp"

namespace legofeup {

/// θ̄ of the formula above; `points[i](index)` is the i-th angle, points[0] the reference.
template <class Point, std::size_t K>
double weighted_angle_mean(const std::array<Point, K>& points, const std::array<double, K>& weights,
                           int index) {
    static_assert(K > 0);
    const double reference = points[0](index);
    double offset = 0.0;
    for (std::size_t i = 1; i < K; ++i) {
        offset += weights[i] * wrap_angle(points[i](index) - reference);
    }
    return wrap_angle(reference + offset);
}

}  // namespace legofeup
