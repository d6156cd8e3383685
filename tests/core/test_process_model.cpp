#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

using testing::Uniform;

OdometryIncrement increment(double distance, double rotation) {
    return increment_from_motion(distance, rotation, 0.12);
}

TEST(OdometryProcessModel, StateJacobianMatchesCentralDifferences) {
    Uniform uniform(31);
    for (int i = 0; i < 2000; ++i) {
        const OdometryProcessModel model(increment(uniform(-0.05, 0.05), uniform(-0.3, 0.3)),
                                         Eigen::Matrix2d::Identity());
        const StateVector x(uniform(-3, 3), uniform(-3, 3), uniform(-kPi, kPi));
        const auto f = [&](const StateVector& s) { return model.predict_state(s); };
        const auto numeric = testing::central_difference<3, 3>(f, x, 1e-6, 0b100);
        EXPECT_LT((numeric - model.state_jacobian(x)).cwiseAbs().maxCoeff(), 1e-8)
            << "x = " << x.transpose();
    }
}

/// True if a and b hold the same doubles bit for bit (−0 and +0 differ, NaN equals itself).
template <class A, class B>
bool same_bits(const A& a, const B& b) {
    for (Eigen::Index i = 0; i < a.size(); ++i) {
        if (std::bit_cast<std::uint64_t>(a.data()[i])
            != std::bit_cast<std::uint64_t>(b.data()[i])) {
            return false;
        }
    }
    return true;
}

// The EKF predicts through linearise (one cos φ, one sin φ): it must give exactly the
// bits of the three separate hooks, signed zeros included (propagate's d + 0 makes −0 +0).
TEST(OdometryProcessModel, LineariseIsTheThreeHooksBitForBit) {
    Uniform uniform(37);
    const Eigen::Matrix2d Q = Eigen::Vector2d(1e-6, 1e-5).asDiagonal();
    std::vector<std::pair<StateVector, OdometryIncrement>> cases;
    for (int trial = 0; trial < 200; ++trial) {
        cases.emplace_back(StateVector(uniform(-1.0, 1.0), uniform(-1.0, 1.0), uniform(-4.0, 4.0)),
                           increment(uniform(-0.02, 0.02), uniform(-0.3, 0.3)));
    }
    OdometryIncrement negative_zeros;
    negative_zeros.distance = -0.0;
    negative_zeros.rotation = -0.0;
    for (const double theta : {0.0, -0.0, kPi, -kPi}) {
        cases.emplace_back(StateVector(-0.0, -0.0, theta), negative_zeros);
        cases.emplace_back(StateVector(0.0, -0.0, theta), OdometryIncrement{});
    }
    for (const auto& [x, u] : cases) {
        const OdometryProcessModel model(u, Q);
        const OdometryProcessModel::Linearisation linearised = model.linearise(x);
        EXPECT_TRUE(same_bits(linearised.state, model.predict_state(x))) << x.transpose();
        EXPECT_TRUE(same_bits(linearised.state_jacobian, model.state_jacobian(x))) << x.transpose();
        EXPECT_TRUE(same_bits(linearised.noise_jacobian, model.noise_jacobian(x))) << x.transpose();
    }
}

TEST(OdometryProcessModel, NoiseJacobianMatchesCentralDifferences) {
    Uniform uniform(32);
    for (int i = 0; i < 2000; ++i) {
        const OdometryProcessModel model(increment(uniform(-0.05, 0.05), uniform(-0.3, 0.3)),
                                         Eigen::Matrix2d::Identity());
        const StateVector x(uniform(-3, 3), uniform(-3, 3), uniform(-kPi, kPi));
        const auto f = [&](const Eigen::Vector2d& q) { return model.propagate(x, q); };
        const auto numeric =
            testing::central_difference<3, 2>(f, Eigen::Vector2d::Zero().eval(), 1e-6, 0b100);
        EXPECT_LT((numeric - model.noise_jacobian(x)).cwiseAbs().maxCoeff(), 1e-8);
    }
}

TEST(OdometryProcessModel, PredictsTheCentredDifferenceStep) {
    const OdometryProcessModel model(increment(0.1, 0.2), Eigen::Matrix2d::Zero());
    const StateVector next = model.predict_state(StateVector(1.0, 2.0, 0.5));
    EXPECT_NEAR(next(kX), 1.0 + 0.1 * std::cos(0.6), 1e-15);
    EXPECT_NEAR(next(kY), 2.0 + 0.1 * std::sin(0.6), 1e-15);
    EXPECT_NEAR(next(kTheta), 0.7, 1e-15);
}

TEST(OdometryProcessModel, CovariancePropagationHandWorked) {
    // From a perfectly known pose heading +x, one straight step d with Q = diag(q1, q2):
    // ∇f_q = [1 0; 0 d/2; 0 1] ⇒ P = [q1 0 0; 0 d²q2/4 d·q2/2; 0 d·q2/2 q2].
    const double d = 0.04;
    const double q1 = 1e-6;
    const double q2 = 1e-4;
    ExtendedKalmanFilter<PoseStateSpace> ekf;
    CovarianceLimits no_floor;
    no_floor.min_variance = 1e-30;
    ekf.set_limits(no_floor);
    ASSERT_TRUE(ekf.reset(StateVector(0.0, 0.0, 0.0), StateCovariance::Zero()));
    const Eigen::Matrix2d Q = Eigen::Vector2d(q1, q2).asDiagonal();
    ASSERT_EQ(ekf.predict(OdometryProcessModel(increment(d, 0.0), Q)), StepStatus::Applied);
    StateCovariance expected;
    expected << q1, 0, 0,               //
        0, d * d * q2 / 4, d * q2 / 2,  //
        0, d * q2 / 2, q2;
    // This P is singular (y and θ come from the same ε_Δθ); the guard keeps P positive
    // definite by lifting eigenvalues below 1e-12·λ_max, i.e. by ~1e-16 here.
    EXPECT_LT((ekf.covariance() - expected).cwiseAbs().maxCoeff(), 2e-16);
    EXPECT_NEAR(ekf.state()(kX), d, 1e-15);

    // A second step carries the heading uncertainty into y: P_yy grows by the lever arm.
    ASSERT_EQ(ekf.predict(OdometryProcessModel(increment(d, 0.0), Q)), StepStatus::Applied);
    // F = [1 0 0; 0 1 d; 0 0 1]; P₂ = F P₁ Fᵀ + G Q Gᵀ ⇒ P_yy = d²q2/4 + 2d·(d q2/2) + d² q2
    // + d²q2/4 = 2.5 d² q2.
    EXPECT_NEAR(ekf.covariance()(kY, kY), 2.5 * d * d * q2, 3e-16);
    EXPECT_NEAR(ekf.covariance()(kTheta, kTheta), 2.0 * q2, 3e-16);
}

}  // namespace
}  // namespace legofeup
