// The loop on a real robot's timing (docs/loop.md, "Steps of any length"): frames 40–150 ms
// apart, as an NXT over Bluetooth delivers them, long gaps between frames, and encoder
// glitches. Q is stated per nominal period and scaled by each step's elapsed time; a gap is
// motion, not a glitch; a glitch adds the noise of the motion it skipped.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "kinematic_world.hpp"
#include "legofeup/core/chi_square.hpp"
#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup {
namespace {

using testing::KinematicRobot;
using testing::KinematicRobotParams;

constexpr double kTimingSpeed = 0.1;     // m/s, both wheels: a straight drive
constexpr double kTimingSlip = 1e-3;     // m^½: the kinematic robot's slip (the experiments')
constexpr double kTimingSeconds = 20.0;  // 2 m
// Encoders fine enough (0.004 mm a count) that their rounding is nothing next to the slip.
constexpr double kFineCountsPerTurn = 36000.0;
// Why this small a slip: the heading error θ shortens the distance along x by about
// S·E[θ²]/4, a bias the EKF's linearisation does not see. With σ_θ² = 2·slip²·S/b² that
// bias is slip·S^1.5/(√2·b²) ≈ 0.14 of σ_x here, but 1.4 of it at slip 0.01.

/// The kinematic robot with those encoders, and `slip`.
KinematicRobotParams fine_encoder_robot(double slip = 0.0) {
    KinematicRobotParams params;
    params.counts_per_turn = kFineCountsPerTurn;
    params.slip_noise = slip;
    return params;
}

// The filter's Q for one nominal period Ts that matches the kinematic robot's slip: each
// wheel's ground distance is off by N(0, slip²·v·Ts) a period, independently, so
// Var(d) = slip²·v·Ts/2 and Var(Δθ) = 2·slip²·v·Ts/b², uncorrelated. An odometry-only loop
// (no IR) starting exactly at the truth.
LoopConfig slip_matched_config() {
    LoopConfig config;
    const double per_wheel = kTimingSlip * kTimingSlip * kTimingSpeed * config.control_period;
    const double b = config.odometry.wheel_base;
    config.filter.q11 = per_wheel / 2.0;
    config.filter.q22 = 2.0 * per_wheel / (b * b);
    config.initial = InitialBelief{Pose2{0.0, 0.0, 0.0}, 1e-10, 1e-10, 1e-10};
    config.odometry.codo_right = nominal_counts_per_metre(0.0432, kFineCountsPerTurn);
    config.odometry.codo_left = config.odometry.codo_right;
    return config;
}

/// With Q = diag(1e-6, 4e-6), round numbers for hand-worked covariances.
LoopConfig round_q_config() {
    LoopConfig config = slip_matched_config();
    config.filter.q11 = 1e-6;
    config.filter.q22 = 4e-6;
    return config;
}

SensorFrame odometry_frame_at(double time, std::uint32_t sequence, const KinematicRobot& robot) {
    SensorFrame frame;
    frame.time = time;
    frame.sequence = sequence;
    frame.encoder_counts = robot.encoder_counts();
    frame.ir_valid = {false, false};  // odometry only: the prediction is all there is
    return frame;
}

// eᵀP⁻¹e for e = estimate − truth (heading wrapped), computed here from the definition.
double nees_from_definition(const Pose2& truth, const LoopSnapshot& s) {
    Eigen::Vector3d e(s.estimate(kX) - truth.x, s.estimate(kY) - truth.y,
                      std::remainder(s.estimate(kTheta) - truth.theta, 2.0 * kPi));
    return e.dot(s.covariance.ldlt().solve(e));
}

struct DriveResult {
    double final_nees = 0.0;
    double mean_period = 0.0;  // s
};

// Drives straight for kTimingSeconds with frames `period()` apart; the NEES at the end.
template <class Period>
DriveResult drive_timed(unsigned seed, Period period) {
    LegoFeupLoop loop(slip_matched_config());
    KinematicRobot robot(loop.config().initial.pose, fine_encoder_robot(kTimingSlip), seed);
    double time = 0.0;
    std::uint32_t steps = 0;
    const LoopSnapshot* last = &loop.step(odometry_frame_at(time, steps++, robot));
    while (time < kTimingSeconds) {
        const double dt = period();
        robot.drive(WheelSpeeds{kTimingSpeed, kTimingSpeed}, dt);
        time += dt;
        last = &loop.step(odometry_frame_at(time, steps++, robot));
        EXPECT_EQ(last->predict_status, StepStatus::Applied) << "seed " << seed << " t " << time;
        EXPECT_FALSE(last->odometry_glitch) << "seed " << seed << " t " << time;
    }
    return {nees_from_definition(robot.pose(), *last), time / (steps - 1)};
}

TEST(LoopTiming, JitteredFramesAreAsConsistentAsRegularOnes) {
    // 50 seeds of 2 m each, once with frames every 50 ms and once 40–150 ms apart. A
    // consistent filter's final NEES is χ²(3) on each seed, so their mean over 50 seeds lies
    // in [χ²₀.₀₂₅(150), χ²₀.₉₇₅(150)]/50 = [2.36, 3.72] with probability 0.95. With Q added
    // once a step whatever its length, the jittered run (mean period 95 ms) would add Q half
    // as often as its time needs: NEES about 3·95/50 ≈ 5.7, far outside.
    constexpr int kSeeds = 50;
    const double low = chi_square_quantile(0.025, 3.0 * kSeeds) / kSeeds;
    const double high = chi_square_quantile(0.975, 3.0 * kSeeds) / kSeeds;
    double regular = 0.0;
    double jittered = 0.0;
    double mean_jittered_period = 0.0;
    for (unsigned seed = 1; seed <= kSeeds; ++seed) {
        regular += drive_timed(seed, [] { return 0.05; }).final_nees / kSeeds;
        std::mt19937_64 rng(1000 + seed);
        std::uniform_real_distribution<double> nxt_period(0.040, 0.150);
        const DriveResult run = drive_timed(seed, [&] { return nxt_period(rng); });
        jittered += run.final_nees / kSeeds;
        mean_jittered_period += run.mean_period / kSeeds;
    }
    std::cout << "mean final NEES over " << kSeeds << " seeds: regular " << regular << ", jittered "
              << jittered << " (95 % bounds [" << low << ", " << high << "])\n";
    EXPECT_GT(regular, low);
    EXPECT_LT(regular, high);
    EXPECT_GT(jittered, low);
    EXPECT_LT(jittered, high);
    // The premise: the jittered frames really are far from the nominal 50 ms on average.
    EXPECT_GT(mean_jittered_period, 0.09);
}

TEST(LoopTiming, QGrowsWithTheElapsedTimeOfTheStep) {
    // The robot stands still: each step adds ∇f_q·Q·(Δt/Ts)·∇f_qᵀ, which at θ = 0 and d = 0
    // is q11·Δt/Ts on P_xx and q22·Δt/Ts on P_θθ.
    LegoFeupLoop loop(round_q_config());
    const KinematicRobot robot(loop.config().initial.pose, fine_encoder_robot());
    const StateCovariance P0 = loop.step(odometry_frame_at(0.0, 0, robot)).covariance;
    const StateCovariance P1 =
        loop.step(odometry_frame_at(0.15, 1, robot)).covariance;  // 3 periods
    EXPECT_NEAR(P1(kX, kX) - P0(kX, kX), 3.0 * 1e-6, 1e-15);
    EXPECT_NEAR(P1(kTheta, kTheta) - P0(kTheta, kTheta), 3.0 * 4e-6, 1e-15);
    EXPECT_NEAR(P1(kY, kY), P0(kY, kY), 1e-18);  // no motion: nothing sideways
    const StateCovariance P2 =
        loop.step(odometry_frame_at(0.17, 2, robot)).covariance;  // 0.4 period
    EXPECT_NEAR(P2(kX, kX) - P1(kX, kX), 0.4 * 1e-6, 1e-15);
}

TEST(LoopTiming, AOneSecondGapAtFullSpeedIsMotionNotAGlitch) {
    // 1 s without a frame at 0.38 m/s: each wheel moves 0.38 m, beyond the 0.25 m a
    // period allows, but well within the 20 periods' 5 m. The estimate follows the truth.
    LegoFeupLoop loop(slip_matched_config());
    KinematicRobot robot(loop.config().initial.pose, fine_encoder_robot());
    loop.step(odometry_frame_at(0.0, 0, robot));
    robot.drive(WheelSpeeds{0.38, 0.38}, 1.0);
    const LoopSnapshot& s = loop.step(odometry_frame_at(1.0, 1, robot));
    EXPECT_FALSE(s.odometry_glitch);
    EXPECT_EQ(s.odometry_glitches, 0u);
    EXPECT_EQ(s.predict_status, StepStatus::Applied);
    EXPECT_NEAR(s.estimate(kX), robot.pose().x, 1e-5);  // counts of 0.004 mm
    EXPECT_NEAR(s.estimate(kY), 0.0, 1e-9);
}

TEST(LoopTiming, AGlitchSkipsItsCountsAddsTheNoiseOfTheSkippedMotionAndIsCounted) {
    const LoopConfig config = round_q_config();
    LegoFeupLoop loop(config);
    const KinematicRobot robot(loop.config().initial.pose, fine_encoder_robot());
    SensorFrame frame = odometry_frame_at(0.0, 0, robot);
    const StateCovariance P0 = loop.step(frame).covariance;
    // A counter reset on the robot: the right wheel's count jumps by 100 000 counts, 0.38 m
    // in 50 ms.
    frame = odometry_frame_at(0.05, 1, robot);
    frame.encoder_counts[0] += 100000;
    const LoopSnapshot& s = loop.step(frame);
    EXPECT_TRUE(s.odometry_glitch);
    EXPECT_EQ(s.odometry_glitches, 1u);
    EXPECT_EQ(s.predict_status, StepStatus::Applied);
    EXPECT_EQ(s.estimate, to_state(loop.config().initial.pose));  // the jump is not motion
    // Hand-worked: L = v_max·Δt = 0.38·0.05 = 0.019 m; Var(d) = L²/6, Var(Δθ) = 2L²/(3b²).
    ASSERT_EQ(config.max_wheel_speed, 0.38);
    ASSERT_EQ(config.odometry.wheel_base, 0.12);
    const double L = 0.38 * 0.05;
    const double b = 0.12;
    EXPECT_NEAR(s.covariance(kX, kX) - P0(kX, kX), 1e-6 + L * L / 6.0, 1e-15);
    EXPECT_NEAR(s.covariance(kTheta, kTheta) - P0(kTheta, kTheta),
                4e-6 + 2.0 * L * L / (3.0 * b * b), 1e-12);
    // The next frame measures from the new count: no glitch, and none counted again.
    frame = odometry_frame_at(0.10, 2, robot);
    frame.encoder_counts[0] += 100000;
    const LoopSnapshot& next = loop.step(frame);
    EXPECT_FALSE(next.odometry_glitch);
    EXPECT_EQ(next.odometry_glitches, 1u);
}

}  // namespace
}  // namespace legofeup
