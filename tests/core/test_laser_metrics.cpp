// The laser lesson's run metrics on hand-made snapshots: scan counts, the lap test's
// end-to-start distances and the time to recover from a kidnapping.
#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/run_metrics.hpp"

namespace legofeup {
namespace {

LoopSnapshot snapshot_at(double time, const Pose2& estimate, const Pose2& odometry) {
    LoopSnapshot s;
    s.time = time;
    s.estimate = to_state(estimate);
    s.covariance = 1e-4 * StateCovariance::Identity();
    s.odometry_pose = odometry;
    return s;
}

TEST(LaserMetrics, CountsScansMatchesSkipsAndRecoveries) {
    RunMetricsAccumulator metrics;
    const Pose2 pose{0.0, 0.0, 0.0};
    for (int k = 0; k < 10; ++k) {
        LoopSnapshot s = snapshot_at(0.05 * k, pose, pose);
        s.laser.scan_received = k % 2 == 0;            // 5 scans
        s.laser.matched = k == 0 || k == 2 || k == 4;  // 3 matches
        s.laser.wrong_beam_count = k == 8;             // one of the scans was skipped
        s.laser.recovery_triggered = k == 6;
        metrics.add(s, pose);
    }
    const RunMetrics m = metrics.result();
    EXPECT_EQ(m.laser_scans, 4u);
    EXPECT_EQ(m.laser_matches, 3u);
    EXPECT_EQ(m.laser_skipped_scans, 1u);
    EXPECT_EQ(m.laser_recoveries, 1u);
    EXPECT_DOUBLE_EQ(m.laser_match_fraction, 0.75);
    EXPECT_EQ(RunMetricsAccumulator().result().laser_match_fraction, 0.0);
}

TEST(LaserMetrics, EndToStartDistancesUseTheTrueStart) {
    RunMetricsAccumulator metrics;
    const Pose2 start{-1.0, -1.0, 0.0};
    // The filter believed it started elsewhere; the distances are from the true start.
    metrics.add(snapshot_at(0.0, {-0.9, -1.0, 0.0}, {-0.9, -1.0, 0.0}), start);
    metrics.add(snapshot_at(0.05, {0.0, 0.0, 1.0}, {0.5, 0.5, 1.0}), Pose2{0.1, 0.0, 1.0});
    // One lap later: truth (−1.02, −1.0), estimate 3–4–5 cm, odometry 12–16–20 cm from start.
    metrics.add(snapshot_at(0.10, {-0.97, -0.96, 0.0}, {-0.88, -0.84, 0.0}),
                Pose2{-1.02, -1.0, 0.0});
    const RunMetrics m = metrics.result();
    ASSERT_TRUE(m.truth.has_value());
    const TruthMetrics& t = *m.truth;
    EXPECT_NEAR(t.estimate_end_to_start, 0.05, 1e-12);
    EXPECT_NEAR(t.odometry_end_to_start, 0.20, 1e-12);
    // Final errors against the final truth: estimate (0.05, 0.04), odometry (0.14, 0.16).
    EXPECT_NEAR(t.final_position_error, std::hypot(0.05, 0.04), 1e-12);
    EXPECT_NEAR(t.final_odometry_position_error, std::hypot(0.14, 0.16), 1e-12);
    EXPECT_NEAR(t.odometry_to_estimate_final_error_ratio,
                std::hypot(0.14, 0.16) / std::hypot(0.05, 0.04), 1e-9);
}

// Truth at the origin, kidnapped to (1, 0) at t = 1 s; the estimate's error per step is
// given, the truth jumps once.
TruthMetrics kidnapping_run(const std::vector<double>& errors_after, bool jump = true) {
    RunMetricsAccumulator metrics;
    const Pose2 home{0.0, 0.0, 0.0};
    const Pose2 away{jump ? 1.0 : 0.0, 0.0, 0.0};
    for (int k = 0; k < 10; ++k) {  // 0 … 0.9 s at home, tracked within 1 cm
        metrics.add(snapshot_at(0.1 * k, {0.01, 0.0, 0.0}, home), home);
    }
    for (std::size_t i = 0; i < errors_after.size(); ++i) {
        const double time = 1.0 + 0.1 * static_cast<double>(i);
        metrics.add(snapshot_at(time, {away.x + errors_after[i], 0.0, 0.0}, home), away);
    }
    return metrics.result().truth.value();
}

TEST(LaserMetrics, TimeToRecoverIsTheStartOfTheFinalGoodStretch) {
    // Errors after the kidnapping (one per 0.1 s from t = 1.0): large, briefly good at
    // 1.3–1.4, bad again at 1.5, good for good from 1.6 s.
    const TruthMetrics m =
        kidnapping_run({1.0, 0.8, 0.5, 0.05, 0.09, 0.2, 0.08, 0.02, 0.01, 0.0, 0.03});
    EXPECT_EQ(m.kidnappings, 1u);
    EXPECT_TRUE(m.kidnap_recovered);
    EXPECT_NEAR(m.time_to_recover, 0.6, 1e-12);
}

TEST(LaserMetrics, NeverRecoveredOrNeverKidnappedIsMinusOne) {
    const TruthMetrics lost = kidnapping_run({1.0, 0.05, 0.05, 0.3});
    EXPECT_EQ(lost.kidnappings, 1u);
    EXPECT_FALSE(lost.kidnap_recovered);
    EXPECT_EQ(lost.time_to_recover, -1.0);
    // An error exactly at the threshold is not recovered.
    EXPECT_FALSE(kidnapping_run({1.0, kRecoveredPositionError}).kidnap_recovered);

    const TruthMetrics calm = kidnapping_run({0.01, 0.01}, false);
    EXPECT_EQ(calm.kidnappings, 0u);
    EXPECT_FALSE(calm.kidnap_recovered);
    EXPECT_EQ(calm.time_to_recover, -1.0);
}

TEST(LaserMetrics, TeleportsReportedByTheTruthCountEvenWhenSmall) {
    // A 5 cm teleport is no jump a drive could not make, but the truth says it happened.
    RunMetricsAccumulator metrics;
    GroundTruth truth;
    truth.pose = {0.0, 0.0, 0.0};
    metrics.add(snapshot_at(0.0, truth.pose, truth.pose), truth);
    truth.pose = {0.05, 0.0, 0.0};
    truth.teleports = 1;
    metrics.add(snapshot_at(0.1, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}), truth);
    metrics.add(snapshot_at(0.2, {0.05, 0.0, 0.0}, {0.0, 0.0, 0.0}), truth);
    const TruthMetrics m = metrics.result().truth.value();
    EXPECT_EQ(m.kidnappings, 1u);
    EXPECT_TRUE(m.kidnap_recovered);
    EXPECT_NEAR(m.time_to_recover, 0.0, 1e-12);  // within 10 cm straight away
    // Heading jumps count too (the Pose2 overload has no teleport count).
    RunMetricsAccumulator turned;
    turned.add(snapshot_at(0.0, {0, 0, 0}, {0, 0, 0}), Pose2{0.0, 0.0, 0.0});
    turned.add(snapshot_at(0.1, {0, 0, 0}, {0, 0, 0}), Pose2{0.0, 0.0, kKidnapHeadingJump + 0.1});
    EXPECT_EQ(turned.result().truth.value().kidnappings, 1u);
}

}  // namespace
}  // namespace legofeup
