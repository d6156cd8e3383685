#pragma once
// SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators",
// OOPSLA 2014): one step of its Weyl sequence (+ the golden-ratio increment γ) and its
// finaliser, a well-mixed 64-bit value from any 64-bit input. The simulator derives its noise
// streams' seeds from it (sim/src/noise_streams.hpp), and the particle filter's stream fills
// its state with successive outputs, splitmix64(s), splitmix64(s + γ), … (random_stream.hpp).

#include <cstdint>

namespace legofeup {

/// SplitMix64's increment γ = 2⁶⁴ / φ, odd.
inline constexpr std::uint64_t kSplitMix64Increment = 0x9E3779B97F4A7C15ULL;

/// SplitMix64's output for the state `value`: mix(value + γ).
constexpr std::uint64_t splitmix64(std::uint64_t value) {
    value += kSplitMix64Increment;
    value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
    value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
    return value ^ (value >> 31);
}

}  // namespace legofeup
