#include <gtest/gtest.h>

#include <cmath>

#include "kinematic_world.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

using testing::Uniform;

TEST(IrGeometry, BeamsStartAtTheMountsAndLookRight) {
    const IrMount mount;                    // front +5 cm, rear −5 cm, 6 cm to the right
    const Pose2 pose{1.0, 2.0, kPi / 2.0};  // heading +y: the right side faces +x
    const IrBeam front = ir_beam(pose, mount, kFrontSensor);
    const IrBeam rear = ir_beam(pose, mount, kRearSensor);
    EXPECT_NEAR(front.origin.x(), 1.06, 1e-12);
    EXPECT_NEAR(front.origin.y(), 2.05, 1e-12);
    EXPECT_NEAR(rear.origin.x(), 1.06, 1e-12);
    EXPECT_NEAR(rear.origin.y(), 1.95, 1e-12);
    EXPECT_NEAR(front.direction.x(), 1.0, 1e-12);
    EXPECT_NEAR(front.direction.y(), 0.0, 1e-12);
}

TEST(IrGeometry, BothBeamsAtOnceAreEachBeamsOwnBits) {
    const IrMount mount{0.07, -0.04, 0.055};
    for (const double theta : {-3.0, -1.2, 0.0, 0.3, kPi / 2.0, 2.9}) {
        const Pose2 pose{0.31, -0.77, theta};
        const auto beams = ir_beams(pose, mount);
        for (const int sensor : {kFrontSensor, kRearSensor}) {
            const IrBeam one = ir_beam(pose, mount, sensor);
            const IrBeam& both = beams[static_cast<std::size_t>(sensor)];
            EXPECT_EQ(both.origin, one.origin) << theta << " sensor " << sensor;
            EXPECT_EQ(both.direction, one.direction) << theta << " sensor " << sensor;
        }
    }
}

TEST(IrGeometry, CastBeamHitsMissesAndHonoursTheMargin) {
    const WallLine wall = make_wall_line({"w", {0.0, -1.0}, {1.0, -1.0}});
    IrBeam beam{{0.5, -0.8}, {0.0, -1.0}};
    BeamHit hit = cast_beam(beam, wall, 0.0);
    EXPECT_TRUE(hit.hit);
    EXPECT_NEAR(hit.range, 0.2, 1e-12);
    EXPECT_NEAR(hit.along, 0.5, 1e-12);

    beam.origin = {1.05, -0.8};  // 5 cm past the wall's end
    EXPECT_FALSE(cast_beam(beam, wall, 0.0).hit);
    EXPECT_TRUE(cast_beam(beam, wall, 0.10).hit);

    beam.direction = {0.0, 1.0};  // looking away
    EXPECT_FALSE(cast_beam(beam, wall, 0.10).hit);
    beam.direction = {1.0, 0.0};  // parallel
    EXPECT_FALSE(cast_beam(beam, wall, 0.10).hit);
}

// Eq. 3 against the independent ray geometry: the readings a robot at a known pose would
// get must give back its heading and its centre's distance to the wall, exactly.
void expect_observation_recovers_pose(const IrMount& mount, unsigned seed) {
    const std::vector<Wall> walls{{"wall_y-", {-20.0, -1.21}, {20.0, -1.21}}};
    Uniform uniform(seed);
    for (int i = 0; i < 500; ++i) {
        const Pose2 pose{uniform(-1.0, 1.0), uniform(-1.1, -0.9), uniform(-0.6, 0.6)};
        const auto ds = testing::true_ir_distances(
            pose, walls, mount.lateral_offset, mount.front_longitudinal, mount.rear_longitudinal);
        const WallObservation obs = observe_wall(ds[0], ds[1], mount);
        EXPECT_NEAR(obs.angle, pose.theta, 1e-12);  // facing wall_y− means heading 0
        EXPECT_NEAR(obs.centre_distance, pose.y + 1.21, 1e-12);
        EXPECT_NEAR(obs.sensor_distance, (0.5 * (ds[0] + ds[1])) * std::cos(pose.theta), 1e-12);
    }
}

TEST(IrGeometry, ObservationRecoversHeadingAndCentreDistance) {
    expect_observation_recovers_pose(IrMount{}, 11);
}

TEST(IrGeometry, ObservationHandlesAsymmetricMounts) {
    IrMount mount;
    mount.front_longitudinal = 0.08;
    mount.rear_longitudinal = -0.03;
    mount.lateral_offset = 0.045;
    expect_observation_recovers_pose(mount, 12);
}

TEST(IrGeometry, JacobianMatchesThePapersEquations18To20WithoutOffsets) {
    IrMount centred;  // the paper's idealisation: sensors on the centre line, e = m = 0
    centred.lateral_offset = 0.0;
    Uniform uniform(13);
    for (int i = 0; i < 200; ++i) {
        const double ds1 = uniform(0.05, 0.28);
        const double ds2 = uniform(0.05, 0.28);
        const double L = centred.separation();
        const double obs_angle = std::atan((ds1 - ds2) / L);
        const double dangle = L / (L * L + (ds1 - ds2) * (ds1 - ds2));       // eq. 18
        const double a = 0.5 * std::cos(obs_angle);                          // eq. 19
        const double b = -(ds1 + ds2) / 2.0 * std::sin(obs_angle) * dangle;  // eq. 19
        const Eigen::Matrix2d J = observe_wall(ds1, ds2, centred).jacobian;
        EXPECT_NEAR(J(0, 0), a + b, 1e-12);  // eq. 20 with signal = 1
        EXPECT_NEAR(J(0, 1), a - b, 1e-12);
        EXPECT_NEAR(J(1, 0), dangle, 1e-12);
        EXPECT_NEAR(J(1, 1), -dangle, 1e-12);
    }
}

TEST(IrGeometry, JacobianMatchesCentralDifferences) {
    IrMount mount;
    mount.front_longitudinal = 0.07;  // non-zero midpoint exercises every term
    Uniform uniform(14);
    for (int i = 0; i < 500; ++i) {
        const Eigen::Vector2d ds(uniform(0.04, 0.30), uniform(0.04, 0.30));
        const auto observation = [&](const Eigen::Vector2d& r) {
            const WallObservation o = observe_wall(r(0), r(1), mount);
            return Eigen::Vector2d(o.centre_distance, o.angle);
        };
        const Eigen::Matrix2d numeric = testing::central_difference<2, 2>(observation, ds);
        const Eigen::Matrix2d analytic = observe_wall(ds(0), ds(1), mount).jacobian;
        EXPECT_LT((numeric - analytic).cwiseAbs().maxCoeff(), 1e-7) << "at " << ds.transpose();
    }
}

}  // namespace
}  // namespace legofeup
