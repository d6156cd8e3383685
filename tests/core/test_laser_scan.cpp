#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "legofeup/core/laser_scan.hpp"

namespace legofeup {
namespace {

bool has_issue(const std::vector<ConfigIssue>& issues, const std::string& field) {
    for (const ConfigIssue& issue : issues) {
        if (issue.field == field) {
            return true;
        }
    }
    return false;
}

void expect_pose_near(const Pose2& actual, const Pose2& expected, double tolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(wrap_angle(actual.theta - expected.theta), 0.0, tolerance);
}

TEST(ScanGeometry, DefaultIsTheUrg04lx) {
    const ScanGeometry urg;
    EXPECT_TRUE(validate(urg, "scan").empty());
    EXPECT_EQ(urg.beam_count, 682);
    EXPECT_NEAR(radians_to_degrees(urg.angle_increment), 360.0 / 1024.0, 1e-12);
    // Centred on the forward axis: first and last beam symmetric, ≈ ±119.7°.
    EXPECT_NEAR(urg.angle_of(0), -urg.angle_of(681), 1e-12);
    EXPECT_NEAR(radians_to_degrees(urg.angle_of(681)), 681 * 0.5 * 360.0 / 1024.0, 1e-9);
}

TEST(ScanGeometry, ValidateNamesEachBadField) {
    ScanGeometry g;
    g.beam_count = 0;
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.beam_count"));
    g.beam_count = kMaxScanBeams + 1;
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.beam_count"));

    g = {};
    g.angle_increment = -0.01;
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.angle_increment"));
    g.angle_increment = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.angle_increment"));

    // 1024 beams of 2π/1000 cover more than a turn.
    g = {};
    g.beam_count = 1024;
    g.angle_increment = 2.0 * kPi / 1000.0;
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.angle_increment"));
    g.angle_increment = 2.0 * kPi / 1024.0;  // exactly one turn is allowed
    EXPECT_TRUE(validate(g, "scan").empty());

    g = {};
    g.range_min = 0.0;
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.range_min"));
    g = {};
    g.range_max = 0.01;  // below range_min = 0.02
    const std::vector<ConfigIssue> issues = validate(g, "laser.scan");
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].field, "laser.scan.range_max");
    EXPECT_EQ(issues[0].value, "0.01");
    g = {};
    g.range_max = 70.0;  // not representable in 16-bit millimetres
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.range_max"));
    g = {};
    g.angle_min = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(has_issue(validate(g, "scan"), "scan.angle_min"));
}

TEST(LaserScan, RangeOfSkipsCodesAndOutOfRangeValues) {
    ScanGeometry g;
    g.range_min = 0.02;
    g.range_max = 4.0;
    LaserScan scan;
    scan.beam_count = 8;
    scan.range_mm[0] = kRangeNoEcho;
    scan.range_mm[1] = kRangeTooNear;
    scan.range_mm[2] = kRangeDropout;
    scan.range_mm[3] = 19;  // an unlisted code
    scan.range_mm[4] = 20;  // 0.02 m, the minimum
    scan.range_mm[5] = 1234;
    scan.range_mm[6] = 4000;
    scan.range_mm[7] = 4001;  // beyond range_max
    for (int beam : {0, 1, 2, 3, 7}) {
        EXPECT_FALSE(range_of(scan, beam, g).has_value()) << "beam " << beam;
    }
    EXPECT_DOUBLE_EQ(*range_of(scan, 4, g), 0.020);
    EXPECT_DOUBLE_EQ(*range_of(scan, 5, g), 1.234);
    EXPECT_DOUBLE_EQ(*range_of(scan, 6, g), 4.0);
    // Beams outside the scan are not ranges.
    scan.range_mm[8] = 1000;
    EXPECT_FALSE(range_of(scan, 8, g).has_value());
    EXPECT_FALSE(range_of(scan, -1, g).has_value());
}

