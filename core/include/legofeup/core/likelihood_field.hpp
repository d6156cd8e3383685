#pragma once
// The laser measurement model of Monte Carlo localisation: the likelihood field (Thrun,
// Burgard & Fox, Probabilistic Robotics, §6.4, Table 6.3 likelihood_field_range_finder_model).
//
// A beam's end point is scored by how far it lies from the nearest obstacle of the map, not
// by ray casting the beam: the expected range would need one ray cast per beam and particle
// (bench/scan_bench: ~200 ns a ray in the office map, against ~8 ns an end point here), and
// its likelihood is not smooth in the pose (a beam grazing a corner jumps from the near wall
// to the far one). The field instead precomputes, once per map, the distance from every cell
// to the nearest occupied cell; scoring a scan at a pose is then a transform, a look-up and
// an exp per end point:
//
//   1. the end points z_k of the beams with a measured range, in the robot frame
//      (scan_endpoints: x_k = M ⊕ (z_k cos α_k, z_k sin α_k), M the scanner's mount);
//      beams without a range (no echo — the book's max-range readings — too near, dropout)
//      are skipped, as the book skips z_k = z_max;
//   2. each end point in the world at the pose x = (x, y, θ): p_k = x ⊕ x_k;
//   3. dist_k = the field's distance at p_k (max_distance outside the map);
//   4. q = Π_k (z_hit · N(dist_k; 0, σ_hit²) + z_random / z_max), returned as
//      log q = Σ_k log(z_hit · N(dist_k; 0, σ_hit²) + z_random / z_max),
//      a log because the factors (0.018 … 3.6 with the default parameters) of a few hundred
//      end points multiply out of a double's range, and because particle weights are
//      normalised in log space.
//
// The book's z_max is the scanner's range_max (ScanGeometry::range_max), an argument of
// scan_log_likelihood rather than a parameter of the model: the scanner knows it, and a
// copy in the model's parameters could disagree with it.
//
// The field (Felzenszwalb & Huttenlocher, "Distance Transforms of Sampled Functions",
// Theory of Computing 8, 2012): the squared Euclidean distance transform
//   D(p) = min_q (‖p − q‖² + f(q)),  f(q) = 0 at occupied cells, ∞ elsewhere,
// is separable: a 1-D transform along every column, then one along every row of the
// result. Each 1-D transform is the lower envelope of the parabolas (p − q)² + f(q), found
// in one left-to-right sweep, so the whole field costs O(cells) and is exact — distances
// between cell centres, as a brute-force search over every occupied cell gives them.
// Unknown cells are not obstacles. Distances are clamped at max_distance: beyond a few
// σ_hit the Gaussian term is nothing next to z_random / z_max, so farther is no different,
// and the clamp is what a point outside the map (no obstacle known there) receives.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

/// The likelihood field model's parameters (Table 6.3's z_hit, z_random, σ_hit) and the
/// subsampling of the scan.
///
/// z_hit and z_random are relative weights, normalised by their sum: the model uses
/// z_hit / (z_hit + z_random) and z_random / (z_hit + z_random), so the mixture is a density
/// whatever they add up to (0.9 and 0.3 are 0.75 and 0.25). Either may be 0, not both.
struct LikelihoodFieldParams {
    double sigma_hit = 0.1;  ///< m: standard deviation of a measured end point about the obstacle
    double z_hit = 0.9;      ///< weight of the Gaussian about the nearest obstacle
    double z_random = 0.1;   ///< weight of the uniform density 1 / z_max (random readings)
    int beam_stride = 8;     ///< use every k-th beam (neighbouring beams are not independent)
    double max_distance = 2.0;  ///< m: the field's distances clamp here

    friend bool operator==(const LikelihoodFieldParams&, const LikelihoodFieldParams&) = default;
};

/// Everything wrong with the parameters (fields "<prefix>.sigma_hit", ...): finite values,
/// 1e-6 ≤ σ_hit ≤ 100 m (a micrometre is far below any cell; σ_hit → 0 would overflow
/// 1/σ_hit²), 0 ≤ z_hit, z_random ≤ 1 and not both 0, 1 ≤ beam_stride ≤ kMaxScanBeams,
/// 0 < max_distance ≤ 100 m.
std::vector<ConfigIssue> validate(const LikelihoodFieldParams& params, const std::string& prefix);

