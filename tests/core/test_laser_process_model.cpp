// The laser lesson's prediction (paper 001 eq. 11–13) and its H = I pose observation
// (eq. 14–18), checked against central differences and hand-worked numbers.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/laser_pose_measurement.hpp"
#include "legofeup/core/laser_process_model.hpp"
#include "legofeup/core/pose_estimator_registry.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

constexpr unsigned kLaserThetaOutput = 1U << kTheta;

double max_abs(const Eigen::MatrixXd& m) {
    return m.cwiseAbs().maxCoeff();
}

TEST(LaserProcessModel, JacobiansMatchCentralDifferences) {
    const LaserTuning tuning;
    testing::Uniform uniform(11);
    for (int trial = 0; trial < 50; ++trial) {
        const OdometryIncrement increment =
            increment_from_motion(uniform(-0.05, 0.05), uniform(-0.3, 0.3), 0.12);
        // Headings all around the circle, including next to ±π.
        const StateVector x(
            uniform(-3.0, 3.0), uniform(-3.0, 3.0),
            trial < 2 ? (trial == 0 ? kPi - 1e-3 : -kPi + 1e-3) : uniform(-kPi, kPi));
        const LaserProcessModel model(increment, x(kTheta), tuning);
        const auto f = [&](const StateVector& s) { return model.predict_state(s); };
        EXPECT_LT(max_abs(model.state_jacobian(x)
                          - testing::central_difference<3, 3>(f, x, 1e-6, kLaserThetaOutput)),
                  1e-8)
            << "trial " << trial;
        const auto g = [&](const StateVector& q) { return model.propagate(x, q); };
        EXPECT_LT(max_abs(model.noise_jacobian(x)
                          - testing::central_difference<3, 3>(g, StateVector::Zero().eval(), 1e-6,
                                                              kLaserThetaOutput)),
                  1e-8);
    }
}

TEST(LaserProcessModel, StateAndJacobianAreEquations11And12) {
    // d = 0.1 m, Δθ = 0.2 rad from θ = 0.5: φ = 0.6.
    const OdometryIncrement increment = increment_from_motion(0.1, 0.2, 0.12);
    const LaserProcessModel model(increment, 0.5, LaserTuning{});
    const StateVector x(1.0, 2.0, 0.5);
    const double dx = 0.1 * std::cos(0.6);  // 0.0825336
    const double dy = 0.1 * std::sin(0.6);  // 0.0564642
    const StateVector next = model.predict_state(x);
    EXPECT_NEAR(next(kX), 1.0 + dx, 1e-12);
    EXPECT_NEAR(next(kY), 2.0 + dy, 1e-12);
    EXPECT_NEAR(next(kTheta), 0.7, 1e-12);
    const StateCovariance F = model.state_jacobian(x);
    EXPECT_NEAR(F(kX, kTheta), -dy, 1e-12);
    EXPECT_NEAR(F(kY, kTheta), dx, 1e-12);
    StateCovariance unit_part = F;
    unit_part(kX, kTheta) = 0.0;
    unit_part(kY, kTheta) = 0.0;
    EXPECT_EQ(unit_part, StateCovariance::Identity());
    // Across ±π the heading wraps.
    const LaserProcessModel turning(increment_from_motion(0.0, 0.2, 0.12), kPi - 0.1,
                                    LaserTuning{});
    EXPECT_NEAR(turning.predict_state(StateVector(0.0, 0.0, kPi - 0.1))(kTheta), -kPi + 0.1, 1e-12);
}

TEST(LaserProcessModel, ProcessNoiseIsEquation13) {
    // The paper's appendix: static 5e-4 each; dynamic 1e-3, 1e-3, 1.1e-3.
    const LaserTuning tuning;
    // d = 0.1 m, Δθ = −0.2 rad from θ = 2.0: φ = 1.9, Δx = 0.1·cos 1.9 = −0.0323290,
    // Δy = 0.1·sin 1.9 = 0.0946300.
    const LaserProcessModel model(increment_from_motion(0.1, -0.2, 0.12), 2.0, tuning);
    StateCovariance expected = StateCovariance::Zero();
    expected(kX, kX) = 0.0005 + 0.001 * 0.0323290;
    expected(kY, kY) = 0.0005 + 0.001 * 0.0946300;
    expected(kTheta, kTheta) = 0.0005 + 0.0011 * 0.2;
    EXPECT_LT(max_abs(model.noise_covariance() - expected), 1e-9);
    // Evaluated at the prior heading given, not at the state it is applied to.
    EXPECT_EQ(model.noise_covariance(), model.process_noise(2.0));
    EXPECT_NE(model.process_noise(2.0), model.process_noise(0.0));

    // Standing still (a missed frame): the static part alone.
    const LaserProcessModel still(OdometryIncrement{}, 1.0, tuning);
    EXPECT_EQ(still.noise_covariance(),
              StateCovariance(Eigen::Vector3d(0.0005, 0.0005, 0.0005).asDiagonal()));
    EXPECT_EQ(still.predict_state(StateVector(0.3, -0.2, 1.0)), StateVector(0.3, -0.2, 1.0));
}