TEST(LaserScan, ScanToPointsMatchesHandWorkedPoints) {
    // Four beams at −90°, 0°, 90°, 180°.
    ScanGeometry g;
    g.beam_count = 4;
    g.angle_min = -0.5 * kPi;
    g.angle_increment = 0.5 * kPi;
    g.range_max = 5.6;
    LaserScan scan;
    scan.beam_count = 4;
    scan.range_mm = {};
    scan.range_mm[0] = 1000;          // (0, −1) in the scanner's frame
    scan.range_mm[1] = kRangeNoEcho;  // skipped
    scan.range_mm[2] = 2000;          // (0, 2)
    scan.range_mm[3] = 500;           // (−0.5, 0)

    std::vector<Vector2> points;
    scan_to_points(scan, g, Pose2{}, points);
    ASSERT_EQ(points.size(), 3u);
    EXPECT_NEAR(points[0].x(), 0.0, 1e-12);
    EXPECT_NEAR(points[0].y(), -1.0, 1e-12);
    EXPECT_NEAR(points[1].x(), 0.0, 1e-12);
    EXPECT_NEAR(points[1].y(), 2.0, 1e-12);
    EXPECT_NEAR(points[2].x(), -0.5, 1e-12);
    EXPECT_NEAR(points[2].y(), 0.0, 1e-12);

    // Scanner at (1, 2) facing +y: (x, y) ↦ (1 − y, 2 + x).
    scan_to_points(scan, g, Pose2{1.0, 2.0, 0.5 * kPi}, points);
    ASSERT_EQ(points.size(), 3u);
    EXPECT_NEAR(points[0].x(), 2.0, 1e-12);
    EXPECT_NEAR(points[0].y(), 2.0, 1e-12);
    EXPECT_NEAR(points[1].x(), -1.0, 1e-12);
    EXPECT_NEAR(points[1].y(), 2.0, 1e-12);
    EXPECT_NEAR(points[2].x(), 1.0, 1e-12);
    EXPECT_NEAR(points[2].y(), 1.5, 1e-12);
}

TEST(LaserScan, ScanToPointsClearsAndDoesNotReallocate) {
    const ScanGeometry g;
    LaserScan scan;
    scan.beam_count = static_cast<std::uint16_t>(g.beam_count);
    for (int i = 0; i < g.beam_count; ++i) {
        scan.range_mm[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(500 + i);
    }
    std::vector<Vector2> points{Vector2(9, 9)};
    points.reserve(kMaxScanBeams);
    const Vector2* storage = points.data();
    scan_to_points(scan, g, Pose2{}, points);
    EXPECT_EQ(points.size(), static_cast<std::size_t>(g.beam_count));
    EXPECT_EQ(points.data(), storage);
    // Every point lies at its beam's range and angle.
    for (int i = 0; i < g.beam_count; ++i) {
        const Vector2& p = points[static_cast<std::size_t>(i)];
        EXPECT_NEAR(p.norm(), (500 + i) / 1000.0, 1e-12);
        EXPECT_NEAR(std::atan2(p.y(), p.x()), g.angle_of(i), 1e-12);
    }
}

TEST(Pose2Algebra, ComposeMatchesHandWorkedExample) {
    // Robot at (1, 0) facing +y; a point 1 m ahead of it is at (1, 1).
    const Pose2 a{1.0, 0.0, 0.5 * kPi};
    expect_pose_near(compose(a, Pose2{1.0, 0.0, 0.0}), Pose2{1.0, 1.0, 0.5 * kPi}, 1e-12);
    expect_pose_near(compose(a, Pose2{0.0, 0.0, kPi}), Pose2{1.0, 0.0, -0.5 * kPi}, 1e-12);
    const Vector2 p = transform_point(a, Vector2(2.0, 1.0));
    EXPECT_NEAR(p.x(), 0.0, 1e-12);
    EXPECT_NEAR(p.y(), 2.0, 1e-12);
    // The inverse of (1, 2, 90°): the world origin seen from that pose is at (−2, 1).
    expect_pose_near(inverse(Pose2{1.0, 2.0, 0.5 * kPi}), Pose2{-2.0, 1.0, -0.5 * kPi}, 1e-12);
}

TEST(Pose2Algebra, RoundTripsOverRandomPoses) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> position(-10.0, 10.0);
    std::uniform_real_distribution<double> heading(-kPi, kPi);
    const auto random_pose = [&] { return Pose2{position(rng), position(rng), heading(rng)}; };
    for (int trial = 0; trial < 200; ++trial) {
        const Pose2 a = random_pose();
        const Pose2 b = random_pose();
        const Pose2 c = random_pose();
        expect_pose_near(compose(a, inverse(a)), Pose2{}, 1e-12);
        expect_pose_near(compose(inverse(a), a), Pose2{}, 1e-12);
        expect_pose_near(inverse(inverse(a)), a, 1e-12);
        expect_pose_near(compose(compose(a, b), c), compose(a, compose(b, c)), 1e-11);
        // (a ⊕ b)⁻¹ = b⁻¹ ⊕ a⁻¹.
        expect_pose_near(inverse(compose(a, b)), compose(inverse(b), inverse(a)), 1e-11);
        // Points: (a ⊕ b)·p = a·(b·p), a⁻¹·(a·p) = p.
        const Vector2 p(position(rng), position(rng));
        EXPECT_LT(
            (transform_point(compose(a, b), p) - transform_point(a, transform_point(b, p))).norm(),
            1e-11);
        EXPECT_LT((transform_point(inverse(a), transform_point(a, p)) - p).norm(), 1e-11);
        // Heading stays wrapped.
        const double theta = compose(a, b).theta;
        EXPECT_GT(theta, -kPi);
        EXPECT_LE(theta, kPi);
    }
}

}  // namespace
}  // namespace legofeup
