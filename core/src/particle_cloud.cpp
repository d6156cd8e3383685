#include "legofeup/core/particle_cloud.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup {

void thin_particles(std::span<const double> xs, std::span<const double> ys,
                    std::span<const double> thetas, std::span<const double> weights,
                    std::size_t max_points, std::vector<ParticlePoint>& out) {
    out.clear();
    const std::size_t count = std::min({xs.size(), ys.size(), thetas.size(), weights.size()});
    if (count == 0 || max_points == 0) {
        return;
    }
    const std::size_t stride = (count + max_points - 1) / max_points;  // ⌈N / max⌉
    const auto shown = [&](std::size_t i) {
        return std::isfinite(xs[i]) && std::isfinite(ys[i]) && std::isfinite(weights[i])
               && weights[i] >= 0.0;
    };
    // Relative weights (divided in double: a weight of 1e-300 is no float): the heaviest
    // shown is 1; all 0, every point is shown as equal.
    double heaviest = 0.0;
    for (std::size_t i = 0; i < count; i += stride) {
        if (shown(i)) {
            heaviest = std::max(heaviest, weights[i]);
        }
    }
    out.reserve((count + stride - 1) / stride);
    for (std::size_t i = 0; i < count; i += stride) {
        if (shown(i)) {
            const double weight = heaviest > 0.0 ? weights[i] / heaviest : 1.0;
            out.push_back({static_cast<float>(xs[i]), static_cast<float>(ys[i]),
                           static_cast<float>(thetas[i]), static_cast<float>(weight)});
        }
    }
}

}  // namespace legofeup
