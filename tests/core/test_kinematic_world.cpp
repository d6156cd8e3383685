// The kinematic test robot's slip (support/kinematic_world.hpp): the encoders count what the
// wheels rolled, the pose follows what the tyres covered, so slip is odometry error, and
// without slip dead reckoning from the encoders is the truth up to the encoders' whole counts.

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <cstdint>

#include "kinematic_world.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/odometry.hpp"

namespace legofeup {
namespace {

using testing::KinematicRobot;
using testing::KinematicRobotParams;

constexpr double kKinematicPeriod = 0.05;  // s
constexpr double kSpeed = 0.1;             // m/s on both wheels
constexpr int kSteps = 400;                // 2 m straight ahead
constexpr double kRolledPerStep = kSpeed * kKinematicPeriod;
constexpr double kDistance = kSteps * kRolledPerStep;

/// Dead reckoning from a robot's encoder counts through the core's odometry (eq. 7–9), as the
/// loop does with the wall updates off.
class DeadReckoning {
  public:
    DeadReckoning(const KinematicRobot& robot, const KinematicRobotParams& params)
        : pose_(robot.pose()), counts_(robot.encoder_counts()) {
        params_.codo_right =
            nominal_counts_per_metre(params.right_wheel_diameter, params.counts_per_turn);
        params_.codo_left =
            nominal_counts_per_metre(params.left_wheel_diameter, params.counts_per_turn);
        params_.wheel_base = params.wheel_base;
    }

    void follow(const KinematicRobot& robot) {
        const std::array<std::int32_t, 2> now = robot.encoder_counts();
        pose_ = advance_pose(pose_, odometry_increment(encoder_delta(now[0], counts_[0]),
                                                       encoder_delta(now[1], counts_[1]), params_));
        counts_ = now;
    }

    const Pose2& pose() const { return pose_; }
    double metres_per_count() const { return 1.0 / params_.codo_right; }

