#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_world.hpp"
#include "legofeup/core/wall_measurement.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

using testing::Uniform;

const Eigen::Matrix2d kIrCovariance = Eigen::Vector2d(1e-4, 2e-4).asDiagonal();

// A pose `distance` from the wall's middle on side σ, turned by `turn` from looking
// straight at it. The heading is found independently: the sensors look along the robot's
// −y axis (sin h, −cos h), which must equal −σ·n when turn = 0.
Pose2 pose_facing(const WallLine& wall, int side, double distance, double along, double turn) {
    const double s = side;
    const Vector2 point = wall.start + along * wall.direction + s * distance * wall.normal;
    const double heading = std::atan2(-s * wall.normal.x(), s * wall.normal.y());
    return {point.x(), point.y(), wrap_angle(heading + turn)};
}

WallMeasurement measure(const WallLine& line, int side, const Pose2& pose,
                        const std::vector<Wall>& walls) {
    const auto ds = testing::true_ir_distances(pose, walls);
    return WallMeasurement(line, side, observe_wall(ds[0], ds[1], IrMount{}), kIrCovariance);
}

TEST(WallMeasurement, StandardWallsHaveThePapersNormalsAndSignals) {
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    ASSERT_EQ(arena.size(), 4);
    // Canonical normals: +y for the y walls, +x for the x walls (z₁ = y or x, eq. 4–5).
    const Vector2 expected_normals[] = {{0, 1}, {1, 0}, {0, 1}, {1, 0}};
    const double expected_offsets[] = {-1.21, 1.21, 1.21, -1.21};
    // From inside the square the robot is on the −n side of x+ and y+: the paper's
    // "signal" is −1 there and +1 for x− and y−.
    const int inside_side[] = {1, -1, -1, 1};
    for (int i = 0; i < 4; ++i) {
        const WallLine& line = arena.line(i);
        EXPECT_NEAR((line.normal - expected_normals[i]).norm(), 0.0, 1e-12) << i;
        EXPECT_NEAR(line.offset, expected_offsets[i], 1e-12) << i;
        EXPECT_EQ(line.signed_distance({0.0, 0.0}) > 0.0 ? 1 : -1, inside_side[i]) << i;
        EXPECT_NEAR(line.length, 1.0, 1e-12);
    }
    EXPECT_EQ(arena.wall(0).name, "wall_y-");
    EXPECT_EQ(arena.wall(1).name, "wall_x+");
    EXPECT_EQ(arena.wall(2).name, "wall_y+");
    EXPECT_EQ(arena.wall(3).name, "wall_x-");
}

TEST(WallMeasurement, ExactReadingsGiveTheTruePoseComponentsForEveryWallAndSide) {
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    Uniform uniform(21);
    for (int wall = 0; wall < arena.size(); ++wall) {
        for (int side : {-1, 1}) {
            const WallLine& line = arena.line(wall);
            const std::vector<Wall> only_this{arena.wall(wall)};
            for (int i = 0; i < 100; ++i) {
                const Pose2 pose = pose_facing(line, side, uniform(0.10, 0.30), uniform(0.3, 0.7),
                                               uniform(-0.5, 0.5));
                const WallMeasurement m = measure(line, side, pose, only_this);
                const bool x_wall = std::abs(line.normal.x()) > 0.5;
                EXPECT_NEAR(m.measurement()(0), x_wall ? pose.x : pose.y, 1e-12)
                    << arena.wall(wall).name << " side " << side;
                EXPECT_NEAR(wrap_angle(m.measurement()(1) - pose.theta), 0.0, 1e-12)
                    << arena.wall(wall).name << " side " << side;
            }
        }
    }
}

TEST(WallMeasurement, PapersEquationsFourAndFiveWithTheCorrectedSign) {
    // At the wall_x+ the robot heads +y; turned away from the wall by δ the front sensor
    // reads more, ObsAng = δ, and the heading is π/2 + ObsAng (the paper prints π/2 − ObsAng).
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    const double delta = 0.2;
    const Pose2 pose{1.0, -0.5, kPi / 2.0 + delta};
    const auto ds = testing::true_ir_distances(pose, {arena.wall(1)});
    EXPECT_GT(ds[0], ds[1]);
    const WallObservation obs = observe_wall(ds[0], ds[1], IrMount{});
    EXPECT_NEAR(obs.angle, delta, 1e-12);
    const WallMeasurement m(arena.line(1), -1, obs, kIrCovariance);
    EXPECT_NEAR(m.measurement()(1), kPi / 2.0 + obs.angle, 1e-12);
    // x = L_w − D_c, where D_c includes the 6 cm mounting offset (d_w + e·cos ObsAng).
    EXPECT_NEAR(m.measurement()(0), 1.21 - (obs.sensor_distance + 0.06 * std::cos(delta)), 1e-12);
}

