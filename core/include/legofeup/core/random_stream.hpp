#pragma once
// The particle filter's own random numbers: uniforms on [0, 1) and standard normals from
// one seeded stream. std::mt19937_64 is specified to the bit by the C++ standard, so a seed
// gives the same stream on every compiler and library; the normals are our own polar
// Box–Muller (Marsaglia's method) because std::normal_distribution's algorithm is left to
// each library. A run's seed reaches the stream through the loop (LoopConfig::random_seed),
// so a run with the particle filter is bit-identical for the same seed, whatever --jobs.

#include <cmath>
#include <cstdint>
#include <random>

namespace legofeup {

class RandomStream {
  public:
    explicit RandomStream(std::uint64_t seed = 1) { reseed(seed); }

    void reseed(std::uint64_t seed) {
        engine_.seed(seed);
        have_spare_ = false;
    }

    /// Uniform on [0, 1): the top 53 bits of one draw, scaled by 2⁻⁵³ (every double of the
    /// form k·2⁻⁵³ equally likely).
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

    /// Standard normal. Marsaglia's polar method: (u, v) uniform in the unit disc,
    /// s = u² + v²; then u·√(−2 ln s / s) and v·√(−2 ln s / s) are independent N(0, 1).
    /// The second is kept for the next call.
    double normal() {
        if (have_spare_) {
            have_spare_ = false;
            return spare_;
        }
        double u = 0.0;
        double v = 0.0;
        double s = 0.0;
        do {
            u = 2.0 * uniform() - 1.0;
            v = 2.0 * uniform() - 1.0;
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        const double factor = std::sqrt(-2.0 * std::log(s) / s);
        spare_ = v * factor;
        have_spare_ = true;
        return u * factor;
    }

  private:
    std::mt19937_64 engine_;
    double spare_ = 0.0;
    bool have_spare_ = false;
};

}  // namespace legofeup
