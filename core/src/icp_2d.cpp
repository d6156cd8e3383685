#include "legofeup/core/icp_2d.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <nanoflann.hpp>

#include "legofeup/core/angles.hpp"

namespace legofeup {

const char* to_string(IcpMetric metric) {
    switch (metric) {
        case IcpMetric::PointToPoint:
            return "point_to_point";
        case IcpMetric::PointToLine:
            return "point_to_line";
    }
    return "unknown";
}

std::optional<IcpMetric> icp_metric_from_string(std::string_view text) {
    for (const IcpMetric value : {IcpMetric::PointToPoint, IcpMetric::PointToLine}) {
        if (text == to_string(value)) {
            return value;
        }
    }
    return std::nullopt;
}

std::vector<ConfigIssue> validate(const IcpParams& params, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    const std::string p = prefix + ".";
    check.in_range(p + "max_iterations", params.max_iterations, 1, 10000);
    check.positive(p + "max_correspondence_distance", params.max_correspondence_distance, 100.0);
    check.in_range(p + "trim_fraction", params.trim_fraction, 0.0, 0.9);
    check.positive(p + "translation_epsilon", params.translation_epsilon, 1.0);
    check.positive(p + "rotation_epsilon", params.rotation_epsilon, 1.0);
    return issues;
}

namespace {

/// nanoflann's dataset adaptor over the reference points.
struct PointCloud {
    std::vector<Vector2> points;

    std::size_t kdtree_get_point_count() const { return points.size(); }
    double kdtree_get_pt(std::uint32_t index, std::size_t dim) const {
        return points[index][static_cast<Eigen::Index>(dim)];
    }
    template <class BoundingBox>
    bool kdtree_get_bbox(BoundingBox& /*box*/) const {
        return false;  // let nanoflann compute it
    }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>,
                                                   PointCloud, 2, std::uint32_t>;

/// Neighbours (the point itself included) whose scatter gives a reference point's normal.
constexpr std::uint32_t kNormalNeighbours = 5;
/// Too few pairs to fix the three degrees of freedom of a planar rigid transform.
constexpr std::size_t kMinPairs = 3;

/// One correspondence: source point, its nearest reference point, their squared distance.
struct Pair {
    std::uint32_t source = 0;
    std::uint32_t reference = 0;
    double distance2 = 0.0;
};

/// The unit normal of the line through `points` (total least squares): the eigenvector of
/// the smaller eigenvalue of their 2×2 scatter matrix C. The major axis lies at angle
/// φ = ½·atan2(2·c_xy, c_xx − c_yy), so the normal is (−sin φ, cos φ).
Vector2 line_normal(const std::array<Vector2, kNormalNeighbours>& points, std::size_t count) {
    Vector2 mean = Vector2::Zero();
    for (std::size_t i = 0; i < count; ++i) {
        mean += points[i];
    }
    mean /= static_cast<double>(count);
    double cxx = 0.0;
    double cxy = 0.0;
    double cyy = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const Vector2 d = points[i] - mean;
        cxx += d.x() * d.x();
        cxy += d.x() * d.y();
        cyy += d.y() * d.y();
    }
    const double phi = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
    return {-std::sin(phi), std::cos(phi)};
}

}  // namespace

struct Icp2d::Index {
    PointCloud reference;
    std::vector<Vector2> normals;  ///< one per reference point, once computed
    bool normals_ready = false;
    KdTree tree{2, reference,
                nanoflann::KDTreeSingleIndexAdaptorParams(
                    10, nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex)};
    std::vector<Pair> pairs;  ///< the current iteration's correspondences (reused)

    /// The nearest reference point of `query`.
    Pair nearest(const Vector2& query) const {
        const std::array<double, 2> q{query.x(), query.y()};
        Pair pair;
        tree.knnSearch(q.data(), 1, &pair.reference, &pair.distance2);
        return pair;
    }

