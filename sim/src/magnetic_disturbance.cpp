#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::sim {

// d(p) = A/3 · [sin(k·e₀·p) + sin(k·e₆₀·p) + cos(k·e₁₂₀·p)], k = 2π/λ, e_α = (cos α, sin α).
// Since e₁₂₀ = e₆₀ − e₀, the third phase is the difference of the first two (plus π/2 for
// the cosine), so all three terms reach 1 together (at k·e₀·p ≡ k·e₆₀·p ≡ π/2): the largest
// |d| is exactly A. Each term's gradient is at most A/3·k, so |∇d| ≤ A·k.
double magnetic_disturbance_deg(const MagneticDisturbance& field, const Vector2& position) {
    if (field.amplitude_deg == 0.0) {
        return 0.0;
    }
    const double k = 2.0 * kPi / field.wavelength;
    const double half_sqrt3 = 0.5 * std::sqrt(3.0);
    const double along_0 = position.x();                                       // e₀·p
    const double along_60 = 0.5 * position.x() + half_sqrt3 * position.y();    // e₆₀·p
    const double along_120 = -0.5 * position.x() + half_sqrt3 * position.y();  // e₁₂₀·p
    return field.amplitude_deg / 3.0
           * (std::sin(k * along_0) + std::sin(k * along_60) + std::cos(k * along_120));
}

}  // namespace legofeup::sim
