#pragma once
// 2-D Iterative Closest Point (paper 001 §III-A.2): finds the rigid transform T that moves a
// source point cloud onto a reference cloud, T·p_src ≈ p_ref. Correspondences come from a
// kd-tree (nanoflann) over the reference; pairs farther apart than the correspondence
// distance are outliers, and the worst `trim_fraction` of the rest are dropped each
// iteration (trimmed ICP). Point-to-point minimises Σ|T·p − q|² (closed form, SVD of the
// 2×2 cross-covariance, which in the plane is one atan2); point-to-line minimises
// Σ(n·(T·p − q))² with the reference normals n (Gauss–Newton on the small-angle
// linearisation, one 3×3 solve per iteration). Point-to-point converges linearly (tens of
// iterations), point-to-line in a handful; docs/scan_matching.md compares them.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

enum class IcpMetric : std::uint8_t { PointToPoint, PointToLine };
const char* to_string(IcpMetric metric);  ///< "point_to_point", "point_to_line"
std::optional<IcpMetric> icp_metric_from_string(std::string_view text);

struct IcpParams {
    IcpMetric metric = IcpMetric::PointToLine;
    int max_iterations = 50;
    /// m: a source point whose nearest reference point is farther than this is an outlier.
    double max_correspondence_distance = 0.3;
    /// Fraction (0 … <1) of the remaining pairs, the worst ones, dropped each iteration.
    double trim_fraction = 0.1;
    /// Converged when one iteration changes the transform by less than both epsilons, or
    /// returns within them to the transform of two iterations before (a pair on the edge of
    /// the rejection flipping in and out makes the iteration alternate between two
    /// transforms).
    double translation_epsilon = 1e-5;  ///< m
    double rotation_epsilon = 1e-5;     ///< rad

    friend bool operator==(const IcpParams&, const IcpParams&) = default;
};

/// Everything wrong with the parameters (fields "<prefix>.max_iterations", ...).
std::vector<ConfigIssue> validate(const IcpParams& params, const std::string& prefix);

struct IcpResult {
    /// T: source point p maps to (x, y) + R(θ)·p in the reference frame.
    Pose2 transform;
    bool converged = false;  ///< the epsilons were met within max_iterations
    int iterations = 0;
    int matched_points = 0;     ///< inlier pairs used in the last iteration
    double rms_residual = 0.0;  ///< m: RMS distance (point-to-point) of those pairs
};

/// Owns the kd-tree and its buffers: set the reference once, align many sources.
/// Buffers keep their capacity, so repeated alignments of scans of the same size do not
/// allocate once warmed up (the kd-tree rebuild in set_reference may).
class Icp2d {
  public:
    explicit Icp2d(IcpParams params = {});
    ~Icp2d();
    Icp2d(Icp2d&&) noexcept;
    Icp2d& operator=(Icp2d&&) noexcept;
    Icp2d(const Icp2d&) = delete;
    Icp2d& operator=(const Icp2d&) = delete;

    void set_params(const IcpParams& params) { params_ = params; }
    const IcpParams& params() const { return params_; }

    /// Copies the points (non-finite ones are skipped) and builds the kd-tree. The
    /// point-to-line normals (total least squares through each point's 5 nearest
    /// neighbours) are computed by the first point-to-line align after it. Fewer than 3
    /// points leave an empty reference: align then fails.
    void set_reference(std::span<const Vector2> reference);
    int reference_size() const;

    /// Aligns `source` onto the reference, starting from `initial_guess`.
    /// Not converged (and matched_points possibly 0) when the reference or source is too
    /// small, when fewer than 3 pairs survive the rejection, or after max_iterations.
    IcpResult align(std::span<const Vector2> source, const Pose2& initial_guess = {});

  private:
    struct Index;
    IcpParams params_;
    std::unique_ptr<Index> index_;
};

}  // namespace legofeup
