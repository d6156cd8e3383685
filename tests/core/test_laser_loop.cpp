// The laser lesson in the loop (paper 001): scans ray-cast at the true pose in a hand-built
// room (plus range noise) are matched against the expected scan at the prediction.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <functional>
#include <random>

#include "kinematic_world.hpp"
#include "laser_room.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/run_metrics.hpp"

namespace legofeup {
namespace {

using testing::KinematicRobot;
using testing::KinematicRobotParams;
using testing::RunRecord;

constexpr double kPeriod = 0.05;
constexpr double kRangeNoise = 0.01;  // m, the URG's σ under 1 m

double position_error(const Pose2& truth, const StateVector& estimate) {
    return std::hypot(truth.x - estimate(kX), truth.y - estimate(kY));
}

double position_error(const Pose2& truth, const Pose2& estimate) {
    return std::hypot(truth.x - estimate.x, truth.y - estimate.y);
}

LoopConfig laser_config(FilterKind kind = FilterKind::Ekf) {
    LoopConfig config;
    config.lesson.localisation = Localisation::Laser;
    config.lesson.kind = kind;
    config.map = testing::laser_test_room();
    config.controller = FollowPath(square_path(ArenaSpec{}), 1);
    return config;
}

// The long runs use every other beam of the URG (341 over 240°): half the cost of the ICP
// in a debug build, and still ≈300 points per scan.
LoopConfig sparse_laser_config(FilterKind kind = FilterKind::Ekf) {
    LoopConfig config = laser_config(kind);
    ScanGeometry& geometry = config.lesson.laser.geometry;
    geometry.angle_increment *= 2.0;
    geometry.beam_count = 341;
    geometry.angle_min = -0.5 * (geometry.beam_count - 1) * geometry.angle_increment;
    return config;
}

// The robot of scenario.md: wheel-diameter ratio E_d = 1.005, effective base E_b = 1.03.
KinematicRobotParams biased_wheels() {
    KinematicRobotParams params;
    params.right_wheel_diameter = 0.0432 * 1.0025;
    params.left_wheel_diameter = 0.0432 / 1.0025;
    params.wheel_base = 0.12 * 1.03;
    return params;
}

// Makes the frames of a run: encoder counts of `counts`, and on every other frame a scan
// taken at `truth` (through the physical mount) in `world`.
class ScanSource {
  public:
    ScanSource(std::shared_ptr<const OccupancyGrid> world, const LaserTuning& tuning,
               unsigned seed = 3)
        : world_(std::move(world)), geometry_(tuning.geometry), mount_(tuning.mount), rng_(seed) {}

    SensorFrame frame(int k, const std::array<std::int32_t, 2>& counts, const Pose2& truth) {
        SensorFrame frame;
        frame.time = k * kPeriod;
        frame.sequence = static_cast<std::uint32_t>(k);
        frame.encoder_counts = counts;
        frame.ir_valid = {false, false};
        frame.has_laser_scan = k % 2 == 0;  // 100 ms scans on 50 ms frames
        if (frame.has_laser_scan) {
            testing::synthesize_scan(*world_, compose(truth, mount_), geometry_, noise_, rng_,
                                     frame.laser);
        }
        return frame;
    }
    void set_world(std::shared_ptr<const OccupancyGrid> world) { world_ = std::move(world); }
    void set_noise(double sigma) { noise_ = sigma; }

