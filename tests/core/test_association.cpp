#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_world.hpp"
#include "legofeup/core/wall_association.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {
namespace {

const WallMap kArena = standard_arena_walls(ArenaSpec{});
constexpr double kMaxRange = 0.30;

// The pose `distance` from the middle of a wall on side σ, turned by `turn` (independent
// construction as in test_wall_measurement.cpp).
Pose2 pose_at(const WallLine& wall, int side, double distance, double turn) {
    const double s = side;
    const Vector2 p = wall.start + 0.5 * wall.length * wall.direction + s * distance * wall.normal;
    return {p.x(), p.y(), wrap_angle(std::atan2(-s * wall.normal.x(), s * wall.normal.y()) + turn)};
}

WallObservation observe_from(const Pose2& truth) {
    const auto ds = testing::true_ir_distances(truth, kArena.walls());
    return observe_wall(ds[0], ds[1], IrMount{});
}

AssociationResult associate(const Pose2& estimate, const WallObservation& observation,
                            const AssociationParams& params = {}) {
    return associate_wall(estimate, observation, kArena, IrMount{}, kMaxRange, params);
}

TEST(Association, FindsEachWallFromEachSide) {
    for (int wall = 0; wall < kArena.size(); ++wall) {
        for (int side : {-1, 1}) {
            for (double turn : {-0.3, 0.0, 0.25}) {
                const Pose2 truth = pose_at(kArena.line(wall), side, 0.2, turn);
                // The estimate is a little off, as it always is.
                const Pose2 estimate{truth.x + 0.02, truth.y - 0.02, truth.theta + 0.03};
                const AssociationResult result = associate(estimate, observe_from(truth));
                EXPECT_EQ(result.outcome, AssociationOutcome::Associated)
                    << kArena.wall(wall).name << " side " << side << ": "
                    << to_string(result.outcome);
                EXPECT_EQ(result.wall, wall);
                EXPECT_EQ(result.side, side);
                EXPECT_NEAR(result.predicted_angle, turn + 0.03, 1e-9);
                EXPECT_LT(std::abs(result.distance_error), 0.05);
            }
        }
    }
}

TEST(Association, PredictedBeamsMatchTheTruthWhenTheEstimateIsExact) {
    const Pose2 truth = pose_at(kArena.line(1), -1, 0.18, 0.1);
    const auto ds = testing::true_ir_distances(truth, kArena.walls());
    const AssociationResult result = associate(truth, observe_wall(ds[0], ds[1], IrMount{}));
    ASSERT_TRUE(result.associated());
    EXPECT_NEAR(result.predicted_ds_front, ds[0], 1e-12);
    EXPECT_NEAR(result.predicted_ds_rear, ds[1], 1e-12);
    EXPECT_NEAR(result.angle_error, 0.0, 1e-12);
    EXPECT_NEAR(result.distance_error, 0.0, 1e-12);
}

TEST(Association, NoWallInViewFromTheMiddleOfTheArena) {
    const WallObservation fake = observe_wall(0.15, 0.15, IrMount{});
    const AssociationResult result = associate({0.0, 0.0, 0.0}, fake);
    EXPECT_EQ(result.outcome, AssociationOutcome::NoWallInView);
    EXPECT_EQ(result.wall, -1);
}

TEST(Association, NoWallInViewPastTheEndOfAWall) {
    // The walls cover the first metre of each side; on the second half of the first side
    // (x > 0) there is nothing to the right, beyond the 10 cm margin.
    const WallObservation fake = observe_wall(0.15, 0.15, IrMount{});
    EXPECT_EQ(associate({0.25, -1.0, 0.0}, fake).outcome, AssociationOutcome::NoWallInView);
    EXPECT_EQ(associate({0.04, -1.0, 0.0}, fake).outcome, AssociationOutcome::Associated);
}

TEST(Association, RejectsObliqueIncidence) {
    // Turning at a corner next to a wall: the estimate says the beams meet it at 50°.
    const Pose2 truth = pose_at(kArena.line(0), 1, 0.15, degrees_to_radians(50.0));
    const AssociationResult result = associate(truth, observe_from(truth));
    EXPECT_EQ(result.outcome, AssociationOutcome::ObliqueIncidence);
    EXPECT_EQ(result.wall, 0);
}

TEST(Association, RejectsAnAngleThatDoesNotFit) {
    const Pose2 estimate = pose_at(kArena.line(0), 1, 0.2, 0.0);
    const WallObservation turned = observe_wall(0.25, 0.20, IrMount{});  // ObsAng ≈ 26.6°
    const AssociationResult result = associate(estimate, turned);
    EXPECT_EQ(result.outcome, AssociationOutcome::AngleMismatch);
    EXPECT_NEAR(result.angle_error, std::atan(0.5), 1e-12);
}

TEST(Association, RejectsADistanceThatDoesNotFit) {
    // The estimate is 15 cm from the wall's line; the sensors say the centre is 32 cm away.
    const Pose2 estimate = pose_at(kArena.line(0), 1, 0.15, 0.0);
    const WallObservation far = observe_wall(0.26, 0.26, IrMount{});
    const AssociationResult result = associate(estimate, far);
    EXPECT_EQ(result.outcome, AssociationOutcome::DistanceMismatch);
    EXPECT_NEAR(result.distance_error, 0.32 - 0.15, 1e-12);
}

TEST(Association, TakesTheNearestOfTwoWallsInLine) {
    const WallMap two({{"near", {-1.0, -0.2}, {1.0, -0.2}}, {"far", {-1.0, -0.35}, {1.0, -0.35}}});
    const WallObservation obs = observe_wall(0.14, 0.14, IrMount{});
    const AssociationResult result =
        associate_wall({0.0, 0.0, 0.0}, obs, two, IrMount{}, kMaxRange, AssociationParams{});
    EXPECT_EQ(result.wall, 0);
    EXPECT_TRUE(result.associated());
}

TEST(Association, OutcomesHaveReadableNames) {
    EXPECT_STREQ(to_string(AssociationOutcome::NoWallInView), "no wall in view of both sensors");
    EXPECT_STREQ(to_string(AssociationOutcome::Associated), "associated");
}

}  // namespace
}  // namespace legofeup
