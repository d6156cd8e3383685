#include "legofeup/core/likelihood_field.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>

namespace legofeup {

std::vector<ConfigIssue> validate(const LikelihoodFieldParams& params, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    const std::string p = prefix + ".";
    // A micrometre is far below any cell (and σ → 0 would overflow 1/σ²); no map is
    // uncertain by 100 m.
    check.in_range(p + "sigma_hit", params.sigma_hit, 1e-6, 100.0);
    check.in_range(p + "z_hit", params.z_hit, 0.0, 1.0);
    check.in_range(p + "z_random", params.z_random, 0.0, 1.0);
    check.require(!(params.z_hit == 0.0 && params.z_random == 0.0), p + "z_random", params.z_random,
                  "z_hit and z_random must not both be 0 (they are relative weights)");
    check.in_range(p + "beam_stride", params.beam_stride, 1, kMaxScanBeams);
    check.positive(p + "max_distance", params.max_distance, 100.0);
    return issues;
}

namespace {

/// The 1-D squared distance transform of a sampled function (Felzenszwalb & Huttenlocher
/// 2012, Algorithm DT): d(p) = min_q ((p − q)² + f(q)), p, q = 0 … n − 1, as the lower
/// envelope of the parabolas y = (p − q)² + f(q). `v` and `z` are scratch of n and n + 1
/// entries: the envelope is parabola v[j] between the abscissae z[j] and z[j + 1].
/// Every f(q) must be finite (an obstacle-free line carries a large finite value), so that
/// the intersections are never ∞ − ∞.
void squared_distance_transform_1d(std::span<const double> f, std::span<double> d, std::span<int> v,
                                   std::span<double> z) {
    const int n = static_cast<int>(f.size());
    if (n == 0) {
        return;
    }
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const auto at = [](auto values, int i) -> auto& {
        return values[static_cast<std::size_t>(i)];
    };
    // 1. The envelope, left to right. Parabola q goes last, after removing every parabola it
    //    hides: the last one, v[k], is hidden when q meets it at s ≤ z[k], left of where v[k]
    //    begins to be the lowest.
    int k = 0;
    at(v, 0) = 0;
    at(z, 0) = -kInfinity;
    at(z, 1) = kInfinity;
    for (int q = 1; q < n; ++q) {
        const double fq = at(f, q) + static_cast<double>(q) * q;
        double s = 0.0;
        for (;;) {
            const int r = at(v, k);
            // Where parabolas q and r meet: ((f(q) + q²) − (f(r) + r²)) / (2q − 2r).
            s = (fq - (at(f, r) + static_cast<double>(r) * r)) / (2.0 * (q - r));
            if (s > at(z, k)) {
                break;  // always so for k = 0, z[0] = −∞
            }
            --k;
        }
        ++k;
        at(v, k) = q;
        at(z, k) = s;
        at(z, k + 1) = kInfinity;
    }
    // 2. Read the envelope at every sample.
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (at(z, k + 1) < q) {
            ++k;
        }
        const double offset = q - at(v, k);
        at(d, q) = offset * offset + at(f, at(v, k));
    }
}

}  // namespace

LikelihoodField::LikelihoodField(OccupancyGrid grid, double max_distance)
    : grid_(std::move(grid)),
      max_distance_(max_distance),
      outside_distance_(static_cast<float>(max_distance)) {
    if (!std::isfinite(max_distance) || max_distance <= 0.0) {
        throw std::invalid_argument("likelihood field: max_distance = "
                                    + format_config_number(max_distance)
                                    + ": must be a positive finite number of metres");
    }
    const std::vector<CellState>& cells = grid_.cells();
    distances_.assign(cells.size(), outside_distance_);
    has_obstacles_ = std::find(cells.begin(), cells.end(), CellState::Occupied) != cells.end();
    if (!has_obstacles_) {
        return;  // nothing to be near: max_distance everywhere
    }

    const auto width = static_cast<std::size_t>(grid_.width());
    const auto height = static_cast<std::size_t>(grid_.height());
    const std::size_t longest = std::max(width, height);
    // Cells that are not occupied (free or unknown) start at a finite "infinity" above every
    // squared distance in the grid ((w − 1)² + (h − 1)² cells²): an integer a double holds
    // exactly, so the transform's arithmetic on whole numbers stays exact.
    const double far = static_cast<double>(width) * static_cast<double>(width)
                       + static_cast<double>(height) * static_cast<double>(height) + 1.0;
    std::vector<double> column_pass(cells.size());
    std::vector<double> line(longest);
    std::vector<double> transformed(longest);
    std::vector<int> envelope(longest);
    std::vector<double> boundaries(longest + 1);
    const std::span<int> v(envelope);
    const std::span<double> z(boundaries);

    // 1. Along every column: the squared distance (cells²) to the nearest occupied cell in
    //    the same column, `far` where the column has none.
    for (std::size_t col = 0; col < width; ++col) {
        for (std::size_t row = 0; row < height; ++row) {
            line[row] = cells[row * width + col] == CellState::Occupied ? 0.0 : far;
        }
        squared_distance_transform_1d(std::span<const double>(line.data(), height),
                                      std::span<double>(transformed.data(), height), v, z);
        for (std::size_t row = 0; row < height; ++row) {
            column_pass[row * width + col] = transformed[row];
        }
    }
    // 2. Along every row of that: min over columns c of (col − c)² + D_column(c, row), the
    //    squared distance to the nearest occupied cell anywhere. Then metres, clamped.
    for (std::size_t row = 0; row < height; ++row) {
        squared_distance_transform_1d(
            std::span<const double>(column_pass.data() + row * width, width),
            std::span<double>(transformed.data(), width), v, z);
        for (std::size_t col = 0; col < width; ++col) {
            const double metres = std::sqrt(transformed[col]) * grid_.resolution();
            distances_[row * width + col] = static_cast<float>(std::min(metres, max_distance));
        }
    }
}

