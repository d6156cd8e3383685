#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

#include "kinematic_world.hpp"
#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup {
namespace {

using testing::KinematicRobot;
using testing::KinematicRobotParams;
using testing::RunRecord;

constexpr double kTwoLaps = 190.0;  // seconds: two laps of the square at 0.1 m/s

double position_error(const Pose2& truth, const StateVector& estimate) {
    return std::hypot(truth.x - estimate(kX), truth.y - estimate(kY));
}

double position_error(const Pose2& truth, const Pose2& estimate) {
    return std::hypot(truth.x - estimate.x, truth.y - estimate.y);
}

// The robot of scenario.md: wheel-diameter ratio E_d = 1.005, effective base E_b = 1.03.
KinematicRobotParams systematic_errors() {
    KinematicRobotParams params;
    params.right_wheel_diameter = 0.0432 * 1.0025;
    params.left_wheel_diameter = 0.0432 / 1.0025;
    params.wheel_base = 0.12 * 1.03;
    return params;
}

// Runs the loop against the kinematic robot, which starts where the filter believes it starts
// unless `truth_start` says otherwise.
std::vector<RunRecord> run(LoopConfig config, const KinematicRobotParams& robot_params,
                           double seconds, double ir_noise = 0.0,
                           std::optional<Pose2> truth_start = std::nullopt) {
    LegoFeupLoop loop(std::move(config));
    KinematicRobot robot(truth_start.value_or(loop.config().initial.pose), robot_params);
    return testing::run_closed_loop(loop, robot, loop.config().walls.walls(), seconds, 0.05,
                                    ir_noise);
}

TEST(LegoFeupLoop, FirstFrameOnlySetsTheEncoderReference) {
    LegoFeupLoop loop(LoopConfig{});
    SensorFrame frame;
    frame.encoder_counts = {12345, -678};
    const LoopSnapshot& first = loop.step(frame);
    EXPECT_EQ(first.step, 1u);
    EXPECT_EQ(first.predict_status, StepStatus::NotAttempted);
    EXPECT_EQ(first.estimate, to_state(loop.config().initial.pose));
    frame.encoder_counts = {12345 + 100, -678 + 100};
    const LoopSnapshot& second = loop.step(frame);
    EXPECT_EQ(second.predict_status, StepStatus::Applied);
    EXPECT_NEAR(second.estimate(kX), -1.0 + 100.0 / 2652.5824, 1e-6);
}

TEST(LegoFeupLoop, PerfectRobotStaysLocalisedAndSeesEveryWall) {
    const auto records = run(LoopConfig{}, KinematicRobotParams{}, kTwoLaps);
    std::set<int> walls_seen;
    int updates = 0;
    double worst = 0.0;
    for (const RunRecord& r : records) {
        worst = std::max(worst, position_error(r.truth, r.snapshot.estimate));
        if (r.snapshot.update.status == StepStatus::Applied) {
            ++updates;
            walls_seen.insert(r.snapshot.association.wall);
        }
    }
    EXPECT_EQ(walls_seen, (std::set<int>{0, 1, 2, 3}));
    EXPECT_GT(updates, 8 * 100);  // ~1 m of wall per side at 5 mm per period, twice
    EXPECT_LT(worst, 0.01);
}

TEST(LegoFeupLoop, OdometryOnlyDriftsAndItsCovarianceOnlyGrows) {
    // Experiment a: no updates. The estimate is pure dead reckoning, P grows without bound
    // (its determinant and P_θθ never fall; see Ekf.CovarianceOnlyGrowsWithoutUpdates) and the
    // systematic errors carry the estimate away from the truth.
    LoopConfig config;
    config.filter.wall_updates = false;
    const auto records = run(config, systematic_errors(), kTwoLaps);
    double previous_det = 0.0;
    double previous_var_theta = 0.0;
    int associations = 0;
    for (const RunRecord& r : records) {
        const LoopSnapshot& s = r.snapshot;
        EXPECT_NEAR(s.estimate(kX), s.odometry_pose.x, 1e-9);
        EXPECT_NEAR(s.estimate(kY), s.odometry_pose.y, 1e-9);
        EXPECT_NEAR(wrap_angle(s.estimate(kTheta) - s.odometry_pose.theta), 0.0, 1e-9);
        EXPECT_EQ(s.update.status, StepStatus::NotAttempted);
        EXPECT_GE(s.covariance.determinant(), previous_det);
        EXPECT_GE(s.covariance(kTheta, kTheta), previous_var_theta);
        previous_det = s.covariance.determinant();
        previous_var_theta = s.covariance(kTheta, kTheta);
        associations += s.association.associated() ? 1 : 0;
    }
    EXPECT_GT(associations, 0);  // walls are still recognised and shown, just not used
    EXPECT_GT(position_error(records.back().truth, records.back().snapshot.estimate), 0.10);
    EXPECT_GT(records.back().snapshot.covariance.trace(),
              10.0 * records[1].snapshot.covariance.trace());
}

TEST(LegoFeupLoop, WallUpdatesCorrectTheSystematicOdometryErrors) {
    const auto records = run(LoopConfig{}, systematic_errors(), kTwoLaps);
    const RunRecord& last = records.back();
    const double odometry_error = position_error(last.truth, last.snapshot.odometry_pose);
    double worst_after_first_lap = 0.0;
    for (std::size_t k = records.size() / 2; k < records.size(); ++k) {
        worst_after_first_lap = std::max(
            worst_after_first_lap, position_error(records[k].truth, records[k].snapshot.estimate));
    }
    EXPECT_GT(odometry_error, 0.10);
    EXPECT_LT(worst_after_first_lap, 0.06);
    EXPECT_LT(position_error(last.truth, last.snapshot.estimate), odometry_error / 4.0);
}

// steer_by = Odometry: the controller steers by dead reckoning whatever the filter says. With
// the robot's systematic errors the wall updates move the estimate centimetres away from
// odometry, so a run with updates and one without must still command the very same wheels,
// step for step — while steering by the estimate, the same updates change the commands.
TEST(LegoFeupLoop, SteeringByOdometryDrivesThePathWhateverTheEstimateDoes) {
    LoopConfig by_odometry;
    by_odometry.steer_by = SteeringPose::Odometry;
    LoopConfig by_odometry_without_walls = by_odometry;
    by_odometry_without_walls.filter.wall_updates = false;
    const auto with_walls = run(by_odometry, systematic_errors(), kTwoLaps / 2);
    const auto without_walls = run(by_odometry_without_walls, systematic_errors(), kTwoLaps / 2);
    const auto by_estimate = run(LoopConfig{}, systematic_errors(), kTwoLaps / 2);
    ASSERT_EQ(with_walls.size(), without_walls.size());
    ASSERT_EQ(with_walls.size(), by_estimate.size());
    double estimates_apart = 0.0;
    double commands_apart = 0.0;
    int updates = 0;
    for (std::size_t k = 0; k < with_walls.size(); ++k) {
        const LoopSnapshot& a = with_walls[k].snapshot;
        const LoopSnapshot& b = without_walls[k].snapshot;
        ASSERT_EQ(a.wheels.right, b.wheels.right) << k;
        ASSERT_EQ(a.wheels.left, b.wheels.left) << k;
        updates += a.update.status == StepStatus::Applied ? 1 : 0;
        estimates_apart = std::max(estimates_apart, (a.estimate - b.estimate).head<2>().norm());
        const LoopSnapshot& c = by_estimate[k].snapshot;
        commands_apart = std::max(commands_apart, std::abs(a.wheels.right - c.wheels.right)
                                                      + std::abs(a.wheels.left - c.wheels.left));
    }
    // The premise: the walls were used and moved the estimate off dead reckoning …
    EXPECT_GT(updates, 100);
    EXPECT_GT(estimates_apart, 0.02);
    // … and steering by that estimate would have driven otherwise.
    EXPECT_GT(commands_apart, 1e-3);
}

/// How far apart two headings are on the circle: |wrap(a − b)|, so that π − 0.001 and
/// −π + 0.001 are 0.002 apart, not 2π − 0.002.
double heading_gap(double a, double b) {
    return std::abs(wrap_angle(a - b));
}

struct SnapCounts {
    int checked = 0;          ///< applied updates checked
    int across_the_seam = 0;  ///< of which the estimate and z₂ lie on opposite sides of ±π
};

// Experiment b: R ≈ 0. At the first contact with a wall the estimate jumps onto the measured
// y and θ, however far odometry had drifted; afterwards it stays on the readings to well
// within their quantisation (one A/D count at 15 cm is ≈0.9 mm, ≈9 mrad of ObsAng). It cannot
// stay exactly on them: the prior is then as confident as the readings along the direction
// that ties y to θ, so later updates are compromises. Runs `config` for `seconds` with the
// belief starting 3 cm off the truth in y, and checks every applied update.
SnapCounts expect_direct_mode_snaps(LoopConfig config, double seconds) {
    config.filter.r11 = 1e-12;
    config.filter.r22 = 1e-12;
    const Pose2 truth_start = config.initial.pose;
    config.initial.pose.y += 0.03;  // the belief starts 3 cm off: the first update removes it
    const auto records = run(config, systematic_errors(), seconds, 0.0, truth_start);
    SnapCounts counts;
    for (const RunRecord& r : records) {
        const WallUpdateReport& update = r.snapshot.update;
        if (update.status != StepStatus::Applied) {
            continue;
        }
        // z₁ is n·p for the wall's normal (y for wall_y±, x for wall_x±).
        const Vector2 normal = config.walls.line(r.snapshot.association.wall).normal;
        const Vector2 position(r.snapshot.estimate(kX), r.snapshot.estimate(kY));
        const double position_gap = std::abs(normal.dot(position) - update.measurement(0));
        const double theta = r.snapshot.estimate(kTheta);
        if (counts.checked == 0) {
            EXPECT_GT(std::abs(update.innovation(0)), 0.02);
            EXPECT_LT(position_gap, 1e-3 * std::abs(update.innovation(0)));
        }
        EXPECT_LT(position_gap, 4e-4) << "t = " << r.snapshot.time;
        EXPECT_LT(heading_gap(theta, update.measurement(1)), 2e-3)
            << "t = " << r.snapshot.time << ": θ̂ = " << theta << ", z₂ = " << update.measurement(1);
        ++counts.checked;
        counts.across_the_seam += std::abs(theta - update.measurement(1)) > kPi ? 1 : 0;
    }
    return counts;
}

TEST(LegoFeupLoop, DirectModeSnapsToTheWalls) {
    // The first side (wall_y−, heading 0) and the start of the second (wall_x+, heading π/2).
    const SnapCounts counts = expect_direct_mode_snaps(LoopConfig{}, 40.0);
    EXPECT_GT(counts.checked, 50);
}

TEST(LegoFeupLoop, DirectModeSnapsToTheWallSeenAtHeadingPi) {
    // The third side: y = +1 driven at heading π, the sensors on wall_y+, z₂ = π + ObsAng.
    // Estimate and reading then sit on either side of the ±π seam at some updates; their gap
    // must be taken on the circle (an unwrapped gap reads ≈ 2π there).
    LoopConfig config;
    config.initial.pose = Pose2{1.0, 1.0, kPi};
    std::vector<PathSegment> path = square_path(ArenaSpec{});
    std::rotate(path.begin(), path.begin() + 2, path.end());  // start at (1, 1) heading −x
    config.controller = FollowPath(std::move(path), 0);
    const SnapCounts counts = expect_direct_mode_snaps(config, 12.0);
    EXPECT_GT(counts.checked, 50);
    EXPECT_GT(counts.across_the_seam, 0) << "the run never tested the seam";
}

TEST(LegoFeupLoop, SnapshotReportsTheModulesOutputs) {
    const auto records = run(LoopConfig{}, KinematicRobotParams{}, 6.0);
    const LoopSnapshot& s = records.back().snapshot;  // 0.6 m along the first wall
    EXPECT_TRUE(s.observation_available);
    EXPECT_EQ(s.ir[kFrontSensor].reading.status, IrStatus::InRange);
    EXPECT_NEAR(s.ir[kFrontSensor].reading.distance, 0.15, 0.003);
    EXPECT_EQ(s.association.wall, 0);
    EXPECT_EQ(s.update.status, StepStatus::Applied);
    EXPECT_TRUE(std::isfinite(s.update.nis));
    EXPECT_EQ(s.controller.kind, ControllerKind::FollowPath);
    EXPECT_EQ(s.controller.segment, 0);
    EXPECT_NEAR(s.velocity.v, 0.1, 1e-3);
    EXPECT_NEAR(s.wheels.right, s.velocity.v + 0.06 * s.velocity.w, 1e-12);
    EXPECT_NEAR(s.time, 5.95, 1e-9);
}

TEST(LegoFeupLoop, UnavailableReadingsGiveNoObservation) {
    LegoFeupLoop loop(LoopConfig{});
    SensorFrame frame;
    frame.ir_adc = {177, 177};  // ≈15 cm on both sensors
    frame.ir_valid = {true, false};
    const LoopSnapshot& s = loop.step(frame);
    EXPECT_EQ(s.ir[kRearSensor].reading.status, IrStatus::Unavailable);
    EXPECT_FALSE(s.observation_available);
    EXPECT_EQ(s.association.outcome, AssociationOutcome::NoObservation);
}

TEST(LegoFeupLoop, EncoderGlitchIsFlaggedAndSkipped) {
    LegoFeupLoop loop(LoopConfig{});
    SensorFrame frame;
    loop.step(frame);
    frame.encoder_counts = {100000, 100000};  // 37 m in 50 ms: a counter reset, not motion
    const LoopSnapshot& s = loop.step(frame);
    EXPECT_TRUE(s.odometry_glitch);
    // The filter predicts without the jump (and with the noise of the motion it hides:
    // test_loop_timing.cpp).
    EXPECT_EQ(s.predict_status, StepStatus::Applied);
    EXPECT_EQ(s.estimate, to_state(loop.config().initial.pose));
    frame.encoder_counts = {100010, 100010};  // normal motion resumes from the new reference
    EXPECT_EQ(loop.step(frame).predict_status, StepStatus::Applied);
}

TEST(LegoFeupLoop, AMissingFrameOnlyPredictsAndTheNextFrameBringsItsMotion) {
    LegoFeupLoop with_gap(LoopConfig{});
    LegoFeupLoop without_gap(LoopConfig{});
    SensorFrame frame;
    frame.ir_valid = {false, false};
    with_gap.step(frame);
    const StateCovariance P0 = without_gap.step(frame).covariance;

    frame.time = 0.05;
    frame.encoder_counts = {50, 50};
    without_gap.step(frame);
    const LoopSnapshot& missing = with_gap.step_without_frame(0.05);  // frame 2 never came
    EXPECT_TRUE(missing.frame_missing);
    EXPECT_DOUBLE_EQ(missing.time, 0.05);
    EXPECT_FALSE(missing.observation_available);
    EXPECT_EQ(missing.predict_status, StepStatus::Applied);
    EXPECT_EQ(missing.estimate, to_state(with_gap.config().initial.pose));  // X̂ unchanged
    // P ← P + ∇f_q Q ∇f_qᵀ with d = 0 at θ = 0: ∇f_q = [[1, 0], [0, 0], [0, 1]], so Q₁₁
    // adds to P_xx and Q₂₂ to P_θθ (worked by hand from eq. 12).
    StateCovariance expected = P0;
    expected(kX, kX) += with_gap.config().filter.q11;
    expected(kTheta, kTheta) += with_gap.config().filter.q22;
    EXPECT_TRUE(missing.covariance.isApprox(expected, 1e-12)) << missing.covariance;

    // Frame 3's cumulative counts bring frame 2's motion too: both loops end at the same x.
    frame.time = 0.1;
    frame.encoder_counts = {100, 100};
    const double x_without_gap = without_gap.step(frame).estimate(kX);
    const LoopSnapshot& resumed = with_gap.step(frame);
    EXPECT_FALSE(resumed.frame_missing);
    EXPECT_NEAR(resumed.estimate(kX), x_without_gap, 1e-12);
    EXPECT_NEAR(resumed.odometry_pose.x, x_without_gap, 1e-12);
}

TEST(LegoFeupLoop, ResetReturnsToTheInitialBelief) {
    LegoFeupLoop loop(LoopConfig{});
    KinematicRobot robot(loop.config().initial.pose, KinematicRobotParams{});
    testing::run_closed_loop(loop, robot, loop.config().walls.walls(), 5.0);
    EXPECT_NE(loop.snapshot().estimate, to_state(loop.config().initial.pose));
    loop.reset();
    EXPECT_EQ(loop.snapshot().estimate, to_state(loop.config().initial.pose));
    EXPECT_EQ(loop.snapshot().step, 0u);
    SensorFrame frame;
    frame.encoder_counts = {999, 999};  // the first frame after a reset only sets the reference
    EXPECT_EQ(loop.step(frame).predict_status, StepStatus::NotAttempted);
}

TEST(LegoFeupLoop, ReconfigureAppliesLiveOrRefusesWithReasons) {
    LegoFeupLoop loop(LoopConfig{});
    SensorFrame frame;
    loop.step(frame);
    LoopConfig bad = loop.config();
    bad.filter.q11 = -1.0;
    const auto issues = loop.reconfigure(bad);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].field, "filter.q11");
    EXPECT_EQ(loop.config().filter.q11, LoopConfig{}.filter.q11);

    // A larger Q22 makes P_θθ grow faster from the very next step.
    const double before = loop.snapshot().covariance(kTheta, kTheta);
    LoopConfig wider = loop.config();
    wider.filter.q22 = 1e-2;
    EXPECT_TRUE(loop.reconfigure(wider).empty());
    frame.encoder_counts = {10, 10};
    EXPECT_NEAR(loop.step(frame).covariance(kTheta, kTheta) - before, 1e-2, 1e-9);
}