  private:
    OdometryParams params_;
    Pose2 pose_;
    std::array<std::int32_t, 2> counts_;
};

struct StraightDrive {
    Pose2 truth;
    Pose2 odometry;
    double metres_per_count = 0.0;
};

/// Both wheels commanded at kSpeed for kSteps periods from the origin heading +x.
StraightDrive drive_straight(double slip_noise, unsigned seed) {
    KinematicRobotParams params;
    params.slip_noise = slip_noise;
    KinematicRobot robot(Pose2{}, params, seed);
    DeadReckoning odometry(robot, params);
    for (int k = 0; k < kSteps; ++k) {
        robot.drive(WheelSpeeds{kSpeed, kSpeed}, kKinematicPeriod);
        odometry.follow(robot);
    }
    return {robot.pose(), odometry.pose(), odometry.metres_per_count()};
}

TEST(KinematicWorld, SlipNeverReachesTheEncoders) {
    // The same commands, with and without slip: the encoders (what the wheels turned) agree
    // count for count at every step, while the robots end in different places.
    KinematicRobotParams slipping;
    slipping.slip_noise = 2e-3;
    KinematicRobot with_slip(Pose2{-1.0, -1.0, 0.0}, slipping, 5);
    KinematicRobot without_slip(Pose2{-1.0, -1.0, 0.0}, KinematicRobotParams{}, 5);
    for (int k = 0; k < 600; ++k) {
        const double t = k * kKinematicPeriod;
        const VelocityCommand command{0.1 + 0.05 * std::sin(0.3 * t), 0.4 * std::cos(0.2 * t)};
        with_slip.drive(command, kKinematicPeriod);
        without_slip.drive(command, kKinematicPeriod);
        ASSERT_EQ(with_slip.encoder_counts(), without_slip.encoder_counts()) << "step " << k;
    }
    EXPECT_GT(std::hypot(with_slip.pose().x - without_slip.pose().x,
                         with_slip.pose().y - without_slip.pose().y),
              1e-3);
    EXPECT_GT(std::abs(wrap_angle(with_slip.pose().theta - without_slip.pose().theta)), 1e-3);
}

TEST(KinematicWorld, WithoutSlipDeadReckoningIsTheTruthToTheEncodersWholeCounts) {
    // Equal wheels, equal speeds: the truth goes exactly along +x, and so does the odometry
    // (equal counts on both wheels give Δθ = 0 exactly). The encoders report ⌊degrees⌋, so the
    // odometry's distance is the truth's rounded down to a whole count: short by [0, 1) count.
    const StraightDrive run = drive_straight(0.0, 1);
    EXPECT_EQ(run.truth.theta, 0.0);
    EXPECT_EQ(run.truth.y, 0.0);
    EXPECT_EQ(run.odometry.theta, 0.0);
    EXPECT_EQ(run.odometry.y, 0.0);
    EXPECT_NEAR(run.truth.x, kDistance, 1e-12);
    EXPECT_GE(run.truth.x - run.odometry.x, -1e-12);
    EXPECT_LT(run.truth.x - run.odometry.x, run.metres_per_count);
}

TEST(KinematicWorld, WithSlipDeadReckoningDriftsAsTheSlipVarianceSays) {
    // Odometry keeps θ = 0 and y = 0 (the encoders agree), so its error is the truth's (θ, y).
    // Per period j each wheel slips ε ~ N(0, σ²·s), s = v·dt, independently, so the heading
    // steps by δ_j = (ε_r − ε_l)/b with Var δ = v_δ = 2σ²s/b². After K periods
    //   θ = Σ_j δ_j,
    //   y = Σ_k s·sin(θ at mid-period k) ≈ s·Σ_j (K − j − ½)·δ_j      (θ ≪ 1),
    // a linear Gaussian pair with (Σ_{m<K}(m + ½) = K²/2, Σ_{m<K}(m + ½)² = K³/3 − K/12)
    //   Var θ = v_δ·K,  Cov(θ, y) = v_δ·s·K²/2,  Var y = v_δ·s²·(K³/3 − K/12).
    // ε = eᵀΣ⁻¹e with e = truth − odometry is then χ²(2); its average over N seeds must lie in
    // the two-sided χ² interval. An encoder that counted the slip (ε ≈ 0), a slip variance off
    // by a factor of 2 or one not growing with the distance rolled all fall outside it.
    constexpr double kSlip = 1e-3;  // m^½, the experiments' value (docs/experiments.md)
    const double b = KinematicRobotParams{}.wheel_base;
    const double s = kRolledPerStep;
    const double K = kSteps;
    const double step_variance = 2.0 * kSlip * kSlip * s / (b * b);  // v_δ
    Eigen::Matrix2d covariance;
    covariance << step_variance * K, step_variance * s * K * K / 2.0,  //
        step_variance * s * K * K / 2.0, step_variance * s * s * (K * K * K / 3.0 - K / 12.0);
    const Eigen::LDLT<Eigen::Matrix2d> ldlt(covariance);

    constexpr int kSeeds = 400;
    double sum = 0.0;
    for (unsigned seed = 1; seed <= kSeeds; ++seed) {
        const StraightDrive run = drive_straight(kSlip, seed);
        ASSERT_EQ(run.odometry.theta, 0.0) << "seed " << seed;
        ASSERT_EQ(run.odometry.y, 0.0) << "seed " << seed;
        const Eigen::Vector2d error(wrap_angle(run.truth.theta - run.odometry.theta),
                                    run.truth.y - run.odometry.y);
        sum += error.dot(ldlt.solve(error));
    }
    const double average = sum / kSeeds;
    const ChiSquareInterval bounds = average_chi_square_interval(2, kSeeds, 0.999);
    EXPECT_TRUE(bounds.contains(average))
        << "average ε " << average << " outside [" << bounds.lower << ", " << bounds.upper << "]";
}

}  // namespace
}  // namespace legofeup
