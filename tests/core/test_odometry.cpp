#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/odometry.hpp"

namespace legofeup {
namespace {

constexpr double kWheelDiameter = 0.0432;
constexpr double kCircumference = kPi * kWheelDiameter;  // metres per 360 counts

TEST(Odometry, NominalCountsPerMetreOfTheNxtWheel) {
    // scenario.md: 1° per count on a 43.2 mm wheel ⇒ Codo ≈ 2652.6 counts/m.
    EXPECT_NEAR(nominal_counts_per_metre(kWheelDiameter, 360.0), 2652.58, 0.01);
    const OdometryParams defaults;
    EXPECT_DOUBLE_EQ(defaults.codo_right, defaults.codo_left);
    EXPECT_NEAR(defaults.codo_right, 360.0 / kCircumference, 1e-9);
}

TEST(Odometry, EncoderDeltaSurvivesCounterWrapAround) {
    const std::int32_t max = std::numeric_limits<std::int32_t>::max();
    const std::int32_t min = std::numeric_limits<std::int32_t>::min();
    EXPECT_EQ(encoder_delta(min + 5, max - 4), 10);
    EXPECT_EQ(encoder_delta(max - 4, min + 5), -10);
    EXPECT_EQ(encoder_delta(1200, 1000), 200);
    EXPECT_EQ(encoder_delta(-1000, -800), -200);
}

TEST(Odometry, StraightIncrementFromCounts) {
    // 100 counts on both wheels: each wheel turned 100° and rolled 100/360 of a circumference.
    const OdometryIncrement inc = odometry_increment(100, 100, OdometryParams{});
    const double expected = 100.0 / 360.0 * kCircumference;
    EXPECT_NEAR(inc.d_right, expected, 1e-12);
    EXPECT_NEAR(inc.d_left, expected, 1e-12);
    EXPECT_NEAR(inc.distance, expected, 1e-12);
    EXPECT_NEAR(inc.rotation, 0.0, 1e-15);
}

TEST(Odometry, QuarterTurnOnTheSpot) {
    // Turning 90° on the spot rolls each wheel b/2·π/2 = 0.0942 m, i.e.
    // 0.12·90/0.0432 = 250 counts: right wheel forwards, left backwards.
    const OdometryIncrement inc = odometry_increment(250, -250, OdometryParams{});
    EXPECT_NEAR(inc.distance, 0.0, 1e-15);
    EXPECT_NEAR(inc.rotation, kPi / 2.0, 1e-12);
    const Pose2 turned = advance_pose(Pose2{0.3, -0.2, 0.0}, inc);
    EXPECT_NEAR(turned.x, 0.3, 1e-15);
    EXPECT_NEAR(turned.y, -0.2, 1e-15);
    EXPECT_NEAR(turned.theta, kPi / 2.0, 1e-12);
}

TEST(Odometry, UsesEachWheelsOwnCountsPerMetre) {
    OdometryParams params;
    params.codo_right = 2000.0;
    params.codo_left = 2500.0;
    params.wheel_base = 0.1;
    const OdometryIncrement inc = odometry_increment(200, 200, params);
    EXPECT_NEAR(inc.d_right, 0.1, 1e-15);
    EXPECT_NEAR(inc.d_left, 0.08, 1e-15);
    EXPECT_NEAR(inc.distance, 0.09, 1e-15);
    EXPECT_NEAR(inc.rotation, 0.2, 1e-12);  // (0.1 − 0.08)/0.1
}

TEST(Odometry, IncrementFromMotionInvertsEquationEight) {
    const OdometryIncrement inc = increment_from_motion(0.05, 0.2, 0.12);
    EXPECT_NEAR(inc.d_right, 0.05 + 0.012, 1e-15);
    EXPECT_NEAR(inc.d_left, 0.05 - 0.012, 1e-15);
    EXPECT_NEAR(0.5 * (inc.d_right + inc.d_left), inc.distance, 1e-15);   // eq. 8
    EXPECT_NEAR((inc.d_right - inc.d_left) / 0.12, inc.rotation, 1e-15);  // eq. 8
}

TEST(Odometry, StraightSegmentHandWorked) {
    // Ten periods of 100 counts each from the path's start, heading +x.
    Pose2 pose{-1.0, -1.0, 0.0};
    for (int k = 0; k < 10; ++k) {
        pose = advance_pose(pose, odometry_increment(100, 100, OdometryParams{}));
    }
    EXPECT_NEAR(pose.x, -1.0 + 10.0 * 100.0 / 360.0 * kCircumference, 1e-12);
    EXPECT_NEAR(pose.y, -1.0, 1e-15);
    EXPECT_NEAR(pose.theta, 0.0, 1e-15);

    // The same along a 30° heading.
    Pose2 slanted{0.0, 0.0, kPi / 6.0};
    slanted = advance_pose(slanted, 0.5, 0.0);
    EXPECT_NEAR(slanted.x, 0.5 * std::sqrt(3.0) / 2.0, 1e-15);
    EXPECT_NEAR(slanted.y, 0.25, 1e-15);
}

TEST(Odometry, CentredDifferenceFollowsArcsFarBetterThanEuler) {
    // A robot on a circle of radius R turning Δφ per period travels d = R·Δφ along the arc.
    // Exact chord: 2R·sin(Δφ/2) at heading θ + Δφ/2. The centred difference (eq. 7) uses the
    // right heading and errs only in length, by R·Δφ·(1 − sinc) ≈ R·Δφ³/24 per period.
    const double radius = 0.5;
    const double dphi = 0.05;
    const int steps = 63;  // about half a turn
    Pose2 centred{radius, 0.0, kPi / 2.0};
    Pose2 euler = centred;
    for (int k = 0; k < steps; ++k) {
        centred = advance_pose(centred, radius * dphi, dphi);
        euler.x += radius * dphi * std::cos(euler.theta);
        euler.y += radius * dphi * std::sin(euler.theta);
        euler.theta += dphi;
    }
    const double angle = steps * dphi;  // exact end point on the circle
    const double exact_x = radius * std::cos(angle);
    const double exact_y = radius * std::sin(angle);
    const double centred_error = std::hypot(centred.x - exact_x, centred.y - exact_y);
    const double euler_error = std::hypot(euler.x - exact_x, euler.y - exact_y);
    EXPECT_LE(centred_error, steps * radius * std::pow(dphi, 3) / 24.0 * 1.01);
    EXPECT_LT(centred_error * 50.0, euler_error);
    EXPECT_NEAR(centred.theta, wrap_angle(kPi / 2.0 + angle), 1e-12);
}

}  // namespace
}  // namespace legofeup