TEST(WallMeasurement, DiagonalWallsUseTheirCanonicalNormal) {
    const Wall diagonal{"diagonal", {0.0, 0.0}, {1.0, 1.0}};
    const WallLine line = make_wall_line(diagonal);
    const Vector2 n = Vector2(1.0, -1.0) / std::sqrt(2.0);  // left normal flipped to x > 0
    EXPECT_NEAR((line.normal - n).norm(), 0.0, 1e-12);
    Uniform uniform(22);
    for (int side : {-1, 1}) {
        for (int i = 0; i < 50; ++i) {
            const Pose2 pose =
                pose_facing(line, side, uniform(0.1, 0.25), uniform(0.4, 1.0), uniform(-0.4, 0.4));
            const WallMeasurement m = measure(line, side, pose, {diagonal});
            EXPECT_NEAR(m.measurement()(0), (pose.x - pose.y) / std::sqrt(2.0), 1e-12);
            EXPECT_NEAR(wrap_angle(m.measurement()(1) - pose.theta), 0.0, 1e-12);
        }
    }
}

TEST(WallMeasurement, StateJacobianMatchesCentralDifferences) {
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    Uniform uniform(23);
    for (int wall = 0; wall < arena.size(); ++wall) {
        const WallMeasurement m(arena.line(wall), 1, observe_wall(0.15, 0.16, IrMount{}),
                                kIrCovariance);
        for (int i = 0; i < 100; ++i) {
            const StateVector x(uniform(-2, 2), uniform(-2, 2), uniform(-kPi, kPi));
            const auto h = [&](const StateVector& s) { return m.predict_measurement(s); };
            const auto numeric = testing::central_difference<2, 3>(h, x, 1e-6, 0b10);
            EXPECT_LT((numeric - m.jacobian(x)).cwiseAbs().maxCoeff(), 1e-8);
        }
    }
}

TEST(WallMeasurement, NoiseJacobianMatchesCentralDifferencesOnEverySide) {
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    Uniform uniform(24);
    for (int wall = 0; wall < arena.size(); ++wall) {
        for (int side : {-1, 1}) {
            const WallLine& line = arena.line(wall);
            const auto z_of_readings = [&](const Eigen::Vector2d& r) {
                return WallMeasurement(line, side, observe_wall(r(0), r(1), IrMount{}),
                                       kIrCovariance)
                    .measurement();
            };
            for (int i = 0; i < 50; ++i) {
                const Eigen::Vector2d ds(uniform(0.05, 0.29), uniform(0.05, 0.29));
                const auto numeric =
                    testing::central_difference<2, 2>(z_of_readings, ds, 1e-6, 0b10);
                const WallMeasurement m(line, side, observe_wall(ds(0), ds(1), IrMount{}),
                                        kIrCovariance);
                EXPECT_LT((numeric - m.noise_jacobian()).cwiseAbs().maxCoeff(), 1e-7);
                const Eigen::Matrix2d mapped =
                    m.noise_jacobian() * kIrCovariance * m.noise_jacobian().transpose();
                EXPECT_LT((m.noise_covariance() - mapped).cwiseAbs().maxCoeff(), 1e-18);
            }
        }
    }
}

TEST(WallMeasurement, ResidualWrapsTheHeading) {
    const WallMap arena = standard_arena_walls(ArenaSpec{});
    const WallMeasurement m(arena.line(2), -1, observe_wall(0.15, 0.15, IrMount{}), kIrCovariance);
    const Eigen::Vector2d z(1.0, degrees_to_radians(-179.0));
    const Eigen::Vector2d predicted(0.9, degrees_to_radians(179.0));
    const Eigen::Vector2d nu = m.residual(z, predicted);
    EXPECT_NEAR(nu(0), 0.1, 1e-12);
    EXPECT_NEAR(nu(1), degrees_to_radians(2.0), 1e-12);
}

}  // namespace
}  // namespace legofeup
