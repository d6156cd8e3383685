#pragma once
// A drawable sample of the particle filter's cloud: what the GUI's arena draws (one dot per
// point, its opacity the point's weight) without copying, storing or painting 10,000
// particles every frame.
//
// Thinning: of N particles, every k-th, k = ⌈N / max_points⌉, starting at the first. The
// cloud's order favours no place — resampling (Table 4.4) writes the copies of each survivor
// next to one another in the order of the old cloud, and free-space draws land anywhere — so
// a stride is a systematic sample of the cloud: a cluster whose particles lie together (as
// resampling leaves them) holds its share of the points to within one point, and one whose
// particles are scattered through the cloud holds it as a random sample would.
//
// Weights: each point keeps its particle's weight divided by the largest weight among the
// points shown, so the heaviest point has weight 1 and, right after a resampling (all weights
// equal), every point has 1. (Relative, not absolute: 1/N would fade every dot of a large
// cloud to nothing.)

#include <cstddef>
#include <span>
#include <vector>

namespace legofeup {

struct ParticlePoint {
    float x = 0.0F;       ///< m, world frame
    float y = 0.0F;       ///< m
    float theta = 0.0F;   ///< rad
    float weight = 0.0F;  ///< relative to the heaviest point shown: (0, 1]
};

/// The particles the GUI shows of a cloud at most (a cloud of 10,000 is drawn as 1,000 dots).
inline constexpr std::size_t kParticlesShown = 1000;

/// Fills `out` (cleared first) with at most `max_points` (≥ 1) points of the cloud given as
/// columns of equal length (see the top of this file). Points of non-finite position or
/// weight are left out.
void thin_particles(std::span<const double> xs, std::span<const double> ys,
                    std::span<const double> thetas, std::span<const double> weights,
                    std::size_t max_points, std::vector<ParticlePoint>& out);

}  // namespace legofeup