TEST(LegoFeupLoop, ManualDrivingUsesEquationOne) {
    LegoFeupLoop loop(LoopConfig{});
    loop.set_controller(ManualDrive{});
    loop.set_manual_command({0.08, 0.5});
    const LoopSnapshot& s = loop.step(SensorFrame{});
    EXPECT_EQ(s.controller.kind, ControllerKind::Manual);
    EXPECT_NEAR(s.wheels.right, 0.08 + 0.12 * 0.5 / 2.0, 1e-15);
    EXPECT_NEAR(s.wheels.left, 0.08 - 0.12 * 0.5 / 2.0, 1e-15);
    loop.set_manual_command({0.0, 0.0});  // space bar: stop
    EXPECT_EQ(loop.step(SensorFrame{}).wheels.right, 0.0);
}

TEST(LegoFeupLoop, InvalidConfigurationIsRefusedWithEveryReason) {
    LoopConfig config;
    config.filter.r11 = 0.0;
    config.motion.v_ref = -0.1;
    try {
        LegoFeupLoop loop(config);
        FAIL() << "accepted an invalid configuration";
    } catch (const std::invalid_argument& error) {
        const std::string what = error.what();
        EXPECT_NE(what.find("filter.r11 = 0"), std::string::npos) << what;
        EXPECT_NE(what.find("motion.v_ref = -0.1"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace legofeup
