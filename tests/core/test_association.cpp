#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_world.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"
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

// P and R of the standard scenario's start (docs/loop.md): σ 1 cm in x and y, 1.8° in θ;
// σ 1 cm on each IR distance.
const StateCovariance kP = StateVector(1e-4, 1e-4, 1e-3).asDiagonal();
const Eigen::Matrix2d kR = Eigen::Vector2d(1e-4, 1e-4).asDiagonal();

AssociationResult associate(const Pose2& estimate, const WallObservation& observation,
                            const AssociationParams& params = {}) {
    return associate_wall({estimate, kP}, observation, kArena, IrMount{}, kMaxRange, kR, params);
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
        associate_wall({{0.0, 0.0, 0.0}, kP}, obs, two, IrMount{}, kMaxRange, kR, {});
    EXPECT_EQ(result.wall, 0);
    EXPECT_TRUE(result.associated());
}

// The Mahalanobis gate worked by hand. A wall along y = −0.2 (x from −1 to 1), the robot at
// the origin heading +x, both sensors reading 0.14 m: ObsAng = 0 and D_c = 0.14 + 0.06 = 0.20.
// The estimate (0, 0.05, 0.02) is 5 cm too far from the wall and turned by 0.02 rad.
//
//   z = [n·p, θ] with n = (0, 1), c = −0.2, σ = +1: z = [−0.2 + 0.20, 0 + 0] = [0, 0];
//   h(X̂) = [0.05, 0.02], so ν = [−0.05, −0.02].
//   ∇h_X = [0 1 0; 0 0 1] picks P's (y, θ) block: [4e-4 2e-4; 2e-4 1e-3].
//   ∂(D_c, ObsAng)/∂(d_s1, d_s2) at ObsAng = 0 is [½ ½; 1/L −1/L] with L = 0.1, so with
//   R = 1e-4·I, ∇h_r R ∇h_rᵀ = diag(½·1e-4, 200·1e-4) = diag(5e-5, 2e-2).
//   S = [4.5e-4 2e-4; 2e-4 2.1e-2], det S = 9.45e-6 − 4e-8 = 9.41e-6,
//   νᵀ adj(S) ν = 2.1e-2·2.5e-3 − 2·2e-4·1e-3 + 4.5e-4·4e-4 = 5.228e-5,
//   d² = 5.228e-5 / 9.41e-6 = 5.5558...
// χ²(2) is exponential with mean 2, so its p-quantile is −2·ln(1 − p): 9.2103 at p = 0.99
// (d² passes) and 4.6052 at p = 0.9 (d² is refused).
TEST(AssociationMahalanobisGate, MatchesAHandWorkedExample) {
    const WallMap one({{"wall", {-1.0, -0.2}, {1.0, -0.2}}});
    const WallObservation obs = observe_wall(0.14, 0.14, IrMount{});
    ASSERT_NEAR(obs.centre_distance, 0.20, 1e-12);
    StateCovariance P = StateVector(1e-4, 4e-4, 1e-3).asDiagonal();
    P(kY, kTheta) = P(kTheta, kY) = 2e-4;
    const PoseBelief belief{{0.0, 0.05, 0.02}, P};
    const double hand_d2 = 5.228e-5 / 9.41e-6;

    AssociationParams params;
    params.gate = AssociationGate::Mahalanobis;
    const AssociationResult passed =
        associate_wall(belief, obs, one, IrMount{}, kMaxRange, kR, params);
    EXPECT_EQ(passed.gate, AssociationGate::Mahalanobis);
    EXPECT_NEAR(passed.mahalanobis_d2, hand_d2, 1e-9);
    EXPECT_NEAR(passed.mahalanobis_threshold, -2.0 * std::log(1.0 - 0.99), 1e-9);
    EXPECT_EQ(passed.outcome, AssociationOutcome::Associated);

    params.gate_probability = 0.9;
    const AssociationResult refused =
        associate_wall(belief, obs, one, IrMount{}, kMaxRange, kR, params);
    EXPECT_NEAR(refused.mahalanobis_threshold, -2.0 * std::log(0.1), 1e-9);
    EXPECT_NEAR(refused.mahalanobis_d2, hand_d2, 1e-9);
    EXPECT_EQ(refused.outcome, AssociationOutcome::MahalanobisMismatch);

    // The fixed gates (5 cm and 1.1°, under 10 cm and 20°) take it, and still report d².
    const AssociationResult fixed =
        associate_wall(belief, obs, one, IrMount{}, kMaxRange, kR, AssociationParams{});
    EXPECT_EQ(fixed.gate, AssociationGate::Fixed);
    EXPECT_EQ(fixed.outcome, AssociationOutcome::Associated);
    EXPECT_NEAR(fixed.mahalanobis_d2, hand_d2, 1e-9);
}

