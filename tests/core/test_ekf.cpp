#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/wall_measurement.hpp"
#include "numeric_jacobian.hpp"

namespace legofeup {
namespace {

using Ekf = ExtendedKalmanFilter<PoseStateSpace>;
using testing::Uniform;

OdometryIncrement increment(double distance, double rotation) {
    return increment_from_motion(distance, rotation, 0.12);
}

double min_eigenvalue(const StateCovariance& P) {
    return Eigen::SelfAdjointEigenSolver<StateCovariance>(P).eigenvalues().minCoeff();
}

StateCovariance random_covariance(Uniform& uniform, double scale) {
    Eigen::Matrix3d A;
    for (int i = 0; i < 9; ++i) {
        A(i / 3, i % 3) = uniform(-1.0, 1.0);
    }
    return scale * (A * A.transpose() + 0.05 * Eigen::Matrix3d::Identity());
}

const WallMap& arena() {
    static const WallMap walls = standard_arena_walls(ArenaSpec{});
    return walls;
}

TEST(Ekf, OneWallUpdateMatchesAnIndependentCalculation) {
    // The robot believes it is 4 cm off the first side's line, a little turned; it reads the
    // wall_y− with d_s1 = 14 cm and d_s2 = 13.5 cm.
    const StateVector x0(-0.5, -1.03, 0.05);
    StateCovariance P0;
    P0 << 4e-4, 1e-5, 2e-5,  //
        1e-5, 9e-4, 3e-5,    //
        2e-5, 3e-5, 2e-3;
    const double ds1 = 0.14;
    const double ds2 = 0.135;
    const Eigen::Matrix2d R = Eigen::Vector2d(1e-4, 1e-4).asDiagonal();

    // Independent calculation, step by step (eq. 3–5, 15–21 with the corrections):
    const double L = 0.10;
    const double e = 0.06;
    const auto z_of = [&](const Eigen::Vector2d& r) {
        const double angle = std::atan((r(0) - r(1)) / L);
        const double d_w = 0.5 * (r(0) + r(1)) * std::cos(angle);
        return Eigen::Vector2d(-1.21 + d_w + e * std::cos(angle), angle);  // wall_y−, inside
    };
    const Eigen::Vector2d z = z_of(Eigen::Vector2d(ds1, ds2));
    const Eigen::Matrix2d Jr = testing::central_difference<2, 2>(z_of, Eigen::Vector2d(ds1, ds2));
    Eigen::Matrix<double, 2, 3> H;
    H << 0, 1, 0,  //
        0, 0, 1;
    const Eigen::Matrix2d S = H * P0 * H.transpose() + Jr * R * Jr.transpose();
    const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
    Eigen::Matrix2d S_inv;
    S_inv << S(1, 1), -S(0, 1), -S(1, 0), S(0, 0);
    S_inv /= det;
    const Eigen::Matrix<double, 3, 2> K = P0 * H.transpose() * S_inv;
    const Eigen::Vector2d nu = z - H * x0;
    const StateVector x_expected = x0 + K * nu;
    const StateCovariance P_expected = (StateCovariance::Identity() - K * H) * P0;

    Ekf ekf;
    ASSERT_TRUE(ekf.reset(x0, P0));
    const WallMeasurement m(arena().line(0), 1, observe_wall(ds1, ds2, IrMount{}), R);
    const auto report = ekf.update(m);
    ASSERT_EQ(report.status, StepStatus::Applied);
    EXPECT_LT((report.measurement - z).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((report.innovation - nu).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((report.innovation_covariance - S).cwiseAbs().maxCoeff(), 1e-10);
    EXPECT_LT((report.gain - K).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_NEAR(report.nis, nu.dot(S_inv * nu), 1e-6 * report.nis);
    EXPECT_LT((ekf.state() - x_expected).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((ekf.covariance() - P_expected).cwiseAbs().maxCoeff(), 1e-10);
    // The wall pulls y towards the reading: the belief moves, but less than all the way.
    EXPECT_GT(std::abs(ekf.state()(kY) - x0(kY)), 0.0);
    EXPECT_LT(std::abs(ekf.state()(kY) - z(0)), std::abs(x0(kY) - z(0)));
}

TEST(Ekf, CovarianceOnlyGrowsWithoutUpdates) {
    // Without measurements uncertainty can only grow. Not every variance grows (driving back
    // along a path undoes heading-induced drift, a shear of the ellipse), but
    //   P⁺ − ∇f_X·P·∇f_Xᵀ = ∇f_q·Q·∇f_qᵀ ⪰ 0  (the noise only adds),
    //   det P⁺ ≥ det P        (det ∇f_X = 1: the ellipsoid's volume never shrinks),
    //   P⁺_θθ = P_θθ + Q₂₂.
    Uniform uniform(41);
    Ekf ekf;
    ASSERT_TRUE(ekf.reset(StateVector(-1, -1, 0), StateVector(1e-4, 1e-4, 1e-3).asDiagonal()));
    const Eigen::Matrix2d Q = Eigen::Vector2d(1e-7, 1e-5).asDiagonal();
    for (int k = 0; k < 5000; ++k) {
        const StateCovariance before = ekf.covariance();
        const double theta = ekf.state()(kTheta);
        const double d = uniform(-0.01, 0.01);
        const double dtheta = uniform(-0.05, 0.05);
        ASSERT_EQ(ekf.predict(OdometryProcessModel(increment(d, dtheta), Q)), StepStatus::Applied);
        StateCovariance F = StateCovariance::Identity();  // written out again, eq. 13
        F(kX, kTheta) = -d * std::sin(theta + dtheta / 2.0);
        F(kY, kTheta) = d * std::cos(theta + dtheta / 2.0);
        const StateCovariance added = ekf.covariance() - F * before * F.transpose();
        EXPECT_GE(min_eigenvalue(added), -1e-15) << k;
        EXPECT_GT(ekf.covariance().determinant(), before.determinant()) << k;
        EXPECT_NEAR(ekf.covariance()(kTheta, kTheta), before(kTheta, kTheta) + Q(1, 1), 1e-15);
    }
}

TEST(Ekf, UpdateNeverIncreasesUncertainty) {
    Uniform uniform(42);
    for (int i = 0; i < 2000; ++i) {
        Ekf ekf;
        const StateVector x(uniform(-1.0, 0.0), uniform(-1.1, -0.9), uniform(-0.3, 0.3));
        const StateCovariance P = random_covariance(uniform, std::pow(10.0, uniform(-6, 0)));
        ASSERT_TRUE(ekf.reset(x, P));
        const Eigen::Matrix2d R =
            Eigen::Vector2d(std::pow(10.0, uniform(-8, -1)), std::pow(10.0, uniform(-8, -1)))
                .asDiagonal();
        const WallMeasurement m(arena().line(0), 1,
                                observe_wall(uniform(0.05, 0.3), uniform(0.05, 0.3), IrMount{}), R);
        const auto report = ekf.update(m);
        ASSERT_EQ(report.status, StepStatus::Applied);
        EXPECT_LE(ekf.covariance().trace(), P.trace() * (1.0 + 1e-12));
        EXPECT_GE(min_eigenvalue(P - ekf.covariance()), -1e-9 * P.norm());
    }
}

TEST(Ekf, ExtremeNoiseSettingsKeepCovarianceFiniteSymmetricAndPositive) {
    // 10⁵ random steps with Q and R drawn log-uniformly from 1e-12 … 1e6, as a student typing
    // absurd values would set them, and updates against random walls with random readings.
    //
    // Every step must be applied: the inputs are finite, Q and R positive definite, the prior
    // P positive definite (the base conditions it), so S = ∇h_X·P·∇h_Xᵀ + R_z is positive
    // definite, and there is no gate (a gate at probability p would reject ~(1 − p) of
    // consistent measurements, but these random readings are not consistent with anything).
    // So the number of rejections allowed is zero, not a fraction: a filter that silently
    // refused hard steps would otherwise pass by keeping its old, healthy P.
    Uniform uniform(43);
    Ekf ekf;
    ASSERT_TRUE(ekf.reset(StateVector(-1, -1, 0), StateVector(1e-4, 1e-4, 1e-3).asDiagonal()));
    const auto extreme = [&] { return std::pow(10.0, uniform(-12.0, 6.0)); };
    int updates = 0;
    for (int k = 0; k < 100000; ++k) {
        const Eigen::Matrix2d Q = Eigen::Vector2d(extreme(), extreme()).asDiagonal();
        const StepStatus predicted = ekf.predict(
            OdometryProcessModel(increment(uniform(-0.02, 0.02), uniform(-0.1, 0.1)), Q));
        ASSERT_EQ(predicted, StepStatus::Applied) << "step " << k << ": " << to_string(predicted);
        if (uniform(0.0, 1.0) < 0.3) {
            const Eigen::Matrix2d R = Eigen::Vector2d(extreme(), extreme()).asDiagonal();
            const int wall = static_cast<int>(uniform(0.0, 3.999));
            const WallMeasurement m(arena().line(wall), uniform(-1, 1) > 0 ? 1 : -1,
                                    observe_wall(uniform(0.04, 0.3), uniform(0.04, 0.3), IrMount{}),
                                    R);
            const StepStatus updated = ekf.update(m).status;
            ASSERT_EQ(updated, StepStatus::Applied) << "step " << k << ": " << to_string(updated);
            ++updates;
        }
        const StateCovariance& P = ekf.covariance();
        ASSERT_TRUE(P.allFinite()) << "step " << k;
        ASSERT_TRUE(ekf.state().allFinite()) << "step " << k;
        ASSERT_EQ(P, P.transpose()) << "step " << k;
        ASSERT_EQ(Eigen::LLT<StateCovariance>(P).info(), Eigen::Success) << "step " << k;
        ASSERT_GE(P.diagonal().minCoeff(), ekf.limits().min_variance) << "step " << k;
        ASSERT_LE(P.diagonal().maxCoeff(), ekf.limits().max_variance * (1 + 1e-12));
        ASSERT_GT(ekf.state()(kTheta), -kPi);
        ASSERT_LE(ekf.state()(kTheta), kPi);
    }
    // The run exercises the update: Binomial(10⁵, 0.3) updates, 30 000 ± 145.
    EXPECT_GT(updates, 29000);
}

TEST(Ekf, NonFiniteInputsLeaveTheBeliefUntouched) {
    Ekf ekf;
    const StateVector x(-0.5, -1.0, 0.1);
    const StateCovariance P = StateVector(1e-3, 1e-3, 1e-2).asDiagonal();
    ASSERT_TRUE(ekf.reset(x, P));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();

    EXPECT_EQ(ekf.predict(OdometryProcessModel(increment(nan, 0.0), Eigen::Matrix2d::Identity())),
              StepStatus::RejectedNonFinite);
    EXPECT_EQ(ekf.predict(OdometryProcessModel(increment(0.01, 0.0),
                                               Eigen::Vector2d(inf, 1.0).asDiagonal())),
              StepStatus::RejectedNonFinite);
    const Eigen::Matrix2d R = Eigen::Matrix2d::Identity() * 1e-4;
    const auto report =
        ekf.update(WallMeasurement(arena().line(0), 1, observe_wall(nan, 0.15, IrMount{}), R));
    EXPECT_EQ(report.status, StepStatus::RejectedNonFinite);
    EXPECT_EQ(ekf.state(), x);
    EXPECT_EQ(ekf.covariance(), P);
    EXPECT_FALSE(ekf.reset(StateVector(nan, 0, 0), P));
    EXPECT_EQ(ekf.state(), x);
}

// A measurement model whose noise covariance is chosen by the test, to exercise S checks.
struct ScalarHeadingMeasurement {
    static constexpr int kSize = 1;
    double z = 0.0;
    double noise = 1.0;
    Eigen::Matrix<double, 1, 1> measurement() const { return Eigen::Matrix<double, 1, 1>(z); }
    Eigen::Matrix<double, 1, 1> predict_measurement(const StateVector& x) const {
        return Eigen::Matrix<double, 1, 1>(x(kTheta));
    }
    Eigen::Matrix<double, 1, 3> jacobian(const StateVector&) const {
        return Eigen::Matrix<double, 1, 3>(0.0, 0.0, 1.0);
    }
    Eigen::Matrix<double, 1, 1> noise_covariance() const {
        return Eigen::Matrix<double, 1, 1>(noise);
    }
    Eigen::Matrix<double, 1, 1> residual(const Eigen::Matrix<double, 1, 1>& a,
                                         const Eigen::Matrix<double, 1, 1>& b) const {
        return Eigen::Matrix<double, 1, 1>(wrap_angle(a(0) - b(0)));
    }
};

TEST(Ekf, RejectsAnInnovationCovarianceThatIsNotPositiveDefinite) {
    Ekf ekf;
    const StateVector x(0, 0, 0.1);
    const StateCovariance P = StateCovariance::Identity() * 1e-2;
    ASSERT_TRUE(ekf.reset(x, P));
    const auto report = ekf.update(ScalarHeadingMeasurement{0.2, -1.0});  // S = 0.01 − 1 < 0
    EXPECT_EQ(report.status, StepStatus::RejectedSingular);
    EXPECT_EQ(ekf.state(), x);
}

TEST(Ekf, MahalanobisGateRejectsOutliersOnly) {
    Ekf ekf;
    const StateVector x(0, 0, 0.0);
    ASSERT_TRUE(ekf.reset(x, StateCovariance::Identity() * 1e-2));
    MahalanobisGate gate;
    gate.enabled = true;
    gate.threshold = chi_square_quantile(0.99, 1);  // 6.63
    // S = 0.01 + 0.01 = 0.02: ν = 0.5 gives NIS 12.5 > 6.63; ν = 0.2 gives 2.0.
    const auto outlier = ekf.update(ScalarHeadingMeasurement{0.5, 1e-2}, gate);
    EXPECT_EQ(outlier.status, StepStatus::RejectedByGate);
    EXPECT_NEAR(outlier.nis, 12.5, 1e-12);
    EXPECT_EQ(ekf.state(), x);
    const auto inlier = ekf.update(ScalarHeadingMeasurement{0.2, 1e-2}, gate);
    EXPECT_EQ(inlier.status, StepStatus::Applied);
    EXPECT_NEAR(inlier.nis, 2.0, 1e-12);
    EXPECT_NEAR(ekf.state()(kTheta), 0.1, 1e-12);  // halfway: equal prior and noise variance
}

TEST(Ekf, HeadingUpdateWrapsAcrossPlusMinusPi) {
    // Believed heading +179°, measured −179°: the innovation is +2°, not −358°, and the
    // estimate lands between them across the ±180° seam.
    Ekf ekf;
    ASSERT_TRUE(ekf.reset(StateVector(0, 0, degrees_to_radians(179.0)),
                          StateCovariance::Identity() * 1e-2));
    const auto report = ekf.update(ScalarHeadingMeasurement{degrees_to_radians(-179.0), 1e-2});
    ASSERT_EQ(report.status, StepStatus::Applied);
    EXPECT_NEAR(report.innovation(0), degrees_to_radians(2.0), 1e-12);
    EXPECT_NEAR(std::abs(ekf.state()(kTheta)), kPi, 1e-12);
    EXPECT_GT(ekf.state()(kTheta), -kPi);
    EXPECT_LE(ekf.state()(kTheta), kPi);

    // Prediction across the seam wraps too.
    ASSERT_TRUE(ekf.reset(StateVector(0, 0, degrees_to_radians(178.0)),
                          StateCovariance::Identity() * 1e-2));
    ekf.predict(OdometryProcessModel(increment(0.0, degrees_to_radians(4.0)),
                                     Eigen::Matrix2d::Identity() * 1e-6));
    EXPECT_NEAR(ekf.state()(kTheta), degrees_to_radians(-178.0), 1e-12);
}

TEST(Ekf, DirectModeSnapsObservedComponentsToTheMeasurement) {
    // "Direct" localisation (experiment b): R ≈ 0 makes the update trust the walls fully.
    Ekf ekf;
    ASSERT_TRUE(
        ekf.reset(StateVector(-0.5, -1.05, 0.1), StateVector(1e-3, 1e-3, 1e-2).asDiagonal()));
    const WallMeasurement m(arena().line(0), 1, observe_wall(0.15, 0.15, IrMount{}),
                            Eigen::Matrix2d::Identity() * 1e-12);
    ASSERT_EQ(ekf.update(m).status, StepStatus::Applied);
    EXPECT_NEAR(ekf.state()(kY), m.measurement()(0), 1e-7);
    EXPECT_NEAR(ekf.state()(kTheta), m.measurement()(1), 1e-7);
    EXPECT_LT(ekf.covariance()(kY, kY), 1e-9);
    EXPECT_GT(ekf.covariance()(kX, kX), 1e-4);  // x is not observed by a y wall
}

TEST(Ekf, CovarianceGuardRepairsWhatItIsGiven) {
    CovarianceLimits limits;
    StateCovariance P;
    P << 1.0, 2.0, 0.0,  // indefinite: eigenvalues 3 and −1
        2.0, 1.0, 0.0,   //
        0.0, 0.0, 1e20;  // above the ceiling
    const auto repairs = condition_covariance<3>(P, limits);
    EXPECT_TRUE(repairs & kRepairCeiling);
    EXPECT_TRUE(repairs & kRepairProjection);
    EXPECT_EQ(Eigen::LLT<StateCovariance>(P).info(), Eigen::Success);
    EXPECT_LE(P(2, 2), limits.max_variance * (1 + 1e-12));
    EXPECT_EQ(P, P.transpose());

    StateCovariance tiny = StateVector(1e-20, 1.0, 1.0).asDiagonal();
    EXPECT_EQ(condition_covariance<3>(tiny, limits), kRepairFloor);
    EXPECT_EQ(tiny(0, 0), limits.min_variance);
}

TEST(Ekf, ANearlySingularCovarianceIsRepairedIntoOneEveryCholeskyAccepts) {
    // Found by the extreme-noise run built with clang: the exact LDLᵀ test passed this P
    // on a pivot of rounding size, Eigen's LLT failed it, and its smallest eigenvalue is
    // -2.2e-11 (ε·λ_max). Conditioning must leave no such matrix behind.
    StateCovariance found;
    found << 14709.972810254923, -11073.181142172351, 37701.381770159831,  //
        -11073.181142172351, 8478.3213956235977, -28866.540482133867,      //
        37701.381770159831, -28866.540482133867, 98283.271006546231;
    const CovarianceLimits limits;
    StateCovariance repaired = found;
    EXPECT_TRUE(condition_covariance<3>(repaired, limits) & kRepairProjection);
    EXPECT_EQ(Eigen::LLT<StateCovariance>(repaired).info(), Eigen::Success);
    EXPECT_LT((repaired - found).norm(), 1e-6 * found.norm());  // a repair, not a new matrix

    // Random rotations of eigenvalues (λ_max, λ_mid, λ_min) with λ_min/λ_max from -1e-10 to
    // 1e-10, around the edge of what doubles resolve: every result is accepted by Eigen's
    // LLT and has a smallest eigenvalue, computed independently, above zero.
    Uniform uniform(45);
    for (int i = 0; i < 20000; ++i) {
        const Eigen::Quaterniond rotation =
            Eigen::Quaterniond(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1))
                .normalized();
        const double largest = std::pow(10.0, uniform(-6.0, 6.0));
        const StateVector eigenvalues(largest, largest * uniform(1e-6, 1.0),
                                      largest * uniform(-1e-10, 1e-10));
        const Eigen::Matrix3d V = rotation.toRotationMatrix();
        StateCovariance P = V * eigenvalues.asDiagonal() * V.transpose();
        P = (0.5 * (P + P.transpose())).eval();
        const StateCovariance before = P;
        condition_covariance<3>(P, limits);
        ASSERT_EQ(Eigen::LLT<StateCovariance>(P).info(), Eigen::Success) << before;
        ASSERT_GT(Eigen::SelfAdjointEigenSolver<StateCovariance>(P).eigenvalues().minCoeff(), 0.0)
            << before;
        ASSERT_EQ(P, P.transpose());
    }
}

TEST(Ekf, PositiveDefiniteCheckAgreesWithEigensCholesky) {
    Uniform uniform(44);
    int definite = 0;
    for (int i = 0; i < 20000; ++i) {
        StateCovariance P;
        for (int r = 0; r < 3; ++r) {
            for (int c = r; c < 3; ++c) {
                P(r, c) = P(c, r) = uniform(-1.0, 1.0) + (r == c ? uniform(0.0, 2.0) : 0.0);
            }
        }
        const bool expected = Eigen::LLT<StateCovariance>(P).info() == Eigen::Success;
        EXPECT_EQ(is_positive_definite<3>(P), expected) << P;
        definite += expected ? 1 : 0;
    }
    EXPECT_GT(definite, 2000);  // both outcomes well represented
    EXPECT_LT(definite, 18000);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(is_positive_definite<3>(StateVector(1.0, nan, 1.0).asDiagonal().toDenseMatrix()));
}

}  // namespace
}  // namespace legofeup