    void compute_normals() {
        const std::size_t n = reference.points.size();
        normals.resize(n);
        const std::uint32_t k =
            std::min<std::uint32_t>(kNormalNeighbours, static_cast<std::uint32_t>(n));
        std::array<std::uint32_t, kNormalNeighbours> indices{};
        std::array<double, kNormalNeighbours> distances{};
        std::array<Vector2, kNormalNeighbours> neighbours;
        for (std::size_t i = 0; i < n; ++i) {
            const Vector2& p = reference.points[i];
            const std::array<double, 2> q{p.x(), p.y()};
            const std::size_t found = tree.knnSearch(q.data(), k, indices.data(), distances.data());
            for (std::size_t j = 0; j < found; ++j) {
                neighbours[j] = reference.points[indices[j]];
            }
            normals[i] = line_normal(neighbours, found);
        }
        normals_ready = true;
    }
};

Icp2d::Icp2d(IcpParams params) : params_(params), index_(std::make_unique<Index>()) {}
Icp2d::~Icp2d() = default;
Icp2d::Icp2d(Icp2d&&) noexcept = default;
Icp2d& Icp2d::operator=(Icp2d&&) noexcept = default;

void Icp2d::set_reference(std::span<const Vector2> reference) {
    if (!index_) {
        index_ = std::make_unique<Index>();
    }
    std::vector<Vector2>& points = index_->reference.points;
    points.clear();
    for (const Vector2& p : reference) {
        if (p.allFinite()) {  // a NaN would poison the tree's bounding boxes
            points.push_back(p);
        }
    }
    if (points.size() < kMinPairs) {
        points.clear();
    }
    index_->tree.buildIndex();
    index_->normals_ready = false;
}

int Icp2d::reference_size() const {
    return index_ ? static_cast<int>(index_->reference.points.size()) : 0;
}

namespace {

/// Point-to-point, closed form (2-D Procrustes; Arun et al.'s SVD of the 2×2 cross-covariance
/// H = Σ (p − p̄)(q − q̄)ᵀ reduces in the plane to one angle with no reflection case):
///   θ = atan2(Σ (p̃ₓq̃ᵧ − p̃ᵧq̃ₓ), Σ (p̃ₓq̃ₓ + p̃ᵧq̃ᵧ)),   t = q̄ − R(θ) p̄,
/// which minimises Σ |R p + t − q|² over the pairs (p from the source in its own frame).
Pose2 solve_point_to_point(std::span<const Vector2> source, std::span<const Vector2> reference,
                           const std::vector<Pair>& pairs) {
    Vector2 p_mean = Vector2::Zero();
    Vector2 q_mean = Vector2::Zero();
    for (const Pair& pair : pairs) {
        p_mean += source[pair.source];
        q_mean += reference[pair.reference];
    }
    p_mean /= static_cast<double>(pairs.size());
    q_mean /= static_cast<double>(pairs.size());
    double sin_sum = 0.0;
    double cos_sum = 0.0;
    for (const Pair& pair : pairs) {
        const Vector2 p = source[pair.source] - p_mean;
        const Vector2 q = reference[pair.reference] - q_mean;
        sin_sum += p.x() * q.y() - p.y() * q.x();
        cos_sum += p.x() * q.x() + p.y() * q.y();
    }
    const double theta = std::atan2(sin_sum, cos_sum);
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    return {q_mean.x() - (c * p_mean.x() - s * p_mean.y()),
            q_mean.y() - (s * p_mean.x() + c * p_mean.y()), theta};
}

/// Point-to-line, one Gauss–Newton step from `pose` = (tₓ, tᵧ, θ). Each pair's residual is
/// eᵢ = nᵢ · (R(θ) pᵢ + t − qᵢ) with Jacobian Jᵢ = [nₓ, nᵧ, nᵢ · R′(θ) pᵢ], where
/// R′(θ) p = (−(Rp)ᵧ, (Rp)ₓ). Solve (Σ JᵢJᵢᵀ) δ = −Σ Jᵢ eᵢ (LDLT, a tiny Levenberg damping keeps
/// it solvable along a corridor, where the normals leave one direction unconstrained).
Pose2 gauss_newton_point_to_line(std::span<const Vector2> source,
                                 std::span<const Vector2> reference,
                                 const std::vector<Vector2>& normals,
                                 const std::vector<Pair>& pairs, const Pose2& pose) {
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (const Pair& pair : pairs) {
        const Vector2& p = source[pair.source];
        const Vector2 rotated(c * p.x() - s * p.y(), s * p.x() + c * p.y());
        const Vector2& n = normals[pair.reference];
        const Vector2 moved(rotated.x() + pose.x, rotated.y() + pose.y);
        const double e = n.dot(moved - reference[pair.reference]);
        const Eigen::Vector3d jacobian(n.x(), n.y(), n.x() * -rotated.y() + n.y() * rotated.x());
        hessian.noalias() += jacobian * jacobian.transpose();
        gradient += jacobian * e;
    }
    constexpr double kDamping = 1e-9;
    hessian.diagonal().array() += kDamping * (1.0 + hessian.trace());
    const Eigen::Vector3d delta = hessian.ldlt().solve(-gradient);
    return {pose.x + delta(0), pose.y + delta(1), wrap_angle(pose.theta + delta(2))};
}

bool finite(const Pose2& pose) {
    return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.theta);
}

}  // namespace