double LikelihoodField::distance_at(const GridCell& cell) const {
    if (!grid_.contains(cell)) {
        return static_cast<double>(outside_distance_);
    }
    return static_cast<double>(
        distances_[static_cast<std::size_t>(cell.row) * static_cast<std::size_t>(grid_.width())
                   + static_cast<std::size_t>(cell.col)]);
}

double LikelihoodField::distance_at(const Vector2& world) const {
    const std::optional<GridCell> cell = grid_.cell_of(world);
    return cell ? distance_at(*cell) : static_cast<double>(outside_distance_);
}

void scan_endpoints(const LaserScan& scan, const ScanGeometry& geometry, const Pose2& mount,
                    int beam_stride, std::vector<Vector2>& out) {
    out.clear();
    const int stride = std::max(beam_stride, 1);
    // The mount's rotation, evaluated once: x_k = t_M + R(θ_M) · z_k (cos α_k, sin α_k)ᵀ.
    const double c = std::cos(mount.theta);
    const double s = std::sin(mount.theta);
    const int beams =
        std::min({static_cast<int>(scan.beam_count), geometry.beam_count, kMaxScanBeams});
    for (int beam = 0; beam < beams; beam += stride) {
        const std::optional<double> range = range_of(scan, beam, geometry);
        if (!range) {
            continue;  // an error code, no echo, or outside [range_min, range_max]
        }
        const double alpha = geometry.angle_of(beam);
        const double px = *range * std::cos(alpha);
        const double py = *range * std::sin(alpha);
        out.emplace_back(mount.x + c * px - s * py, mount.y + s * px + c * py);
    }
}

namespace {

/// Where the end points of a scan at a robot pose fall in the field's grid, in cells:
/// u = A·x_k + b with A = R(θ − θ_o)/res and b = R(−θ_o)(t − o)/res, the composition of
/// step 2 (robot → world: t + R(θ)·x_k), the grid frame (R(−θ_o)(p − o)) and the cell size,
/// so that an end point costs four products and four sums. An end point within rounding
/// (~1e-15 m) of a cell boundary may land in the neighbour distance_at would pick.
struct EndpointToCell {
    double a00, a01, a10, a11, b0, b1;

