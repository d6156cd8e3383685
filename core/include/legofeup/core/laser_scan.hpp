#pragma once
// A planar laser rangefinder scan (paper 001): the scanner's geometry and one scan of ranges,
// in the convention of the Hokuyo URG-04LX the lesson models — whole millimetres, with values
// below the minimum range being error codes. Fixed size, no heap: a scan travels inside a
// SensorFrame.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

/// At most this many beams in one scan (the URG-04LX measures 682 over 240°).
inline constexpr int kMaxScanBeams = 1024;

/// Where the beams point: beam i is at angle_min + i·angle_increment in the scanner's frame
/// (counter-clockwise, 0 = the scanner's forward axis), i = 0 … beam_count − 1.
struct ScanGeometry {
    /// URG-04LX: 1024 steps per turn (0.3515625°), 682 beams centred on the forward axis.
    double angle_increment = 2.0 * kPi / 1024.0;
    int beam_count = 682;
    double angle_min = -0.5 * (682 - 1) * (2.0 * kPi / 1024.0);  ///< ≈ −119.7°
    double range_min = 0.02;                                     ///< m: shorter readings are errors
    double range_max = 5.6;  ///< m: the longest reading the scanner reports

    double angle_of(int beam) const { return angle_min + beam * angle_increment; }
    friend bool operator==(const ScanGeometry&, const ScanGeometry&) = default;
};

/// Everything wrong with a geometry (fields "<prefix>.beam_count", ...): 1 … kMaxScanBeams
/// beams, a positive increment, a field of view of at most 360°, 0 < range_min < range_max.
std::vector<ConfigIssue> validate(const ScanGeometry& geometry, const std::string& prefix);

/// What a range value below the minimum means (the URG reports such codes instead of a
/// distance). Any value < 20 that is not listed is also an error.
enum ScanRangeCode : std::uint16_t {
    kRangeNoEcho = 0,       ///< nothing within the maximum range
    kRangeTooNear = 1,      ///< an object closer than the minimum range
    kRangeDropout = 2,      ///< the echo was too weak to measure (random dropout)
    kRangeFirstValid = 20,  ///< mm: the smallest value that is a distance
};

struct LaserScan {
    std::uint16_t beam_count = 0;  ///< range_mm[0 .. beam_count) are valid entries
    /// Range of each beam in whole millimetres, or an error code (< kRangeFirstValid).
    std::array<std::uint16_t, kMaxScanBeams> range_mm{};

    friend bool operator==(const LaserScan&, const LaserScan&) = default;
};

/// The range of beam `i` in metres, or nullopt for an error code or a value outside
/// [geometry.range_min, geometry.range_max].
std::optional<double> range_of(const LaserScan& scan, int beam, const ScanGeometry& geometry);

/// The reading a scanner reports for a distance (m) along a beam: kRangeNoEcho for none or
/// beyond geometry.range_max, kRangeTooNear below geometry.range_min, else whole
/// millimetres (at least kRangeFirstValid, at most 65535). The inverse of range_of.
std::uint16_t range_reading(std::optional<double> range, const ScanGeometry& geometry);

/// The measured points of a scan as 2-D points in the frame of `frame_pose` (which is the
/// scanner's pose in that frame; the identity gives the scanner's own frame). Error codes
/// are skipped. Clears `out` first; does not allocate once `out` has kMaxScanBeams capacity.
void scan_to_points(const LaserScan& scan, const ScanGeometry& geometry, const Pose2& frame_pose,
                    std::vector<Vector2>& out);

/// Pose composition a ⊕ b: b expressed in a's frame, returned in a's parent frame.
Pose2 compose(const Pose2& a, const Pose2& b);
/// The inverse pose: compose(a, inverse(a)) is the identity.
Pose2 inverse(const Pose2& a);
/// A point given in the frame of `pose`, returned in the pose's parent frame.
Vector2 transform_point(const Pose2& pose, const Vector2& point);

}  // namespace legofeup
