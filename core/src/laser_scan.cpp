#include "legofeup/core/laser_scan.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup {

std::vector<ConfigIssue> validate(const ScanGeometry& geometry, const std::string& prefix) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    const std::string p = prefix + ".";
    check.in_range(p + "beam_count", geometry.beam_count, 1, kMaxScanBeams);
    check.positive(p + "angle_increment", geometry.angle_increment, 2.0 * kPi);
    check.in_range(p + "angle_min", geometry.angle_min, -2.0 * kPi, 2.0 * kPi);
    // Each beam covers one increment, so the field of view is beam_count · angle_increment.
    const double field_of_view = geometry.beam_count * geometry.angle_increment;
    check.require(!std::isfinite(field_of_view) || field_of_view <= 2.0 * kPi * (1.0 + 1e-12),
                  p + "angle_increment", geometry.angle_increment,
                  "beam_count · angle_increment must be at most 360° (2π rad)");
    // Ranges travel as whole millimetres in 16 bits: at most 65.535 m.
    check.positive(p + "range_min", geometry.range_min, 65.535);
    check.positive(p + "range_max", geometry.range_max, 65.535);
    check.require(
        !(geometry.range_max <= geometry.range_min), p + "range_max", geometry.range_max,
        "must be greater than range_min (" + format_config_number(geometry.range_min) + ")");
    return issues;
}

std::uint16_t range_reading(std::optional<double> range, const ScanGeometry& geometry) {
    if (!range || !(*range <= geometry.range_max)) {
        return kRangeNoEcho;
    }
    if (*range < geometry.range_min) {
        return kRangeTooNear;
    }
    // The largest value 16 bits of millimetres carry.
    constexpr long kMaxMillimetres = 65535;
    return static_cast<std::uint16_t>(
        std::clamp<long>(std::lround(*range * 1000.0), kRangeFirstValid, kMaxMillimetres));
}

std::optional<double> range_of(const LaserScan& scan, int beam, const ScanGeometry& geometry) {
    if (beam < 0 || beam >= scan.beam_count || beam >= kMaxScanBeams) {
        return std::nullopt;
    }
    const std::uint16_t value = scan.range_mm[static_cast<std::size_t>(beam)];
    if (value < kRangeFirstValid) {
        return std::nullopt;  // an error code (no echo, too near, dropout, …)
    }
    const double range = value / 1000.0;
    if (range < geometry.range_min || range > geometry.range_max) {
        return std::nullopt;
    }
    return range;
}

void scan_to_points(const LaserScan& scan, const ScanGeometry& geometry, const Pose2& frame_pose,
                    std::vector<Vector2>& out) {
    out.clear();
    // The scanner's pose rotation, evaluated once: p_frame = t + R(θ) · r (cos α, sin α)ᵀ.
    const double c = std::cos(frame_pose.theta);
    const double s = std::sin(frame_pose.theta);
    const int beams =
        std::min({static_cast<int>(scan.beam_count), geometry.beam_count, kMaxScanBeams});
    for (int beam = 0; beam < beams; ++beam) {
        const std::optional<double> range = range_of(scan, beam, geometry);
        if (!range) {
            continue;
        }
        const double alpha = geometry.angle_of(beam);
        const double px = *range * std::cos(alpha);
        const double py = *range * std::sin(alpha);
        out.emplace_back(frame_pose.x + c * px - s * py, frame_pose.y + s * px + c * py);
    }
}

Pose2 compose(const Pose2& a, const Pose2& b) {
    // a ⊕ b = (t_a + R(θ_a) t_b, θ_a + θ_b).
    const double c = std::cos(a.theta);
    const double s = std::sin(a.theta);
    return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, wrap_angle(a.theta + b.theta)};
}

Pose2 inverse(const Pose2& a) {
    // ⊖a = (−R(θ)ᵀ t, −θ).
    const double c = std::cos(a.theta);
    const double s = std::sin(a.theta);
    return {-(c * a.x + s * a.y), s * a.x - c * a.y, wrap_angle(-a.theta)};
}

Vector2 transform_point(const Pose2& pose, const Vector2& point) {
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    return {pose.x + c * point.x() - s * point.y(), pose.y + s * point.x() + c * point.y()};
}

}  // namespace legofeup