    EndpointToCell(const LikelihoodField& field, const Pose2& robot_pose) {
        const OccupancyGrid& grid = field.grid();
        const double inverse_resolution = 1.0 / grid.resolution();
        const double c = std::cos(robot_pose.theta - grid.origin().theta) * inverse_resolution;
        const double s = std::sin(robot_pose.theta - grid.origin().theta) * inverse_resolution;
        a00 = c;
        a01 = -s;
        a10 = s;
        a11 = c;
        const Vector2 b = grid.to_grid_frame(position_of(robot_pose)) * inverse_resolution;
        b0 = b.x();
        b1 = b.y();
    }
};

/// The end point's field distance (m): the cell containing it, or outside_distance.
/// u ≥ 0 and u < width (false for NaN too) is floor(u) in [0, width), and for u ≥ 0 the
/// conversion to int (truncation) is floor: no call to std::floor in the loop.
inline double field_distance(const float* distances, int width, int height, float outside,
                             const EndpointToCell& m, const Vector2& x) {
    const double u = m.b0 + m.a00 * x.x() + m.a01 * x.y();
    const double w = m.b1 + m.a10 * x.x() + m.a11 * x.y();
    if (!(u >= 0.0 && u < width && w >= 0.0 && w < height)) {
        return static_cast<double>(outside);
    }
    return static_cast<double>(
        distances[static_cast<std::ptrdiff_t>(static_cast<int>(w)) * width + static_cast<int>(u)]);
}

/// The product of step 4 is kept in a double by renormalising: whenever the running product
/// leaves [kRenormaliseBelow, kRenormaliseAbove] its log is banked and it restarts at 1. A
/// factor in [kSmallestProductFactor, kLargestProductFactor] then never under- or overflows
/// it (1e-150 · 1e-100 and 1e150 · 1e100 are well inside a double's normal range), and each
/// factor lies in [z_random/z_max, z_hit/(√(2π)σ_hit) + z_random/z_max].
constexpr double kSmallestProductFactor = 1e-100;
constexpr double kLargestProductFactor = 1e100;
constexpr double kRenormaliseBelow = 1e-150;
constexpr double kRenormaliseAbove = 1e150;

/// End points per batch of the product's loop (a buffer on the stack).
constexpr std::size_t kEndpointChunk = 64;

}  // namespace

double scan_log_likelihood(const LikelihoodField& field, const Pose2& robot_pose,
                           std::span<const Vector2> endpoints_in_robot_frame,
                           const LikelihoodFieldParams& params, double range_max) {
    // The model's constants (Table 6.3): the normalised weights, the Gaussian's peak
    // z_hit/(√(2π)σ_hit) and exponent factor 1/(2σ_hit²), the uniform density z_random/z_max.
    const double weight_sum = params.z_hit + params.z_random;
    const double hit_peak = params.z_hit / weight_sum / (std::sqrt(2.0 * kPi) * params.sigma_hit);
    const double exponent_factor = 1.0 / (2.0 * params.sigma_hit * params.sigma_hit);
    const double random_density = params.z_random / weight_sum / range_max;

    const EndpointToCell to_cell(field, robot_pose);
    const float* distances = field.distances().data();
    const int width = field.width();
    const int height = field.height();
    const float outside = field.outside_distance();

    if (random_density >= kSmallestProductFactor
        && hit_peak + random_density <= kLargestProductFactor) {
        // The usual case: log Π_k f_k, with f_k = z_hit·N(d_k) + z_random/z_max. One exp per
        // end point, and a log only when the product is renormalised (at most every 85 end
        // points with the default parameters, whose factors lie in [0.018, 3.6]) instead of a
        // log per end point, which would cost as much as the exp. In batches: first every
        // end point's exponent −d²/(2σ²) (a transform and a load each, free of calls, so they
        // overlap), then the exps and the product.
        double log_sum = 0.0;
        double product = 1.0;
        std::array<double, kEndpointChunk> exponents;
        for (std::size_t start = 0; start < endpoints_in_robot_frame.size();
             start += kEndpointChunk) {
            const std::size_t count =
                std::min(kEndpointChunk, endpoints_in_robot_frame.size() - start);
            for (std::size_t i = 0; i < count; ++i) {
                const double d = field_distance(distances, width, height, outside, to_cell,
                                                endpoints_in_robot_frame[start + i]);
                exponents[i] = -exponent_factor * d * d;
            }
            for (std::size_t i = 0; i < count; ++i) {
                product *= hit_peak * std::exp(exponents[i]) + random_density;
                if (!(product >= kRenormaliseBelow && product <= kRenormaliseAbove)) {
                    log_sum += std::log(product);
                    product = 1.0;
                }
            }
        }
        return log_sum + std::log(product);
    }

    // z_random = 0 (or a uniform density too small for a product): each term as a
    // log-sum-exp, log(e^a + e^b) = max(a, b) + log1p(e^−|a − b|) with
    // a = log(z_hit/(√(2π)σ)) − d²/(2σ²), b = log(z_random/z_max) (−∞ for z_random = 0, and
    // then the term is a exactly), finite however far d lies from an obstacle.
    const double log_hit_peak = std::log(hit_peak);
    const double log_random = std::log(random_density);
    double sum = 0.0;
    for (const Vector2& x : endpoints_in_robot_frame) {
        const double d = field_distance(distances, width, height, outside, to_cell, x);
        const double hit = log_hit_peak - exponent_factor * d * d;
        sum += std::max(hit, log_random) + std::log1p(std::exp(-std::abs(hit - log_random)));
    }
    return sum;
}

}  // namespace legofeup
