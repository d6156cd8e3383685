#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

TEST(WrapAngle, KeepsAnglesInsideTheHalfOpenInterval) {
    testing::Uniform uniform(3);
    for (int i = 0; i < 10000; ++i) {
        const double angle = uniform(-1000.0, 1000.0);
        const double wrapped = wrap_angle(angle);
        EXPECT_GT(wrapped, -kPi);
        EXPECT_LE(wrapped, kPi);
        // Same direction: the difference is a whole number of turns.
        const double turns = (angle - wrapped) / (2.0 * kPi);
        EXPECT_NEAR(turns, std::round(turns), 1e-9);
    }
}

TEST(WrapAngle, MapsMinusPiToPlusPi) {
    EXPECT_DOUBLE_EQ(wrap_angle(-kPi), kPi);
    EXPECT_DOUBLE_EQ(wrap_angle(kPi), kPi);
    EXPECT_DOUBLE_EQ(wrap_angle(3.0 * kPi), kPi);
}

TEST(WrapAngle, IsIdempotentAndExactInside) {
    for (double angle : {0.0, 0.5, -0.5, 3.0, -3.0, kPi - 1e-12}) {
        EXPECT_EQ(wrap_angle(angle), angle);
        EXPECT_EQ(wrap_angle(wrap_angle(angle + 10.0)), wrap_angle(angle + 10.0));
    }
}

TEST(WrapAngle, CrossesThePiBoundary) {
    EXPECT_NEAR(wrap_angle(kPi + 0.1), -kPi + 0.1, 1e-12);
    EXPECT_NEAR(wrap_angle(-kPi - 0.1), kPi - 0.1, 1e-12);
    EXPECT_NEAR(wrap_angle(degrees_to_radians(181.0)), degrees_to_radians(-179.0), 1e-12);
}

TEST(AngleUnits, ConvertBothWays) {
    EXPECT_DOUBLE_EQ(degrees_to_radians(180.0), kPi);
    EXPECT_DOUBLE_EQ(radians_to_degrees(kPi / 2.0), 90.0);
}

}  // namespace
}  // namespace legofeup
