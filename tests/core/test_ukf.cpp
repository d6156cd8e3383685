#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "legofeup/core/beacon_bearing.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/unscented_kalman_filter.hpp"

namespace legofeup {
namespace {

using Ekf = ExtendedKalmanFilter<PoseStateSpace>;
using Ukf = UnscentedKalmanFilter<PoseStateSpace>;

/// A linear process model on the pose with a 2-dimensional noise: X ← F·X + B + G·q.
struct LinearProcess {
    static constexpr int kNoiseSize = 2;
    using NoiseVector = Eigen::Vector2d;
    StateCovariance F;
    StateVector offset;
    Eigen::Matrix<double, 3, 2> G;
    Eigen::Matrix2d Q;

    StateVector propagate(const StateVector& x, const NoiseVector& q) const {
        return F * x + offset + G * q;
    }
    StateVector predict_state(const StateVector& x) const {
        return propagate(x, NoiseVector::Zero());
    }
    StateCovariance state_jacobian(const StateVector& /*x*/) const { return F; }
    Eigen::Matrix<double, 3, 2> noise_jacobian(const StateVector& /*x*/) const { return G; }
    const Eigen::Matrix2d& noise_covariance() const { return Q; }
};

/// A linear measurement z = H·X with the second component an angle (wrapped residual).
struct LinearMeasurement {
    static constexpr int kSize = 2;
    using Vector = Eigen::Vector2d;
    Eigen::Matrix<double, 2, 3> H;
    Vector z;
    Eigen::Matrix2d R;