TEST(LaserProcessModel, EkfPredictionIsEquation5) {
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    StateCovariance P0;
    P0 << 0.01, 0.002, 0.001,  //
        0.002, 0.02, -0.003,   //
        0.001, -0.003, 0.05;
    const StateVector x0(0.5, -0.5, -2.5);
    ASSERT_TRUE(ekf.reset(x0, P0));
    const LaserProcessModel model(increment_from_motion(0.03, 0.05, 0.12), x0(kTheta),
                                  LaserTuning{});
    ASSERT_EQ(ekf.predict(model), StepStatus::Applied);
    const double phi = -2.5 + 0.025;
    StateCovariance F = StateCovariance::Identity();
    F(kX, kTheta) = -0.03 * std::sin(phi);
    F(kY, kTheta) = 0.03 * std::cos(phi);
    StateCovariance Q = StateCovariance::Zero();
    Q(kX, kX) = 0.0005 + 0.001 * std::abs(0.03 * std::cos(phi));
    Q(kY, kY) = 0.0005 + 0.001 * std::abs(0.03 * std::sin(phi));
    Q(kTheta, kTheta) = 0.0005 + 0.0011 * 0.05;
    EXPECT_LT(max_abs(ekf.covariance() - (F * P0 * F.transpose() + Q)), 1e-15);
    EXPECT_NEAR(ekf.state()(kX), 0.5 + 0.03 * std::cos(phi), 1e-12);
}

TEST(LaserPoseMeasurement, EkfUpdateIsEquations15To18) {
    // K = P(P + R)⁻¹, X ← X + K·V, P ← (I − K)P, worked with an LU solve here.
    StateCovariance P;
    P << 0.02, 0.004, 0.001,  //
        0.004, 0.03, -0.002,  //
        0.001, -0.002, 0.04;
    const StateVector x(1.0, 1.0, kPi - 0.05);
    const StateVector r(0.008, 0.008, 0.01);
    const Pose2 observed{1.1, 0.95, -kPi + 0.05};  // 0.1 rad further, across ±π
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    ASSERT_TRUE(ekf.reset(x, P));
    const auto report = ekf.update(LaserPoseMeasurement(observed, r));
    ASSERT_EQ(report.status, StepStatus::Applied);

    const StateVector V(0.1, -0.05, 0.1);  // eq. 3, heading wrapped
    EXPECT_LT(max_abs(report.innovation - V), 1e-12);
    const StateCovariance R = r.asDiagonal();
    const StateCovariance K = (P + R).transpose().fullPivLu().solve(P.transpose()).transpose();
    const StateVector expected_x = x + K * V;
    EXPECT_NEAR(ekf.state()(kX), expected_x(kX), 1e-12);
    EXPECT_NEAR(ekf.state()(kY), expected_x(kY), 1e-12);
    EXPECT_NEAR(wrap_angle(ekf.state()(kTheta) - expected_x(kTheta)), 0.0, 1e-12);
    const StateCovariance expected_P = (StateCovariance::Identity() - K) * P;
    EXPECT_LT(max_abs(ekf.covariance() - expected_P), 1e-12);
    EXPECT_NEAR(report.nis, V.dot((P + R).fullPivLu().solve(V)), 1e-9);
}

TEST(LaserPoseMeasurement, UkfAgreesWithTheEkf) {
    // h(X) = X is linear: the unscented update equals the Kalman update (heading far from ±π
    // so no sigma point wraps).
    StateCovariance P;
    P << 0.02, 0.004, 0.001,  //
        0.004, 0.03, -0.002,  //
        0.001, -0.002, 0.04;
    const StateVector x(1.0, 1.0, 0.3);
    const LaserPoseMeasurement measurement({1.05, 0.9, 0.4}, StateVector(0.008, 0.008, 0.01));
    const std::unique_ptr<PoseEstimator> ekf = make_pose_estimator(FilterKind::Ekf);
    const std::unique_ptr<PoseEstimator> ukf = make_pose_estimator(FilterKind::Ukf);
    ASSERT_TRUE(ekf->reset(x, P));
    ASSERT_TRUE(ukf->reset(x, P));
    ASSERT_EQ(ekf->update(measurement).status, StepStatus::Applied);
    ASSERT_EQ(ukf->update(measurement).status, StepStatus::Applied);
    EXPECT_LT(max_abs(ekf->state() - ukf->state()), 1e-12);
    EXPECT_LT(max_abs(ekf->covariance() - ukf->covariance()), 1e-12);
}

}  // namespace
}  // namespace legofeup