/// The distance from every cell of an occupancy grid to the nearest occupied cell (see the
/// file comment). Built once per map; read-only afterwards, so one field may be shared
/// between threads. Keeps its own copy of the grid (1 byte a cell) next to the field
/// (4 bytes a cell).
class LikelihoodField {
  public:
    /// An empty field: no grid, every point max_distance (2 m) from an obstacle.
    LikelihoodField() = default;
    /// The field of `grid`, distances clamped at `max_distance` (m). Throws
    /// std::invalid_argument when max_distance is not positive and finite.
    LikelihoodField(OccupancyGrid grid, double max_distance);

    /// Distance (m) from the centre of the cell containing `world` (world frame) to the
    /// nearest occupied cell's centre, at most max_distance; max_distance outside the grid
    /// (and for a non-finite point). Values are stored as float: within 1e-7 relative.
    double distance_at(const Vector2& world) const;
    /// The same for a cell of the grid (max_distance outside it).
    double distance_at(const GridCell& cell) const;

    const OccupancyGrid& grid() const { return grid_; }
    int width() const { return grid_.width(); }
    int height() const { return grid_.height(); }
    double resolution() const { return grid_.resolution(); }  ///< m per cell
    /// The clamp, m, as given. The field's values are floats: max_distance is stored as
    /// static_cast<float>(max_distance), which distance_at also returns outside the grid.
    double max_distance() const { return max_distance_; }
    /// False when the grid has no occupied cell (every distance is then max_distance).
    bool has_obstacles() const { return has_obstacles_; }

    /// The distances, row-major from the bottom row, width·height of them (for the scorer
    /// and for views).
    std::span<const float> distances() const { return distances_; }
    /// The value distance_at returns outside the grid: max_distance as a float.
    float outside_distance() const { return outside_distance_; }

  private:
    OccupancyGrid grid_;
    double max_distance_ = 2.0;
    float outside_distance_ = 2.0F;
    bool has_obstacles_ = false;
    std::vector<float> distances_;
};

/// Step 1: the end points, in the ROBOT frame, of beams 0, k, 2k, … (k = beam_stride; < 1 is
/// taken as 1) that have a valid range (range_of: error codes, no echo and ranges outside
/// [range_min, range_max] are skipped). `mount` is the scanner's pose in the robot frame.
/// Beams past min(scan.beam_count, geometry.beam_count) are ignored. Clears `out` first;
/// does not allocate once `out` has kMaxScanBeams capacity.
void scan_endpoints(const LaserScan& scan, const ScanGeometry& geometry, const Pose2& mount,
                    int beam_stride, std::vector<Vector2>& out);

/// Steps 2–4: log p(z | x, m) = Σ_k log(z_hit · N(dist_k; 0, σ_hit²) + z_random / range_max)
/// of the end points at the robot pose `robot_pose` (world frame), with z_hit and z_random
/// normalised by their sum; 0 for no end points. `range_max` is the scanner's z_max
/// (ScanGeometry::range_max). Preconditions: validate(params) is empty, range_max is
/// positive and finite. params.beam_stride and params.max_distance are not used here (they
/// belong to scan_endpoints and the field).
/// Cost: one exp per end point (bench/scan_bench: ~8 ns an end point on a 2.6 GHz Xeon,
/// about half of it the exp). The sum is taken as the log of the product of the factors,
/// renormalised as it goes: a log at most every ~85 end points with the default parameters
/// instead of one each. When z_random is 0 (or so small that the factors could underflow)
/// each term is a log-sum-exp instead, finite however many σ_hit an end point lies from an
/// obstacle. The pose's cos and sin are taken once; the end points land in the cells
/// distance_at(transform_point(robot_pose, x_k)) finds (but within ~1e-15 m of a cell
/// boundary, where rounding may pick the neighbour). No allocation.
double scan_log_likelihood(const LikelihoodField& field, const Pose2& robot_pose,
                           std::span<const Vector2> endpoints_in_robot_frame,
                           const LikelihoodFieldParams& params, double range_max);

/// One scan as the particle filter's measurement (PoseEstimator::update(ScanLikelihood)): its
/// end points in the robot frame (scan_endpoints), scored against `field` by
/// scan_log_likelihood. Views only: valid while the loop's step runs.
struct ScanLikelihood {
    const LikelihoodField& field;
    std::span<const Vector2> endpoints;
    const LikelihoodFieldParams& params;
    double range_max;  ///< m: the scanner's, the book's z_max
};

}  // namespace legofeup