IcpResult Icp2d::align(std::span<const Vector2> source, const Pose2& initial_guess) {
    IcpResult result;
    result.transform = initial_guess;
    if (!index_ || index_->reference.points.size() < kMinPairs || source.size() < kMinPairs
        || !finite(initial_guess)) {
        return result;
    }
    Index& index = *index_;
    const std::span<const Vector2> reference = index.reference.points;
    if (params_.metric == IcpMetric::PointToLine && !index.normals_ready) {
        index.compute_normals();
    }
    const double max_distance2 =
        params_.max_correspondence_distance * params_.max_correspondence_distance;
    std::vector<Pair>& pairs = index.pairs;
    pairs.reserve(source.size());

    Pose2 pose = initial_guess;
    Pose2 previous_pose = initial_guess;  // the transform one iteration before `pose`
    const auto within_epsilons = [this](const Pose2& a, const Pose2& b) {
        return std::hypot(a.x - b.x, a.y - b.y) < params_.translation_epsilon
               && std::abs(wrap_angle(a.theta - b.theta)) < params_.rotation_epsilon;
    };
    for (int iteration = 1; iteration <= params_.max_iterations; ++iteration) {
        result.iterations = iteration;
        // 1. Correspondences: each source point, moved by the current transform, pairs with
        //    its nearest reference point unless that is farther than the correspondence
        //    distance (an outlier, or a part of the scan the reference does not see).
        const double c = std::cos(pose.theta);
        const double s = std::sin(pose.theta);
        pairs.clear();
        for (std::size_t i = 0; i < source.size(); ++i) {
            const Vector2& p = source[i];
            if (!p.allFinite()) {
                continue;
            }
            const Vector2 moved(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
            Pair pair = index.nearest(moved);
            if (pair.distance2 <= max_distance2) {
                pair.source = static_cast<std::uint32_t>(i);
                pairs.push_back(pair);
            }
        }
        // 2. Trimming: drop the worst trim_fraction of the pairs (nth_element: linear time).
        const auto trimmed = static_cast<std::size_t>(
            std::floor(params_.trim_fraction * static_cast<double>(pairs.size())));
        if (trimmed > 0 && trimmed < pairs.size()) {
            const auto keep = static_cast<std::ptrdiff_t>(pairs.size() - trimmed);
            std::nth_element(
                pairs.begin(), pairs.begin() + keep - 1, pairs.end(),
                [](const Pair& a, const Pair& b) { return a.distance2 < b.distance2; });
            pairs.resize(static_cast<std::size_t>(keep));
        }
        result.matched_points = static_cast<int>(pairs.size());
        if (pairs.size() < kMinPairs) {
            result.transform = pose;
            return result;  // not converged: too few pairs survived
        }
        // 3. The transform that best aligns these pairs under the chosen metric.
        const Pose2 next =
            params_.metric == IcpMetric::PointToPoint
                ? solve_point_to_point(source, reference, pairs)
                : gauss_newton_point_to_line(source, reference, index.normals, pairs, pose);
        if (!finite(next)) {
            result.transform = pose;
            return result;
        }
        // 4. Converged when the step is below both epsilons — or when it returns to the
        //    transform of two iterations ago: a pair on the edge of the correspondence
        //    distance or of the trimmed set then flips in and out, and the iteration
        //    alternates between two transforms (a 2-cycle) without further progress.
        const bool small_step = within_epsilons(pose, next);
        const bool two_cycle = iteration > 1 && within_epsilons(previous_pose, next);
        previous_pose = pose;
        pose = next;
        if (small_step || two_cycle) {
            result.converged = true;
            break;
        }
    }
    result.transform = pose;
    // RMS point-to-point distance of the last iteration's pairs under the final transform.
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    double sum2 = 0.0;
    for (const Pair& pair : pairs) {
        const Vector2& p = source[pair.source];
        const Vector2 moved(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y());
        sum2 += (moved - reference[pair.reference]).squaredNorm();
    }
    result.rms_residual = std::sqrt(sum2 / static_cast<double>(pairs.size()));
    return result;
}

}  // namespace legofeup