  private:
    std::shared_ptr<const OccupancyGrid> world_;
    ScanGeometry geometry_;
    Pose2 mount_;
    double noise_ = kRangeNoise;
    std::mt19937_64 rng_;
};

// Closed loop: the loop drives the kinematic robot, which the scans see where it really is,
// in `world`.
std::vector<RunRecord> drive(LegoFeupLoop& loop, KinematicRobot& robot,
                             std::shared_ptr<const OccupancyGrid> world, double seconds) {
    ScanSource scans(std::move(world), loop.config().lesson.laser);
    std::vector<RunRecord> records;
    const auto steps = static_cast<int>(std::lround(seconds / kPeriod));
    records.reserve(static_cast<std::size_t>(steps));
    for (int k = 0; k < steps; ++k) {
        const LoopSnapshot& s = loop.step(scans.frame(k, robot.encoder_counts(), robot.pose()));
        records.push_back({robot.pose(), s});
        robot.drive(s.wheels, kPeriod);
    }
    return records;
}

bool finite_and_positive_definite(const StateVector& x, const StateCovariance& P,
                                  const CovarianceLimits& limits) {
    if (!x.allFinite() || !P.allFinite() || P != P.transpose()) {
        return false;
    }
    const Eigen::SelfAdjointEigenSolver<StateCovariance> eigen(P);
    return eigen.eigenvalues().minCoeff() > 0.0
           && P.diagonal().maxCoeff() <= limits.max_variance * (1.0 + 1e-12);
}

// §IV: one lap of the square. Dead reckoning with the biased wheels ends far from the truth
// (and from the start); the laser estimate stays within a few centimetres all the way, with
// the EKF driving and a UKF shadow matching its own predictions. As in the paper's elevator
// hall, the world is not quite the map: a box the map does not know stands inside the
// square.
TEST(LaserLoop, TracksTheTruthWhileBiasedOdometryDrifts) {
    LoopConfig config = sparse_laser_config(FilterKind::Ekf);
    config.lesson.compare_kinds = true;
    LegoFeupLoop loop(config);
    KinematicRobot robot(config.initial.pose, biased_wheels());
    const auto world = testing::laser_test_room({{{-0.6, -0.6}, {-0.4, -0.3}}});
    const auto records = drive(loop, robot, world, 100.0);
    const RunRecord& last = records.back();
    ASSERT_TRUE(std::get<FollowPath>(loop.config().controller).laps() == 1);
    EXPECT_TRUE(last.snapshot.controller.finished) << "the lap was not completed";

    RunMetricsAccumulator metrics;
    double worst = 0.0;
    double worst_shadow = 0.0;
    for (std::size_t k = 0; k < records.size(); ++k) {
        const LoopSnapshot& s = records[k].snapshot;
        metrics.add(s, records[k].truth);
        worst = std::max(worst, position_error(records[k].truth, s.estimate));
        ASSERT_TRUE(s.shadow.active);
        ASSERT_EQ(s.shadow.kind, FilterKind::Ukf);
        worst_shadow = std::max(worst_shadow, position_error(records[k].truth, s.shadow.estimate));
        EXPECT_EQ(s.localisation, Localisation::Laser);
    }
    const RunMetrics m = metrics.result();
    ASSERT_TRUE(m.truth.has_value());
    const TruthMetrics& t = *m.truth;
    const double odometry_error = position_error(last.truth, last.snapshot.odometry_pose);
    const double estimate_error = position_error(last.truth, last.snapshot.estimate);
    EXPECT_GT(odometry_error, 0.10);
    EXPECT_LT(estimate_error, 0.04);
    EXPECT_LT(estimate_error, odometry_error / 4.0);
    EXPECT_LT(worst, 0.08);
    EXPECT_LT(worst_shadow, 0.08);
    EXPECT_LT(std::abs(wrap_angle(last.truth.theta - last.snapshot.estimate(kTheta))), 0.03);

    // The metrics agree with the records.
    EXPECT_DOUBLE_EQ(t.final_position_error, estimate_error);
    EXPECT_DOUBLE_EQ(t.final_odometry_position_error, odometry_error);
    EXPECT_DOUBLE_EQ(t.odometry_to_estimate_final_error_ratio, odometry_error / estimate_error);
    EXPECT_EQ(m.laser_scans, records.size() / 2);
    EXPECT_GT(m.laser_match_fraction, 0.95);
    EXPECT_EQ(m.laser_recoveries, 0u);
    EXPECT_EQ(t.kidnappings, 0u);
    EXPECT_EQ(t.time_to_recover, -1.0);
    EXPECT_EQ(last.snapshot.laser.total_scans, m.laser_scans);
    EXPECT_EQ(last.snapshot.laser.total_matches, m.laser_matches);
    // The paper's lap test: the robot really ends near its start; dead reckoning does not.
    EXPECT_LT(position_error(config.initial.pose, last.truth), 0.05);
    EXPECT_GT(t.odometry_end_to_start, 3.0 * t.estimate_end_to_start);
}

// Runs the loop on a robot that never moves, from frame `first` to `last` (exclusive),
// with the truth given per frame; returns the snapshots.
std::vector<LoopSnapshot> stand(LegoFeupLoop& loop, ScanSource& scans, int first, int last,
                                const std::function<Pose2(int)>& truth) {
    std::vector<LoopSnapshot> out;
    for (int k = first; k < last; ++k) {
        out.push_back(loop.step(scans.frame(k, {1000, 2000}, truth(k))));
    }
    return out;
}

// Step 6 of the localiser: Z = X̂ ⊕ M ⊕ T ⊕ M⁻¹ recovers the true pose from a prediction
// that is off, with the scanner mounted off-centre and turned.
TEST(LaserLoop, ObservedPoseUndoesTheMountAndTheMatch) {
    LoopConfig config = laser_config();
    config.lesson.laser.mount = {0.10, 0.05, 0.3};
    const Pose2 truth{-1.0, -1.0, 0.2};
    config.initial.pose = {-0.95, -1.04, 0.23};  // 6.4 cm and 0.03 rad off
    LegoFeupLoop loop(config);
    ScanSource scans(config.map, config.lesson.laser);
    scans.set_noise(0.0);
    const LoopSnapshot s = loop.step(scans.frame(0, {0, 0}, truth));
    const LaserUpdate& laser = s.laser;
    ASSERT_TRUE(laser.scan_received);
    ASSERT_TRUE(laser.matched);
    EXPECT_EQ(laser.status, StepStatus::Applied);
    const Pose2 expected_scanner = compose(config.initial.pose, config.lesson.laser.mount);
    EXPECT_NEAR(laser.scanner_pose.x, expected_scanner.x, 1e-12);
    EXPECT_NEAR(laser.scanner_pose.y, expected_scanner.y, 1e-12);
    EXPECT_NEAR(laser.observed_pose.x, truth.x, 0.015);
    EXPECT_NEAR(laser.observed_pose.y, truth.y, 0.015);
    EXPECT_NEAR(laser.observed_pose.theta, truth.theta, 0.01);
    // V = Z − X̂ (eq. 3): the prediction is the initial pose (no odometry yet).
    EXPECT_NEAR(laser.innovation(kX), laser.observed_pose.x - config.initial.pose.x, 1e-12);
    EXPECT_NEAR(laser.innovation(kTheta), laser.observed_pose.theta - config.initial.pose.theta,
                1e-12);
    EXPECT_GE(laser.icp.matched_points, config.lesson.laser.min_matched_points);
    EXPECT_GT(laser.measured_points, 500);
    EXPECT_GT(laser.expected_points, 500);
    EXPECT_EQ(laser.expected.beam_count, config.lesson.laser.geometry.beam_count);
    EXPECT_EQ(laser.correspondence_distance, config.lesson.laser.icp.max_correspondence_distance);
    // The update moved the estimate towards the truth.
    EXPECT_LT(position_error(truth, s.estimate), position_error(truth, config.initial.pose));
}

// §III-B: a scan of another room does not match; the filter only predicts, exactly as a
// twin that never received a scan, and the streak counts scans, not frames.
TEST(LaserLoop, ScanOfAnotherRoomIsAMismatchAndOnlyPredicts) {
    LoopConfig config = laser_config();
    config.lesson.laser.kidnap_recovery = false;
    const Pose2 truth = config.initial.pose;
    LegoFeupLoop loop(config);
    LegoFeupLoop twin(config);
    ScanSource closet(testing::closet_room(position_of(truth)), config.lesson.laser);
    for (int k = 0; k < 40; ++k) {
        const std::array<std::int32_t, 2> counts{10 * k, 9 * k};  // creeping forward
        const SensorFrame frame = closet.frame(k, counts, truth);
        SensorFrame without_scan = frame;
        without_scan.has_laser_scan = false;
        const LoopSnapshot& s = loop.step(frame);
        const LoopSnapshot& t = twin.step(without_scan);
        ASSERT_EQ(s.laser.scan_received, frame.has_laser_scan);
        EXPECT_FALSE(s.laser.matched);
        EXPECT_EQ(s.laser.status, StepStatus::NotAttempted);
        EXPECT_EQ(s.estimate, t.estimate);
        EXPECT_EQ(s.covariance, t.covariance);
        EXPECT_EQ(s.laser.consecutive_mismatches, k / 2 + 1);
        EXPECT_EQ(s.laser.total_scans, static_cast<std::uint32_t>(k / 2 + 1));
        EXPECT_EQ(s.laser.total_matches, 0u);
        EXPECT_FALSE(t.laser.scan_received);
        EXPECT_EQ(t.laser.consecutive_mismatches, 0);
    }
}

// §IV-B with a far kidnapping: N mismatched scans in a row multiply P by the factor exactly
// once, the ICP gets stricter until a match, and the next streak inflates again.
// With the default threshold of 100 matched points the ICP "converges" on the far place
// with 290–410 of the 682 points paired at an RMS of 6–12 cm (the paper's wrong matches);
// a right match pairs 614 (all but the 10 % trimmed) at under 1 cm. 500 separates them.
TEST(LaserLoop, MismatchStreakInflatesTheCovarianceOncePerStreak) {
    LoopConfig config = laser_config();
    LaserTuning& laser = config.lesson.laser;
    laser.min_matched_points = 500;
    laser.recovery_after_mismatches = 5;
    laser.recovery_covariance_factor = 10.0;
    laser.recovery_correspondence_factor = 0.5;
    LoopConfig no_recovery = config;
    no_recovery.lesson.laser.kidnap_recovery = false;
    LegoFeupLoop loop(config);
    LegoFeupLoop twin(no_recovery);
    const Pose2 home = config.initial.pose;
    const Pose2 far{1.0, 1.3, 2.0};  // across the room, turned round
    const auto truth = [&](int k) { return k >= 10 && k < 60 ? far : home; };
    ScanSource scans(config.map, laser, 5);
    ScanSource twin_scans(config.map, laser, 5);
    const auto s = stand(loop, scans, 0, 10, truth);
    const auto t = stand(twin, twin_scans, 0, 10, truth);
    EXPECT_TRUE(s.back().laser.total_matches == 5u);  // at home every scan matches

    // Kidnapped at frame 10: scans at 10, 12, … mismatch; the 5th (frame 18) inflates P.
    const auto kidnapped = stand(loop, scans, 10, 60, truth);
    const auto twin_kidnapped = stand(twin, twin_scans, 10, 60, truth);
    int triggers = 0;
    for (std::size_t i = 0; i < kidnapped.size(); ++i) {
        const int k = 10 + static_cast<int>(i);
        const LaserUpdate& u = kidnapped[i].laser;
        if (u.scan_received) {
            ASSERT_FALSE(u.matched) << "frame " << k << " matched the wrong place";
        }
        if (k < 18) {
            EXPECT_FALSE(u.recovery_active);
            EXPECT_EQ(kidnapped[i].covariance, twin_kidnapped[i].covariance);
            EXPECT_EQ(u.correspondence_distance, 0.3);
        }
        if (k == 18) {
            ASSERT_TRUE(u.recovery_triggered);
            EXPECT_EQ(u.correspondence_distance, 0.3);  // the trigger's own scan: normal
            EXPECT_EQ(u.consecutive_mismatches, 5);
            // P ← 10·P, on top of the same prediction the twin made.
            EXPECT_LT((kidnapped[i].covariance - 10.0 * twin_kidnapped[i].covariance)
                          .cwiseAbs()
                          .maxCoeff(),
                      1e-12 * twin_kidnapped[i].covariance.norm() * 10.0);
        }
        if (k > 18) {
            EXPECT_TRUE(u.recovery_active);
            if (u.scan_received) {
                EXPECT_DOUBLE_EQ(u.correspondence_distance, 0.15);
            }
        }
        triggers += u.recovery_triggered ? 1 : 0;
        EXPECT_TRUE(finite_and_positive_definite(kidnapped[i].estimate, kidnapped[i].covariance,
                                                 config.filter.limits));
    }
    EXPECT_EQ(triggers, 1);
    EXPECT_EQ(kidnapped.back().laser.total_recoveries, 1u);
    EXPECT_EQ(kidnapped.back().laser.consecutive_mismatches, 25);

    // Back home: the next scan matches, the streak ends and the ICP relaxes.
    const auto home_again = stand(loop, scans, 60, 62, truth);
    EXPECT_TRUE(home_again[0].laser.matched);
    EXPECT_DOUBLE_EQ(home_again[0].laser.correspondence_distance, 0.15);  // found strictly
    EXPECT_EQ(home_again[0].laser.consecutive_mismatches, 0);
    EXPECT_FALSE(home_again[0].laser.recovery_active);
    EXPECT_DOUBLE_EQ(home_again[1].laser.correspondence_distance, 0.3);

    // A second kidnapping is a new streak: P is inflated again, once.
    const auto again = stand(loop, scans, 62, 100, [&](int) { return far; });
    int second_triggers = 0;
    for (const LoopSnapshot& snapshot : again) {
        second_triggers += snapshot.laser.recovery_triggered ? 1 : 0;
    }
    EXPECT_EQ(second_triggers, 1);
    EXPECT_EQ(again.back().laser.total_recoveries, 2u);
}

// §IV-B: lifted 25 cm and 0.15 rad away while standing, the robot is found again.
TEST(LaserLoop, NearbyKidnappingIsRecovered) {
    for (const FilterKind kind : {FilterKind::Ekf, FilterKind::Ukf}) {
        LoopConfig config = sparse_laser_config(kind);
        config.lesson.laser.recovery_after_mismatches = 10;
        LegoFeupLoop loop(config);
        const Pose2 home = config.initial.pose;
        const Pose2 moved{home.x + 0.20, home.y + 0.15, home.theta + 0.15};
        ScanSource scans(config.map, config.lesson.laser, 9);
        RunMetricsAccumulator metrics;
        GroundTruth truth;
        for (int k = 0; k < 400; ++k) {
            truth.pose = k < 20 ? home : moved;
            truth.teleports = k < 20 ? 0 : 1;  // the simulator counts its teleports
            const LoopSnapshot& s = loop.step(scans.frame(k, {0, 0}, truth.pose));
            metrics.add(s, truth);
        }
        const RunMetrics m = metrics.result();
        ASSERT_TRUE(m.truth.has_value());
        const TruthMetrics& t = *m.truth;
        EXPECT_EQ(t.kidnappings, 1u) << to_string(kind);
        EXPECT_TRUE(t.kidnap_recovered) << to_string(kind);
        EXPECT_GE(t.time_to_recover, 0.0);
        EXPECT_LT(t.time_to_recover, 20.0) << to_string(kind);
        EXPECT_LT(t.final_position_error, 0.03) << to_string(kind);
        EXPECT_LT(std::abs(wrap_angle(loop.snapshot().estimate(kTheta) - moved.theta)), 0.03)
            << to_string(kind);
    }
}

// A scan whose beam count is not the configured geometry's is skipped and counted, and the
// filter only predicts.
TEST(LaserLoop, WrongBeamCountIsSkippedAndCounted) {
    LoopConfig config = laser_config();
    LegoFeupLoop loop(config);
    LegoFeupLoop twin(config);
    ScanSource scans(config.map, config.lesson.laser);
    for (int k = 0; k < 6; ++k) {
        SensorFrame frame = scans.frame(2 * k, {5 * k, 5 * k}, config.initial.pose);
        frame.laser.beam_count = k % 2 == 0 ? 600 : 0;
        SensorFrame without_scan = frame;
        without_scan.has_laser_scan = false;
        const LoopSnapshot& s = loop.step(frame);
        const LoopSnapshot& t = twin.step(without_scan);
        EXPECT_TRUE(s.laser.scan_received);
        EXPECT_TRUE(s.laser.wrong_beam_count);
        EXPECT_FALSE(s.laser.matched);
        EXPECT_EQ(s.laser.consecutive_mismatches, 0);
        EXPECT_EQ(s.laser.total_skipped, static_cast<std::uint32_t>(k + 1));
        EXPECT_EQ(s.laser.total_scans, 0u);
        EXPECT_EQ(s.estimate, t.estimate);
        EXPECT_EQ(s.covariance, t.covariance);
    }
    RunMetricsAccumulator metrics;
    metrics.add(loop.snapshot(), config.initial.pose);
    EXPECT_EQ(metrics.result().laser_skipped_scans, 1u);
    EXPECT_EQ(metrics.result().laser_scans, 0u);
}

// Periods without a frame keep the streak and the recovery in the snapshot, and only
// predict (P grows by the static part of eq. 13).
TEST(LaserLoop, MissingFramesKeepTheStreak) {
    LoopConfig config = laser_config();
    config.lesson.laser.kidnap_recovery = false;
    LegoFeupLoop loop(config);
    ScanSource closet(testing::closet_room(position_of(config.initial.pose)), config.lesson.laser);
    for (int k = 0; k < 6; ++k) {
        loop.step(closet.frame(k, {0, 0}, config.initial.pose));
    }
    const StateCovariance before = loop.snapshot().covariance;
    const LoopSnapshot& s = loop.step_without_frame(6 * kPeriod);
    EXPECT_TRUE(s.frame_missing);
    EXPECT_FALSE(s.laser.scan_received);
    EXPECT_EQ(s.laser.consecutive_mismatches, 3);
    EXPECT_EQ(s.laser.total_scans, 3u);
    const LaserTuning& t = config.lesson.laser;
    EXPECT_NEAR(s.covariance(kX, kX) - before(kX, kX), t.q_x_static, 1e-15);
    EXPECT_NEAR(s.covariance(kTheta, kTheta) - before(kTheta, kTheta), t.q_theta_static, 1e-15);
    loop.reset();
    EXPECT_EQ(loop.snapshot().laser.consecutive_mismatches, 0);
    EXPECT_EQ(loop.step(closet.frame(0, {0, 0}, config.initial.pose)).laser.total_scans, 1u);
}

// Students type absurd numbers: whatever they type, x and P stay finite, symmetric,
// positive definite and within the covariance limits, through matches, mismatches,
// inflations, kidnappings and missed frames.
TEST(LaserLoop, AbsurdTuningsStayFinite) {
    LaserTuning tiny;
    tiny.q_x_static = tiny.q_y_static = tiny.q_theta_static = 0.0;
    tiny.q_x_dynamic = tiny.q_y_dynamic = tiny.q_theta_dynamic = 0.0;
    tiny.r_x = tiny.r_y = tiny.r_theta = kMinUserVariance;
    tiny.min_matched_points = 0;
    tiny.recovery_after_mismatches = 1;
    tiny.recovery_covariance_factor = 1e6;
    tiny.recovery_correspondence_factor = 1e-3;
    LaserTuning huge;
    huge.q_x_static = huge.q_y_static = huge.q_theta_static = kMaxUserVariance;
    huge.q_x_dynamic = huge.q_y_dynamic = huge.q_theta_dynamic = kMaxUserVariance;
    huge.r_x = huge.r_y = huge.r_theta = kMaxUserVariance;
    huge.recovery_after_mismatches = 1;
    huge.recovery_covariance_factor = 1e6;
    LaserTuning shrinking;  // a factor below 1 shrinks P at every streak
    shrinking.recovery_after_mismatches = 1;
    shrinking.recovery_covariance_factor = 1e-6;
    for (const FilterKind kind : {FilterKind::Ekf, FilterKind::Ukf}) {
        for (LaserTuning tuning : {tiny, huge, shrinking}) {
            LoopConfig config = sparse_laser_config(kind);
            tuning.geometry = config.lesson.laser.geometry;
            config.lesson.laser = tuning;
            ASSERT_TRUE(validate(config).empty());
            LegoFeupLoop loop(config);
            ScanSource scans(config.map, tuning, 21);
            const Pose2 home = config.initial.pose;
            for (int k = 0; k < 120; ++k) {
                const int phase = (k / 20) % 3;  // home, far away, another room
                scans.set_world(phase == 2 ? testing::closet_room(position_of(home)) : config.map);
                const Pose2 truth = phase == 1 ? Pose2{0.8, 1.2, -2.5} : home;
                const LoopSnapshot& s = k % 7 == 6
                                            ? loop.step_without_frame(k * kPeriod)
                                            : loop.step(scans.frame(k, {20 * k, 17 * k}, truth));
                ASSERT_TRUE(
                    finite_and_positive_definite(s.estimate, s.covariance, config.filter.limits))
                    << to_string(kind) << " step " << k << "\n"
                    << s.covariance;
            }
        }
    }
}

}  // namespace
}  // namespace legofeup
