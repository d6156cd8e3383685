// The one pose error, x̃ = x̂ − x with the heading wrapped, against hand-worked numbers: its
// sign, a heading error across ±π, the half-open (−π, π], and the NEES formed from it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "legofeup/core/consistency.hpp"
#include "legofeup/core/pose_error.hpp"

namespace legofeup {
namespace {

TEST(PoseError, IsEstimateMinusTruth) {
    // Estimate (1.30, 2.00, 0.50) against truth (1.00, 2.25, 0.20): 30 cm too far along +x,
    // 25 cm short along +y, turned 0.3 rad too far counter-clockwise.
    const PoseError e = pose_error(Pose2{1.30, 2.00, 0.50}, Pose2{1.00, 2.25, 0.20});
    EXPECT_NEAR(e.x, 0.30, 1e-15);
    EXPECT_NEAR(e.y, -0.25, 1e-15);
    EXPECT_NEAR(e.theta, 0.30, 1e-15);
    EXPECT_NEAR(e.position(), std::sqrt(0.09 + 0.0625), 1e-15);  // √0.1525 = 0.3905 m
    EXPECT_NEAR(e.heading(), 0.30, 1e-15);
    // The state-vector overload and the vector form say the same.
    const StateVector v =
        pose_error(StateVector(1.30, 2.00, 0.50), Pose2{1.00, 2.25, 0.20}).vector();
    EXPECT_NEAR(v(kX), 0.30, 1e-15);
    EXPECT_NEAR(v(kY), -0.25, 1e-15);
    EXPECT_NEAR(v(kTheta), 0.30, 1e-15);
    // Swapping the arguments flips every sign: the order is the convention.
    const PoseError swapped = pose_error(Pose2{1.00, 2.25, 0.20}, Pose2{1.30, 2.00, 0.50});
    EXPECT_NEAR(swapped.x, -0.30, 1e-15);
    EXPECT_NEAR(swapped.y, 0.25, 1e-15);
    EXPECT_NEAR(swapped.theta, -0.30, 1e-15);
}

TEST(PoseError, HeadingIsWrappedAcrossPlusMinusPi) {
    // θ̂ = π − 0.01 (179.43°) against θ = −π + 0.01 (−179.43°): θ̂ − θ = 2π − 0.02 unwrapped,
    // but the estimate is 0.02 rad clockwise of the truth.
    const PoseError e = pose_error(Pose2{0.0, 0.0, kPi - 0.01}, Pose2{0.0, 0.0, -kPi + 0.01});
    EXPECT_NEAR(e.theta, -0.02, 1e-12);
    EXPECT_NEAR(e.heading(), 0.02, 1e-12);
    EXPECT_NEAR(heading_error(-kPi + 0.01, kPi - 0.01), 0.02, 1e-12);
    // Headings given outside (−π, π] are wrapped too: 370° against 10° is 0.
    EXPECT_NEAR(heading_error(degrees_to_radians(370.0), degrees_to_radians(10.0)), 0.0, 1e-12);
    // Half a turn is +π, never −π (the interval is half-open), whichever way it is reached.
    EXPECT_EQ(heading_error(kPi, 0.0), kPi);
    EXPECT_EQ(heading_error(0.0, kPi), kPi);
    EXPECT_EQ(heading_error(-kPi, 0.0), kPi);
}

TEST(PoseError, AnUnknownTruthGivesNoError) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const PoseError e = pose_error(Pose2{1.0, 2.0, 0.5}, Pose2{nan, nan, nan});
    EXPECT_TRUE(std::isnan(e.x));
    EXPECT_TRUE(std::isnan(e.theta));
    EXPECT_TRUE(std::isnan(e.position()));
    EXPECT_TRUE(std::isnan(normalized_estimation_error(e, StateCovariance::Identity())));
}

TEST(PoseError, NeesIsTheMahalanobisLengthOfTheWrappedError) {
    // x̃ = (0.1, −0.2, −0.02): estimate (0.1, 0, π − 0.01), truth (0, 0.2, −π + 0.01).
    const Pose2 estimate{0.1, 0.0, kPi - 0.01};
    const Pose2 truth{0.0, 0.2, -kPi + 0.01};
    // Diagonal P = diag(0.01, 0.04, 0.0004): each component is one σ off, ε = 1 + 1 + 1.
    const StateCovariance diagonal = StateVector(0.01, 0.04, 0.0004).asDiagonal();
    EXPECT_NEAR(normalized_estimation_error(pose_error(estimate, truth), diagonal), 3.0, 1e-9);
    // Correlated x, y: the block [[a, b], [b, a]] with a = 0.02, b = 0.01 has the inverse
    // [[a, −b], [−b, a]] / (a² − b²), so ε_xy = (a·x̃² − 2b·x̃ỹ + a·ỹ²) / (a² − b²)
    // = (0.0002 + 0.0004 + 0.0008) / 0.0003 = 14/3, plus 1 for θ.
    StateCovariance correlated = diagonal;
    correlated.topLeftCorner<2, 2>() << 0.02, 0.01, 0.01, 0.02;
    EXPECT_NEAR(normalized_estimation_error(pose_error(estimate, truth), correlated),
                14.0 / 3.0 + 1.0, 1e-9);
    // The truth-first overload forms the same x̃.
    EXPECT_NEAR(normalized_estimation_error(to_state(truth), to_state(estimate), correlated),
                14.0 / 3.0 + 1.0, 1e-9);
}

}  // namespace
}  // namespace legofeup
