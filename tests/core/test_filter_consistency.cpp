#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <array>
#include <random>

#include "kinematic_world.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/consistency.hpp"
#include "legofeup/core/extended_kalman_filter.hpp"
#include "legofeup/core/odometry_process_model.hpp"
#include "legofeup/core/pose_state_space.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup {
namespace {

// Monte-Carlo check of the whole EKF (Jacobians, noise mapping, gain, Joseph update): when
// the truth really evolves with the noise the filter assumes, the run-averaged NEES and NIS
// must lie inside their χ² bounds (Bar-Shalom, Li & Kirubarajan §5.4). A wrong Jacobian or a
// mis-mapped R shows up as a NEES far outside the bounds.
//
// The scenario keeps the EKF in its linear regime (IR noise σ = 1 mm, headings within a few
// degrees). With noisier sensors the inverse observation z₁ = (d̄ + e)·cos(ObsAng) is biased
// by E[cos(α + n)] = cos α·e^{−σ²/2} and the NEES rises a few percent above 3: the EKF's
// known linearisation inconsistency, not an error in the algebra.
TEST(EkfConsistency, AveragedNeesAndNisStayInsideChiSquareBounds) {
    constexpr int kRuns = 400;
    constexpr int kSteps = 240;
    constexpr int kUpdateEvery = 4;
    const std::array<int, 4> checkpoints{20, 60, 120, 239};

    const std::vector<Wall> walls{{"long wall", {-5.0, -1.21}, {5.0, -1.21}}};
    const WallLine line = make_wall_line(walls.front());
    const Eigen::Matrix2d Q = Eigen::Vector2d(1e-7, 1e-5).asDiagonal();  // per step
    const Eigen::Matrix2d R = Eigen::Vector2d(1e-6, 1e-6).asDiagonal();  // σ = 1 mm
    const StateVector x0(-1.0, -1.0, 0.0);
    const StateCovariance P0 = StateVector(1e-4, 1e-4, 1e-3).asDiagonal();
    const StateCovariance L0 = P0.llt().matrixL();

    std::array<double, kSteps> nees_sum{};
    double nis_sum = 0.0;
    int nis_count = 0;
    for (int run = 0; run < kRuns; ++run) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(1000 + run));
        std::normal_distribution<double> unit(0.0, 1.0);
        StateVector truth = x0 + L0 * StateVector(unit(rng), unit(rng), unit(rng));
        ExtendedKalmanFilter<PoseStateSpace> ekf;
        ASSERT_TRUE(ekf.reset(x0, P0));
        for (int k = 0; k < kSteps; ++k) {
            const OdometryProcessModel model(
                increment_from_motion(0.005, 0.002 * std::sin(0.05 * k), 0.12), Q);
            const Eigen::Vector2d q(std::sqrt(Q(0, 0)) * unit(rng), std::sqrt(Q(1, 1)) * unit(rng));
            truth = model.propagate(truth, q);  // the truth moves with the assumed noise
            ASSERT_EQ(ekf.predict(model), StepStatus::Applied);
            if (k % kUpdateEvery == kUpdateEvery - 1) {
                const auto ds = testing::true_ir_distances(to_pose(truth), walls);
                const double ds1 = ds[0] + std::sqrt(R(0, 0)) * unit(rng);
                const double ds2 = ds[1] + std::sqrt(R(1, 1)) * unit(rng);
                const auto report =
                    ekf.update(WallMeasurement(line, 1, observe_wall(ds1, ds2, IrMount{}), R));
                ASSERT_EQ(report.status, StepStatus::Applied);
                nis_sum += report.nis;
                ++nis_count;
            }
            nees_sum[static_cast<std::size_t>(k)] +=
                normalized_estimation_error(truth, ekf.state(), ekf.covariance());
        }
    }
    // 99 % two-sided bounds for the average of kRuns χ²(3) values at each checkpoint.
    const ChiSquareInterval nees_bounds = average_chi_square_interval(3, kRuns, 0.99);
    for (int k : checkpoints) {
        const double average = nees_sum[static_cast<std::size_t>(k)] / kRuns;
        EXPECT_TRUE(nees_bounds.contains(average))
            << "step " << k << ": mean NEES " << average << " outside [" << nees_bounds.lower
            << ", " << nees_bounds.upper << "]";
    }
    // NIS averaged over all updates of all runs (updates are independent in a consistent
    // filter: the innovation sequence is white).
    const ChiSquareInterval nis_bounds = average_chi_square_interval(2, nis_count, 0.99);
    const double nis_average = nis_sum / nis_count;
    EXPECT_TRUE(nis_bounds.contains(nis_average))
        << "mean NIS " << nis_average << " outside [" << nis_bounds.lower << ", "
        << nis_bounds.upper << "]";
}

TEST(EkfConsistency, NeesOfAKnownErrorIsItsMahalanobisLength) {
    // x̃ = (0.1, 0, 0) with σ_x = 0.1 ⇒ ε = 1; heading errors are wrapped first.
    const StateCovariance P = StateVector(0.01, 0.04, 0.25).asDiagonal();
    EXPECT_NEAR(normalized_estimation_error(StateVector(0.1, 0, 0), StateVector::Zero(), P), 1.0,
                1e-12);
    const StateVector truth(0, 0, degrees_to_radians(179.0));
    const StateVector estimate(0, 0, degrees_to_radians(-179.0));
    const double wrapped = degrees_to_radians(-2.0);
    EXPECT_NEAR(normalized_estimation_error(truth, estimate, P), wrapped * wrapped / 0.25, 1e-12);
    EXPECT_TRUE(std::isnan(normalized_estimation_error(truth, estimate, StateCovariance::Zero())));
}

}  // namespace
}  // namespace legofeup
