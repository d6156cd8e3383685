#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

TEST(BeaconBearing, PredictsTheBearingRelativeToTheHeading) {
    const BeaconBearingMeasurement m(Vector2(2.0, 1.0), 0.0, 1e-2);
    // From (1, 0) the beacon is at 45°; heading 30° leaves 15° to the left.
    EXPECT_NEAR(m.predict_measurement(StateVector(1.0, 0.0, kPi / 6))(0), kPi / 12, 1e-12);
    // Behind the robot: wrapped to (−π, π].
    EXPECT_NEAR(m.predict_measurement(StateVector(3.0, 1.0, 0.0))(0), kPi, 1e-12);
    EXPECT_NEAR(m.residual(Eigen::Matrix<double, 1, 1>(kPi - 0.1),
                           Eigen::Matrix<double, 1, 1>(-kPi + 0.1))(0),
                -0.2, 1e-12);
}

TEST(BeaconBearing, JacobianMatchesCentralDifferences) {
    const BeaconBearingMeasurement m(Vector2(1.5, -0.5), 0.3, 1e-2);
    const std::array<StateVector, 5> poses{
        StateVector(0.0, 0.0, 0.0), StateVector(1.2, 0.7, 2.9),
        StateVector(-1.0, -0.5, -3.1),  // beacon dead ahead, θ≈±π
        StateVector(1.5, 1.0, 1.0),     // Δx = 0
        StateVector(3.0, -0.49, kPi)};  // h ≈ ±π
    for (const StateVector& x : poses) {
        const auto h = [&](const StateVector& s) { return m.predict_measurement(s); };
        const Eigen::Matrix<double, 1, 3> numeric =
            testing::central_difference<1, 3>(h, x, 1e-6, 1U);
        EXPECT_LT((m.jacobian(x) - numeric).cwiseAbs().maxCoeff(), 1e-7) << x.transpose();
    }
}

TEST(BeaconBearing, OnTheBeaconIsNotUsableButStaysFinite) {
    const BeaconBearingMeasurement m(Vector2(1.0, 1.0), 0.3, 1e-2);
    const StateVector on(1.0, 1.0 + 5e-4, 0.2);
    EXPECT_FALSE(m.usable(on));
    EXPECT_TRUE(m.usable(StateVector(1.0, 1.002, 0.2)));
    EXPECT_TRUE(m.predict_measurement(on).allFinite());
    EXPECT_TRUE(m.jacobian(on).allFinite());
    EXPECT_TRUE(m.jacobian(StateVector(1.0, 1.0, 0.0)).allFinite());
}

// A static robot, a wrong prior (0.9 m and 0.5 rad off) and four beacons at the corners of a
// 3 m square, bearings with σ = 0.05 rad: after 100 periods (400 bearings) the position is
// within 5 cm and the heading within 0.03 rad (the CRLB is ≈ 1 cm), for 10 seeds.
template <class Filter>
void localises_a_static_robot(Filter& filter) {
    const std::array<Vector2, 4> beacons{Vector2(1.5, 1.5), Vector2(-1.5, 1.5), Vector2(-1.5, -1.5),
                                         Vector2(1.5, -1.5)};
    const StateVector truth(0.3, -0.2, 0.5);
    const double sigma = 0.05;
    for (unsigned seed = 1; seed <= 10; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> noise(0.0, sigma);
        ASSERT_TRUE(
            filter.reset(StateVector(-0.5, 0.2, 0.0), Eigen::Vector3d(1.0, 1.0, 0.5).asDiagonal()));
        const OdometryProcessModel still(increment_from_motion(0.0, 0.0, 0.12),
                                         Eigen::Vector2d(1e-8, 1e-8).asDiagonal());
        for (int step = 0; step < 100; ++step) {
            ASSERT_EQ(filter.predict(still), StepStatus::Applied);
            for (const Vector2& beacon : beacons) {
                const BeaconBearingMeasurement exact(beacon, 0.0, sigma * sigma);
                const double bearing = exact.predict_measurement(truth)(0) + noise(rng);
                const auto report =
                    filter.update(BeaconBearingMeasurement(beacon, bearing, sigma * sigma));
                ASSERT_EQ(report.status, StepStatus::Applied);
            }
        }
        const StateVector error = PoseStateSpace::difference(filter.state(), truth);
        EXPECT_LT(error.head<2>().norm(), 0.05) << "seed " << seed;
        EXPECT_LT(std::abs(error(kTheta)), 0.03) << "seed " << seed;
    }
}

TEST(BeaconBearing, EkfLocalisesAStaticRobotFromAWrongPrior) {
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    localises_a_static_robot(ekf);
}

TEST(BeaconBearing, UkfLocalisesAStaticRobotFromAWrongPrior) {
    UnscentedKalmanFilter<PoseStateSpace> ukf;
    localises_a_static_robot(ukf);
}

}  // namespace
}  // namespace legofeup
