#pragma once
// The particle filter's own random numbers: uniforms on [0, 1) and standard normals from
// one seeded stream. The generator is xoshiro256** (Blackman & Vigna, "Scrambled linear
// pseudorandom number generators", ACM TOMS 47(4), 2021): 256 bits of state, period
// 2²⁵⁶ − 1, passes BigCrush, and costs a few shifts and two multiplications a draw, where
// std::mt19937_64 was a tenth of the motion sampling's time. Its state starts from the seed
// through splitmix64 (the authors' recommended seeding), so a seed gives the same stream on
// every compiler and library; the normals are our own (the ziggurat below) because
// std::normal_distribution's algorithm is left to each library. A
// run's seed reaches the stream through the loop (LoopConfig::random_seed), so a run with
// the particle filter is bit-identical for the same seed, whatever --jobs.
//
// Why a ziggurat: the filter draws two or three normals per particle and step (10,000
// particles: 30,000 per step), and the polar method needs a logarithm, a square root and
// 1.27 draws per normal (21 % of its pairs are rejected). With xoshiro256** and
// small_angle_sincos it took the motion sampling from 105 to 58 ns a particle
// (bench/filters_bench.cpp, BM_PfMotionSampling). The ziggurat (Marsaglia &
// Tsang, "The Ziggurat Method for Generating Random Variables", J. Stat. Softw. 5(8), 2000)
// covers the density f(x) = exp(−x²/2) with 256 layers of equal area V: layer i is the
// rectangle [0, xᵢ] × [f(xᵢ), f(xᵢ₊₁)] (x₁ = r, the base layer 0 is [0, r] × [0, f(r)] plus
// the tail beyond r, given the width x₀ = V / f(r)). One 64-bit draw picks a layer (its low
// 8 bits), a sign and a position x = u·xᵢ, u ∈ [−1, 1) (its top 53 bits). When |x| < xᵢ₊₁
// the point lies under the curve whatever its height: x is returned at once (98.5 % of
// draws). Otherwise the layer's wedge is tested with a second uniform (layers ≥ 1), or the
// tail beyond r is sampled exactly (Marsaglia 1964: x = −ln(u₁)/r, y = −ln(u₂), accepted
// when 2y > x²; layer 0). Every accepted x is exactly N(0, 1)-distributed.

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "legofeup/core/splitmix64.hpp"

namespace legofeup {

class RandomStream {
  public:
    explicit RandomStream(std::uint64_t seed = 1) { reseed(seed); }

    /// The four state words are four successive outputs of splitmix64 from the seed (never
    /// all zero, the one state xoshiro cannot leave).
    void reseed(std::uint64_t seed) {
        for (std::uint64_t& word : state_) {
            word = splitmix64(seed);
            seed += kSplitMix64Increment;
        }
    }

    /// A stream from its four state words as they are (not all zero): for known-answer
    /// tests against the generator's published definition.
    static RandomStream from_state(const std::array<std::uint64_t, 4>& state) {
        RandomStream stream;
        stream.state_ = state;
        return stream;
    }

    /// The next 64 random bits, as the generator gives them.
    std::uint64_t bits() { return next(); }

    /// Uniform on [0, 1): the top 53 bits of one draw, scaled by 2⁻⁵³ (every double of the
    /// form k·2⁻⁵³ equally likely).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

    /// Standard normal, by the ziggurat (above).
    double normal() {
        const ZigguratTables& table = tables();
        for (;;) {
            const std::uint64_t bits = next();
            const std::size_t layer = bits & 0xffU;
            const double u = static_cast<double>(bits >> 11) * 0x1.0p-52 - 1.0;  // [−1, 1)
            const double x = u * table.x[layer];
            if (std::abs(x) < table.x[layer + 1]) {
                return x;  // inside the layer's rectangle that lies wholly under the curve
            }
            if (layer == 0) {
                return u < 0.0 ? -tail() : tail();
            }
            // The wedge between xᵢ₊₁ and xᵢ: a uniform height in [f(xᵢ), f(xᵢ₊₁)].
            const double height =
                table.f[layer] + uniform() * (table.f[layer + 1] - table.f[layer]);
            if (height < std::exp(-0.5 * x * x)) {
                return x;
            }
        }
    }

  private:
    static constexpr std::size_t kLayers = 256;
    static constexpr double kTailStart = 3.6541528853610088;  // r (Marsaglia & Tsang, n = 256)
    static constexpr double kLayerArea = 4.92867323399e-3;    // V

    struct ZigguratTables {
        std::array<double, kLayers + 1> x{};  // xᵢ: x₀ the base's width, x₁ = r, x₂₅₆ = 0
        std::array<double, kLayers + 1> f{};  // f(xᵢ) = exp(−xᵢ²/2); f₀ = 0, f₂₅₆ = 1
    };

    /// The layers' edges: each layer has area V, so f(xᵢ₊₁) = f(xᵢ) + V / xᵢ.
    static const ZigguratTables& tables() {
        static const ZigguratTables computed = [] {
            ZigguratTables t;
            const auto density = [](double x) { return std::exp(-0.5 * x * x); };
            t.x[1] = kTailStart;
            t.f[1] = density(kTailStart);
            t.x[0] = kLayerArea / t.f[1];
            t.f[0] = 0.0;
            for (std::size_t i = 1; i + 1 < kLayers; ++i) {
                t.f[i + 1] = t.f[i] + kLayerArea / t.x[i];
                t.x[i + 1] = std::sqrt(-2.0 * std::log(t.f[i + 1]));
            }
            t.x[kLayers] = 0.0;
            t.f[kLayers] = 1.0;
            return t;
        }();
        return computed;
    }

    /// |x| given |x| > r: Marsaglia's exact tail sampler.
    double tail() {
        for (;;) {
            const double x = -std::log(1.0 - uniform()) / kTailStart;  // 1 − u ∈ (0, 1]
            const double y = -std::log(1.0 - uniform());
            if (2.0 * y > x * x) {
                return kTailStart + x;
            }
        }
    }

    /// xoshiro256**: the output scrambles word 1 (×5, rotate by 7, ×9); the state advances
    /// by the generator's linear shift-and-rotate recurrence.
    std::uint64_t next() {
        const std::uint64_t result = std::rotl(state_[1] * 5, 7) * 9;
        const std::uint64_t shifted = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= shifted;
        state_[3] = std::rotl(state_[3], 45);
        return result;
    }

    std::array<std::uint64_t, 4> state_{};
};

}  // namespace legofeup