// d² is the NIS the filter's update computes for the same wall (S = ∇h_X P ∇h_Xᵀ + R_z in
// both), for the EKF and for the UKF, whose sigma points reproduce a linear h exactly; the
// particle filter's S is its cloud's sample covariance of h plus R, the same to sampling
// error (10⁵ particles: about 0.5 % on each variance).
TEST(AssociationMahalanobisGate, DistanceIsTheUpdatesNis) {
    const Pose2 truth = pose_at(kArena.line(2), -1, 0.21, 0.05);
    const Pose2 estimate{truth.x + 0.06, truth.y - 0.03, truth.theta - 0.04};
    StateCovariance P = StateVector(9e-4, 4e-4, 2e-3).asDiagonal();
    P(kX, kTheta) = P(kTheta, kX) = -3e-4;
    const WallObservation obs = observe_from(truth);
    AssociationParams params;
    params.gate = AssociationGate::Mahalanobis;
    const AssociationResult result =
        associate_wall({estimate, P}, obs, kArena, IrMount{}, kMaxRange, kR, params);
    ASSERT_EQ(result.wall, 2);
    for (const PoseEstimatorEntry& entry : pose_estimators()) {
        const FilterKind kind = entry.kind;
        const std::unique_ptr<PoseEstimator> filter = entry.make();
        const bool sampled = kind == FilterKind::Pf;
        if (sampled) {
            PoseEstimatorSettings settings;
            settings.particles.particle_count = 100000;
            filter->configure(settings);
        }
        filter->reset(to_state(estimate), P);
        const auto report = filter->update(WallMeasurement(kArena.line(2), result.side, obs, kR),
                                           MahalanobisGate{});
        ASSERT_EQ(report.status, StepStatus::Applied) << to_string(kind);
        EXPECT_NEAR(result.mahalanobis_d2, report.nis, (sampled ? 0.03 : 1e-9) * report.nis)
            << to_string(kind);
    }
}

// The bar of issue 20: 15 cm across a wall the fixed gates refuse the wall however large P
// is; the Mahalanobis gate refuses it while P says the estimate is good to a centimetre or
// two, and takes it once P has grown to cover the error.
TEST(AssociationMahalanobisGate, WidensWithTheCovarianceWhereTheFixedGatesDoNot) {
    const Pose2 truth = pose_at(kArena.line(0), 1, 0.21, 0.0);
    const WallLine& wall = kArena.line(0);
    const Pose2 estimate{truth.x + 0.15 * wall.normal.x(), truth.y + 0.15 * wall.normal.y(),
                         truth.theta};
    const WallObservation obs = observe_from(truth);
    AssociationParams mahalanobis;
    mahalanobis.gate = AssociationGate::Mahalanobis;
    struct Case {
        double sigma;  // of x and y, m
        AssociationOutcome mahalanobis;
    };
    for (const Case c :
         {Case{0.01, AssociationOutcome::MahalanobisMismatch},
          Case{0.02, AssociationOutcome::MahalanobisMismatch},
          Case{0.03, AssociationOutcome::MahalanobisMismatch},
          Case{0.06, AssociationOutcome::Associated}, Case{0.1, AssociationOutcome::Associated},
          Case{0.3, AssociationOutcome::Associated}}) {
        const double var = c.sigma * c.sigma;
        const StateCovariance P = StateVector(var, var, 1e-3).asDiagonal();
        const auto fixed = associate_wall({estimate, P}, obs, kArena, IrMount{}, kMaxRange, kR, {});
        const auto gated =
            associate_wall({estimate, P}, obs, kArena, IrMount{}, kMaxRange, kR, mahalanobis);
        EXPECT_EQ(fixed.outcome, AssociationOutcome::DistanceMismatch) << c.sigma;
        EXPECT_EQ(gated.outcome, c.mahalanobis) << c.sigma;
        EXPECT_NEAR(gated.distance_error, -0.15, 1e-9);
    }
}

TEST(AssociationMahalanobisGate, GatesHaveNamesThatReadBack) {
    for (const AssociationGate gate : {AssociationGate::Fixed, AssociationGate::Mahalanobis}) {
        EXPECT_EQ(association_gate_from_string(to_string(gate)), gate);
    }
    EXPECT_STREQ(to_string(AssociationGate::Mahalanobis), "mahalanobis");
    EXPECT_FALSE(association_gate_from_string("chi2").has_value());
}

TEST(Association, OutcomesHaveReadableNames) {
    EXPECT_STREQ(to_string(AssociationOutcome::NoWallInView), "no wall in view of both sensors");
    EXPECT_STREQ(to_string(AssociationOutcome::Associated), "associated");
}

}  // namespace
}  // namespace legofeup