    const Vector& measurement() const { return z; }
    Vector predict_measurement(const StateVector& x) const { return H * x; }
    Eigen::Matrix<double, 2, 3> jacobian(const StateVector& /*x*/) const { return H; }
    const Eigen::Matrix2d& noise_covariance() const { return R; }
    Vector residual(const Vector& a, const Vector& b) const {
        return {a(0) - b(0), wrap_angle(a(1) - b(1))};
    }
};

StateCovariance test_covariance() {
    StateCovariance P;
    P << 4e-2, 1e-2, 2e-3,  //
        1e-2, 9e-2, -3e-3,  //
        2e-3, -3e-3, 2e-2;
    return P;
}

LinearProcess linear_process() {
    LinearProcess model;
    model.F << 1.0, 0.1, 0.2,  //
        -0.05, 1.0, 0.3,       //
        0.0, 0.02, 1.0;
    model.offset = StateVector(0.1, -0.05, 0.03);
    model.G << 1.0, 0.2,  //
        0.5, 0.1,         //
        0.0, 1.0;
    model.Q << 3e-3, 1e-4,  //
        1e-4, 2e-3;
    return model;
}

double min_eigenvalue(const StateCovariance& P) {
    return Eigen::SelfAdjointEigenSolver<StateCovariance>(P).eigenvalues().minCoeff();
}

// (a) On a linear model the unscented transform is exact, so the UKF equals the EKF.
TEST(Ukf, EqualsTheEkfOnALinearProcessModel) {
    for (const double kappa : {0.0, 1.0, -2.0, 3.0}) {
        const StateVector x0(0.3, -0.2, 0.4);
        Ekf ekf;
        Ukf ukf(UkfParams{kappa});
        ASSERT_TRUE(ekf.reset(x0, test_covariance()));
        ASSERT_TRUE(ukf.reset(x0, test_covariance()));
        const LinearProcess model = linear_process();
        ASSERT_EQ(ekf.predict(model), StepStatus::Applied);
        ASSERT_EQ(ukf.predict(model), StepStatus::Applied) << "kappa " << kappa;
        EXPECT_LT((ukf.state() - ekf.state()).cwiseAbs().maxCoeff(), 1e-9) << "kappa " << kappa;
        EXPECT_LT((ukf.covariance() - ekf.covariance()).cwiseAbs().maxCoeff(), 1e-9)
            << "kappa " << kappa;
    }
}

TEST(Ukf, EqualsTheEkfOnALinearMeasurement) {
    for (const double kappa : {0.0, 1.0, -1.0}) {
        const StateVector x0(0.3, -0.2, 0.4);
        LinearMeasurement m;
        m.H << 1.0, 0.2, 0.0,  //
            0.0, 0.0, 1.0;
        m.z = Eigen::Vector2d(0.45, 0.3);
        m.R << 1e-2, 2e-3,  //
            2e-3, 5e-3;
        Ekf ekf;
        Ukf ukf(UkfParams{kappa});
        ASSERT_TRUE(ekf.reset(x0, test_covariance()));
        ASSERT_TRUE(ukf.reset(x0, test_covariance()));
        const auto e = ekf.update(m);
        const auto u = ukf.update(m);
        ASSERT_EQ(e.status, StepStatus::Applied);
        ASSERT_EQ(u.status, StepStatus::Applied) << "kappa " << kappa;
        EXPECT_LT((u.predicted - e.predicted).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((u.innovation_covariance - e.innovation_covariance).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT((u.gain - e.gain).cwiseAbs().maxCoeff(), 1e-9);
        EXPECT_NEAR(u.nis, e.nis, 1e-9);
        EXPECT_LT((ukf.state() - ekf.state()).cwiseAbs().maxCoeff(), 1e-9) << "kappa " << kappa;
        EXPECT_LT((ukf.covariance() - ekf.covariance()).cwiseAbs().maxCoeff(), 1e-9)
            << "kappa " << kappa;
    }
}

/// Polar → Cartesian, reading the pose's x as a range ρ and θ as a direction:
/// h(X) = [ρ·cos θ, ρ·sin θ] (the classic unscented-transform example).
struct PolarToCartesian {
    static constexpr int kSize = 2;
    using Vector = Eigen::Vector2d;
    Vector z = Vector::Zero();
    Eigen::Matrix2d R = 1e-10 * Eigen::Matrix2d::Identity();  // negligible: S ≈ P_zz

    const Vector& measurement() const { return z; }
    Vector predict_measurement(const StateVector& x) const {
        return {x(kX) * std::cos(x(kTheta)), x(kX) * std::sin(x(kTheta))};
    }
    Eigen::Matrix<double, 2, 3> jacobian(const StateVector& x) const {
        Eigen::Matrix<double, 2, 3> H = Eigen::Matrix<double, 2, 3>::Zero();
        H(0, kX) = std::cos(x(kTheta));
        H(1, kX) = std::sin(x(kTheta));
        H(0, kTheta) = -x(kX) * std::sin(x(kTheta));
        H(1, kTheta) = x(kX) * std::cos(x(kTheta));
        return H;
    }
    const Eigen::Matrix2d& noise_covariance() const { return R; }
    Vector residual(const Vector& a, const Vector& b) const { return a - b; }
};

// (b) ρ = 1 ± 0.02, θ = 0 ± 0.5 rad through polar → Cartesian: the true mean is
// (e^{−σ²/2}, 0) ≈ (0.8825, 0), the EKF says (1, 0). The UKF's mean and covariance
// must be closer to a 200 000-sample Monte Carlo than the EKF's: mean within 0.005
// (Monte Carlo standard error ≈ 0.3/√N ≈ 7e-4), the largest covariance error below half the
// EKF's (which exceeds 0.05), for κ = 0 and 1.
TEST(Ukf, UnscentedTransformBeatsLinearisationAgainstMonteCarlo) {
    const StateVector mean(1.0, 0.0, 0.0);
    const StateCovariance P = Eigen::Vector3d(4e-4, 1e-2, 0.25).asDiagonal();
    const PolarToCartesian m;

    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    const StateVector sigma = P.diagonal().cwiseSqrt();
    constexpr int kSamples = 200000;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d sum_squares = Eigen::Matrix2d::Zero();
    for (int i = 0; i < kSamples; ++i) {
        const StateVector sample =
            mean + sigma.cwiseProduct(StateVector(normal(rng), normal(rng), normal(rng)));
        const Eigen::Vector2d z = m.predict_measurement(sample);
        sum += z;
        sum_squares += z * z.transpose();
    }
    const Eigen::Vector2d mc_mean = sum / kSamples;
    const Eigen::Matrix2d mc_covariance =
        sum_squares / kSamples - mc_mean * mc_mean.transpose() + m.R;
    EXPECT_NEAR(mc_mean(0), std::exp(-0.125), 0.003);  // the analytic mean, a sanity check

    for (const double kappa : {0.0, 1.0}) {
        Ekf ekf;
        Ukf ukf(UkfParams{kappa});
        ASSERT_TRUE(ekf.reset(mean, P));
        ASSERT_TRUE(ukf.reset(mean, P));
        const auto e = ekf.update(m);
        const auto u = ukf.update(m);
        EXPECT_GT((e.predicted - mc_mean).norm(), 0.1);
        EXPECT_LT((u.predicted - mc_mean).norm(), 0.005) << "kappa " << kappa;
        const double ekf_error = (e.innovation_covariance - mc_covariance).cwiseAbs().maxCoeff();
        EXPECT_GT(ekf_error, 0.05);
        EXPECT_LT((u.innovation_covariance - mc_covariance).cwiseAbs().maxCoeff(), 0.5 * ekf_error)
            << "kappa " << kappa << "\n"
            << u.innovation_covariance << "\n"
            << mc_covariance;
    }
}

// (c) Headings straddling ±π average to ≈π; an arithmetic mean would give 0.
TEST(Ukf, WeightedMeanOfHeadingsAcrossPiIsPi) {
    const std::array<StateVector, 3> points{StateVector(1.0, 2.0, kPi - 0.1),
                                            StateVector(1.2, 2.0, -kPi + 0.1),
                                            StateVector(0.8, 2.0, kPi - 0.3)};
    const std::array<double, 3> weights{0.0, 0.5, 0.5};
    const StateVector mean = PoseStateSpace::weighted_mean(points, weights);
    EXPECT_NEAR(mean(kX), 1.0, 1e-12);
    EXPECT_NEAR(mean(kY), 2.0, 1e-12);
    EXPECT_NEAR(std::abs(mean(kTheta)), kPi - 0.1, 1e-12);  // (π + 0.1 + π − 0.3)/2 = π − 0.1
    EXPECT_GT(mean(kTheta), 0.0);

    // A negative central weight (κ < 0) keeps the symmetric mean at the centre.
    const std::array<StateVector, 3> symmetric{StateVector(0, 0, kPi - 0.05),
                                               StateVector(0, 0, wrap_angle(kPi + 0.25)),
                                               StateVector(0, 0, kPi - 0.35)};
    const std::array<double, 3> negative_center{-1.0, 1.0, 1.0};
    EXPECT_NEAR(PoseStateSpace::weighted_mean(symmetric, negative_center)(kTheta), kPi - 0.05,
                1e-12);
}

TEST(Ukf, PredictWithTheHeadingNearPiMatchesTheEkf) {
    const StateVector x0(0.5, 0.5, kPi - 0.01);
    const StateCovariance P = Eigen::Vector3d(1e-4, 1e-4, 0.04).asDiagonal();  // σ_θ = 0.2
    const OdometryProcessModel model(increment_from_motion(0.01, 0.002, 0.12),
                                     Eigen::Vector2d(1e-6, 1e-6).asDiagonal());
    Ekf ekf;
    Ukf ukf;
    ASSERT_TRUE(ekf.reset(x0, P));
    ASSERT_TRUE(ukf.reset(x0, P));
    ASSERT_EQ(ekf.predict(model), StepStatus::Applied);
    ASSERT_EQ(ukf.predict(model), StepStatus::Applied);
    EXPECT_LT(std::abs(wrap_angle(ukf.state()(kTheta) - ekf.state()(kTheta))), 1e-3);
    EXPECT_NEAR(ukf.covariance()(kTheta, kTheta), ekf.covariance()(kTheta, kTheta),
                0.01 * ekf.covariance()(kTheta, kTheta));
}

// (d) Rejections leave x and P unchanged.
TEST(Ukf, RejectsNonPositiveSpreadLeavingTheEstimate) {
    const StateVector x0(0.3, -0.2, 0.4);
    const BeaconBearingMeasurement m(Vector2(1.0, 1.0), 0.3, 1e-2);
    const LinearProcess process = linear_process();  // n = 3 + 2 = 5
    Ukf ukf(UkfParams{-3.0});                        // update: n + κ = 0
    ASSERT_TRUE(ukf.reset(x0, test_covariance()));
    EXPECT_EQ(ukf.update(m).status, StepStatus::RejectedSingular);
    EXPECT_EQ(ukf.state(), x0);
    EXPECT_EQ(ukf.covariance(), test_covariance());
    ukf.set_params(UkfParams{-5.0});  // predict: n + κ = 0
    EXPECT_EQ(ukf.predict(process), StepStatus::RejectedSingular);
    EXPECT_EQ(ukf.state(), x0);
    EXPECT_EQ(ukf.covariance(), test_covariance());
    ukf.set_params(UkfParams{-4.5});  // predict: n + κ = 0.5 > 0 is fine
    EXPECT_EQ(ukf.predict(process), StepStatus::Applied);
    EXPECT_EQ(ukf.params().kappa, -4.5);
}

TEST(Ukf, RejectsNonFiniteInputs) {
    const StateVector x0(0.3, -0.2, 0.4);
    Ukf ukf;
    ASSERT_TRUE(ukf.reset(x0, test_covariance()));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(ukf.update(BeaconBearingMeasurement(Vector2(1.0, 1.0), nan, 1e-2)).status,
              StepStatus::RejectedNonFinite);
    EXPECT_EQ(ukf.update(BeaconBearingMeasurement(Vector2(1.0, 1.0), 0.2, nan)).status,
              StepStatus::RejectedNonFinite);
    LinearProcess process = linear_process();
    process.Q(0, 0) = nan;
    EXPECT_EQ(ukf.predict(process), StepStatus::RejectedNonFinite);
    process = linear_process();
    process.offset(kX) = std::numeric_limits<double>::infinity();
    EXPECT_EQ(ukf.predict(process), StepStatus::RejectedNonFinite);
    EXPECT_EQ(ukf.state(), x0);
    EXPECT_EQ(ukf.covariance(), test_covariance());
}

TEST(Ukf, SemiDefiniteProcessNoiseIsAccepted) {
    Ukf ukf;
    ASSERT_TRUE(ukf.reset(StateVector(0, 0, 0), test_covariance()));
    const OdometryProcessModel model(increment_from_motion(0.01, 0.0, 0.12),
                                     Eigen::Vector2d(0.0, 1e-4).asDiagonal());  // ε_d ≡ 0
    EXPECT_EQ(ukf.predict(model), StepStatus::Applied);
}

TEST(Ukf, AbsurdNoiseKeepsTheCovarianceFiniteAndPositiveDefinite) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> exponent(-12.0, 9.0);
    const std::array<Vector2, 2> beacons{Vector2(1.5, 1.5), Vector2(-1.5, 0.5)};
    for (const double kappa : {0.0, 1.0, -1.0}) {
        Ukf ukf(UkfParams{kappa});
        ASSERT_TRUE(ukf.reset(StateVector(0.1, 0.2, 3.0), test_covariance()));
        for (int step = 0; step < 60; ++step) {
            const double q = std::pow(10.0, exponent(rng));
            const double r = std::pow(10.0, exponent(rng));
            const OdometryProcessModel model(increment_from_motion(0.01, 0.05, 0.12),
                                             Eigen::Vector2d(q, q).asDiagonal());
            ukf.predict(model);
            for (const Vector2& beacon : beacons) {
                ukf.update(BeaconBearingMeasurement(beacon, 0.7, r));
            }
            ASSERT_TRUE(ukf.state().allFinite());
            ASSERT_TRUE(ukf.covariance().allFinite());
            ASSERT_GT(min_eigenvalue(ukf.covariance()), 0.0)
                << "kappa " << kappa << " step " << step;
        }
    }
}

}  // namespace
}  // namespace legofeup
