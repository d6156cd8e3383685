#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "legofeup/core/compass_model.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

constexpr unsigned kCompassThetaOutput = 1U << kTheta;

TEST(CompassModel, JacobiansMatchCentralDifferences) {
    const CompassTuning tuning;
    const CompassOdometryProcessModel model(increment_from_motion(0.03, 0.1, 0.12), tuning);
    // Away from multiples of π/2, where √|cos θ|, √|sin θ| are smooth.
    for (const StateVector& x : {StateVector(0.1, 0.2, 0.4), StateVector(-1.0, 0.5, 2.5),
                                 StateVector(0.0, 0.0, -3.0), StateVector(1.0, -1.0, -1.2)}) {
        const auto f = [&](const StateVector& s) { return model.predict_state(s); };
        EXPECT_LT((model.state_jacobian(x)
                   - testing::central_difference<3, 3>(f, x, 1e-6, kCompassThetaOutput))
                      .cwiseAbs()
                      .maxCoeff(),
                  1e-7);
        const auto g = [&](const StateVector& q) { return model.propagate(x, q); };
        EXPECT_LT((model.noise_jacobian(x)
                   - testing::central_difference<3, 3>(g, StateVector::Zero().eval(), 1e-6,
                                                       kCompassThetaOutput))
                      .cwiseAbs()
                      .maxCoeff(),
                  1e-7);
        const CompassMeasurement compass(0.3, 1e-2);
        const auto h = [&](const StateVector& s) { return compass.predict_measurement(s); };
        EXPECT_LT((compass.jacobian(x) - testing::central_difference<1, 3>(h, x, 1e-6, 1U))
                      .cwiseAbs()
                      .maxCoeff(),
                  1e-7);
    }
}

TEST(CompassModel, ProcessNoiseFollowsEquation5) {
    CompassTuning tuning;
    tuning.k_d = 2e-3;
    tuning.k_dtheta = 1e-3;
    tuning.k_theta = 5e-3;
    const StateVector x(0.0, 0.0, 0.6);
    const double floor = kCompassProcessNoiseFloor;

    const CompassOdometryProcessModel still(increment_from_motion(0.0, 0.0, 0.12), tuning);
    EXPECT_EQ(still.noise_covariance(), floor * StateCovariance::Identity());

    for (const double distance : {0.01, 0.02, -0.04}) {
        const double rotation = 0.05;
        const CompassOdometryProcessModel model(increment_from_motion(distance, rotation, 0.12),
                                                tuning);
        const StateCovariance Q = model.pose_noise(x);
        const double c = std::abs(std::cos(0.6));
        const double s = std::abs(std::sin(0.6));
        EXPECT_NEAR(Q(kX, kX), tuning.k_d * std::abs(distance) * c + c * floor, 1e-18);
        EXPECT_NEAR(Q(kY, kY), tuning.k_d * std::abs(distance) * s + s * floor, 1e-18);
        EXPECT_NEAR(Q(kTheta, kTheta),
                    tuning.k_dtheta * std::abs(distance) + tuning.k_theta * rotation + floor,
                    1e-18);
        EXPECT_EQ(Q(kX, kY), 0.0);
    }
    // Linear in |ΔD| (no rotation): doubling the distance doubles Q less its floor.
    const auto q_of = [&](double distance) {
        return CompassOdometryProcessModel(increment_from_motion(distance, 0.0, 0.12), tuning)
            .pose_noise(x);
    };
    const StateCovariance floor_part = q_of(0.0);
    EXPECT_LT(((q_of(0.02) - floor_part) - 2.0 * (q_of(0.01) - floor_part)).cwiseAbs().maxCoeff(),
              1e-18);
    // The EKF's prediction adds exactly eq. 5 at the prior heading.
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ASSERT_TRUE(ekf.reset(x, 1e-4 * StateCovariance::Identity()));
    const CompassOdometryProcessModel model(increment_from_motion(0.02, 0.0, 0.12), tuning);
    ASSERT_EQ(ekf.predict(model), StepStatus::Applied);
    const StateCovariance F = model.state_jacobian(x);
    EXPECT_LT((ekf.covariance()
               - (F * (1e-4 * StateCovariance::Identity()) * F.transpose() + model.pose_noise(x)))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-15);
}

TEST(CompassModel, MeasurementWrapsAndAveragesAcrossPi) {
    const CompassMeasurement compass(3.0 * kPi / 2.0, 1e-2);
    EXPECT_NEAR(compass.measurement()(0), -kPi / 2.0, 1e-12);
    using V = CompassMeasurement::Vector;
    EXPECT_NEAR(compass.residual(V(-kPi + 0.1), V(kPi - 0.1))(0), 0.2, 1e-12);
    const std::array<V, 3> points{V(kPi - 0.05), V(-kPi + 0.05), V(kPi - 0.15)};
    EXPECT_NEAR(compass.weighted_mean(points, std::array<double, 3>{0.0, 0.5, 0.5})(0), kPi - 0.05,
                1e-12);
}

// 6 m straight along +x in 1 cm steps. The odometry believes the robot turns 0.002 rad per
// step (a wheel-diameter mismatch): alone, its heading drifts to 1.2 rad. With the compass
// (σ = 8°, tuning defaults) the heading error stays below 0.25 rad over the whole drive
// (steady-state lag ≈ bias/K ≈ 0.08 rad plus noise), for EKF and UKF and 3 seeds.
template <class Filter>
void compass_bounds_the_heading_error(Filter& filter) {
    CompassTuning tuning;
    tuning.k_d = 1e-4;
    tuning.k_dtheta = 1e-3;
    tuning.k_theta = 1e-3;
    tuning.r_compass = std::pow(degrees_to_radians(8.0), 2);
    for (unsigned seed = 1; seed <= 3; ++seed) {
        std::mt19937_64 rng(seed);
        std::normal_distribution<double> noise(0.0, std::sqrt(tuning.r_compass));
        Filter odometry_only;
        const StateCovariance P0 = Eigen::Vector3d(1e-4, 1e-4, 1e-3).asDiagonal();
        ASSERT_TRUE(filter.reset(StateVector::Zero(), P0));
        ASSERT_TRUE(odometry_only.reset(StateVector::Zero(), P0));
        double worst = 0.0;
        for (int k = 0; k < 600; ++k) {
            const CompassOdometryProcessModel model(increment_from_motion(0.01, 0.002, 0.12),
                                                    tuning);
            ASSERT_EQ(filter.predict(model), StepStatus::Applied);
            ASSERT_EQ(odometry_only.predict(model), StepStatus::Applied);
            ASSERT_EQ(filter.update(CompassMeasurement(noise(rng), tuning.r_compass)).status,
                      StepStatus::Applied);
            worst = std::max(worst, std::abs(filter.state()(kTheta)));
        }
        EXPECT_LT(worst, 0.25) << "seed " << seed;
        EXPECT_NEAR(odometry_only.state()(kTheta), 1.2, 1e-9);
        // The odometry's belief in its heading keeps growing; the compass bounds it.
        EXPECT_GT(odometry_only.covariance()(kTheta, kTheta),
                  10.0 * filter.covariance()(kTheta, kTheta));
    }
}

TEST(CompassModel, CompassBoundsTheHeadingErrorWhileOdometryDrifts) {
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    compass_bounds_the_heading_error(ekf);
    UnscentedKalmanFilter<PoseStateSpace> ukf;
    compass_bounds_the_heading_error(ukf);
}

}  // namespace
}  // namespace legofeup
