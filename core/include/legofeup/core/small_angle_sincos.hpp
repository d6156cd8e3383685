#pragma once
// sin a and cos a at once for the angles the particle filter sums over every step (the
// circular mean of 10,000 headings, relative to one of them: |a| < 2π). libm's sincos was
// a fifth of the filter's motion step; this one is a few multiplications, and within
// 2·10⁻¹⁶ of it (a test checks 10⁶ angles).
//
// The maths: a = k·π/2 + r with k = round(a·2/π) and |r| ≤ π/4, r computed with π/2 split
// into a 33-bit head (so that k·head is exact for |k| < 2²⁰) and its tail (Cody & Waite).
// On |r| ≤ π/4 the Taylor series
//   sin r = r − r³/3! + r⁵/5! − … − r¹⁵/15!,  cos r = 1 − r²/2! + r⁴/4! − … + r¹⁶/16!
// leave out less than (π/4)¹⁷/17! ≈ 5·10⁻¹⁷. Then by the quadrant k mod 4,
//   (sin a, cos a) = (sin r, cos r), (cos r, −sin r), (−sin r, −cos r), (−cos r, sin r).
// a = 0 gives exactly (0, 1).

#include <array>
#include <cstdint>

namespace legofeup {

struct SinCos {
    double sin;
    double cos;
};

/// sin a and cos a for |a| ≤ 1000 (the reduction's error grows with k; the filter's angles
/// are below 2π).
inline SinCos small_angle_sincos(double a) {
    constexpr double kTwoOverPi = 0.63661977236758134308;
    constexpr double kHalfPiHead = 1.57079632673412561417;      // π/2 to 33 bits
    constexpr double kHalfPiTail = 6.07710050650619224932e-11;  // π/2 − head
    // round(a·2/π) to the nearest integer, ties to even: adding and subtracting 1.5·2⁵²
    // drops every bit below the units (exact IEEE arithmetic; the project builds without
    // -ffast-math, which would fold it away). std::nearbyint is a libm call without SSE4.1.
    constexpr double kRoundingShift = 0x1.8p52;
    const double k = (a * kTwoOverPi + kRoundingShift) - kRoundingShift;
    const double r = (a - k * kHalfPiHead) - k * kHalfPiTail;
    const double r2 = r * r;
    // Horner in r²: sin r = r + r·r²·(c₁ + r²·(c₂ + …)), cos r = 1 + r²·(d₁ + r²·(d₂ + …)),
    // with cₙ = (−1)ⁿ/(2n+1)! and dₙ = (−1)ⁿ/(2n)!.
    constexpr std::array<double, 7> kSinCoefficients = {
        -1.0 / 6.0,        1.0 / 120.0,        -1.0 / 5040.0,         1.0 / 362880.0,
        -1.0 / 39916800.0, 1.0 / 6227020800.0, -1.0 / 1307674368000.0};
    constexpr std::array<double, 8> kCosCoefficients = {-0.5,
                                                        1.0 / 24.0,
                                                        -1.0 / 720.0,
                                                        1.0 / 40320.0,
                                                        -1.0 / 3628800.0,
                                                        1.0 / 479001600.0,
                                                        -1.0 / 87178291200.0,
                                                        1.0 / 20922789888000.0};
    const auto horner = [r2](const auto& coefficients) {
        double sum = coefficients.back();
        for (auto c = coefficients.rbegin() + 1; c != coefficients.rend(); ++c) {
            sum = *c + r2 * sum;
        }
        return sum;
    };
    const double sin_r = r + r * r2 * horner(kSinCoefficients);
    const double cos_r = 1.0 + r2 * horner(kCosCoefficients);
    switch (static_cast<std::int64_t>(k) & 3) {
        case 0:
            return {sin_r, cos_r};
        case 1:
            return {cos_r, -sin_r};
        case 2:
            return {-sin_r, -cos_r};
        default:
            return {-cos_r, sin_r};
    }
}

}  // namespace legofeup
