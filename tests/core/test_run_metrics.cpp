// Run metrics on hand-made snapshots: the counts are the same with and without a truth; what
// needs the truth is absent without one, and formed from pose_error (x̃ = x̂ − x) with it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/run_metrics.hpp"

namespace legofeup {
namespace {

// Step k of a run: an update applied at every 4th step (NIS k/10), refused by the gate at
// every 5th that is not a 4th, an observation at every even one.
LoopSnapshot step(int k, const Pose2& estimate) {
    LoopSnapshot s;
    s.time = 0.05 * k;
    s.estimate = to_state(estimate);
    s.covariance = StateVector(0.01, 0.04, 0.0004).asDiagonal();
    s.odometry_pose = estimate;
    s.observation_available = k % 2 == 0;
    if (k % 4 == 0) {
        s.update.status = StepStatus::Applied;
        s.update.nis = 0.1 * k;
    } else if (k % 5 == 0) {
        s.update.status = StepStatus::RejectedByGate;
        s.update.nis = 50.0;
    }
    return s;
}

constexpr int kSteps = 20;
// Of k = 0 … 19: applied at 0, 4, 8, 12, 16, mean NIS (0 + 0.4 + 0.8 + 1.2 + 1.6) / 5 = 0.8;
// refused at 5, 10, 15.
constexpr std::uint64_t kApplied = 5;
constexpr std::uint64_t kRejected = 3;

TEST(RunMetrics, CountsNeedNoTruthAndTheErrorsAreAbsentWithoutOne) {
    RunMetricsAccumulator without;
    RunMetricsAccumulator with;
    const Pose2 truth{1.0, 1.0, 0.0};
    for (int k = 0; k < kSteps; ++k) {
        without.add(step(k, truth));
        with.add(step(k, truth), truth);
    }
    for (const RunMetrics& m : {without.result(), with.result()}) {
        EXPECT_EQ(m.steps, static_cast<std::uint64_t>(kSteps));
        EXPECT_NEAR(m.duration, 0.05 * (kSteps - 1), 1e-12);
        EXPECT_EQ(m.observations, 10u);
        EXPECT_EQ(m.updates_applied, kApplied);
        EXPECT_EQ(m.updates_rejected, kRejected);
        EXPECT_NEAR(m.mean_nis, 0.8, 1e-12);
    }
    EXPECT_FALSE(without.result().truth.has_value());
    ASSERT_TRUE(with.result().truth.has_value());
    EXPECT_EQ(with.result().truth->steps, static_cast<std::uint64_t>(kSteps));
    EXPECT_EQ(with.result().truth->rms_position_error, 0.0);  // measured: exactly on the truth
    EXPECT_FALSE(RunMetricsAccumulator().result().truth.has_value());
}

TEST(RunMetrics, ErrorsAreThePoseErrorOverTheStepsWithATruth) {
    RunMetricsAccumulator metrics;
    const Pose2 truth{0.0, 0.0, -kPi + 0.01};
    // Steps 0–9 have a truth; the estimate is 3 cm +x and 4 cm −y off, its heading 0.02 rad
    // clockwise across ±π — then 3–4–5 doubled for the last scored step. Steps 10–19 have no
    // truth and an absurd estimate that must not count.
    for (int k = 0; k < 10; ++k) {
        const double scale = k == 9 ? 2.0 : 1.0;
        metrics.add(step(k, {0.03 * scale, -0.04 * scale, kPi - 0.01}), truth);
    }
    for (int k = 10; k < kSteps; ++k) {
        metrics.add(step(k, {9.0, 9.0, 0.0}));
    }
    const RunMetrics m = metrics.result();
    EXPECT_EQ(m.steps, static_cast<std::uint64_t>(kSteps));
    ASSERT_TRUE(m.truth.has_value());
    const TruthMetrics& t = *m.truth;
    EXPECT_EQ(t.steps, 10u);
    EXPECT_NEAR(t.final_position_error, 0.10, 1e-12);
    EXPECT_NEAR(t.max_position_error, 0.10, 1e-12);
    // RMS over the 10 scored steps: √((9·0.05² + 0.10²) / 10).
    EXPECT_NEAR(t.rms_position_error, std::sqrt((9 * 0.0025 + 0.01) / 10.0), 1e-12);
    EXPECT_NEAR(t.final_heading_error, 0.02, 1e-12);
    EXPECT_NEAR(t.rms_heading_error, 0.02, 1e-12);
    // NEES of x̃ = (0.03, −0.04, −0.02) against diag(0.01, 0.04, 0.0004):
    // 0.09 + 0.04 + 1 = 1.13 on steps 0–8; (0.06, −0.08, −0.02): 0.36 + 0.16 + 1 = 1.52.
    EXPECT_NEAR(t.mean_nees, (9 * 1.13 + 1.52) / 10.0, 1e-9);
}

TEST(RunMetrics, SpeedFiltersIntegratedPositionsAgainstOdometryOverTheSameSteps) {
    RunMetricsAccumulator metrics;
    GroundTruth truth;
    truth.pose = {1.0, 2.0, 0.5};
    // Step 0: no speeds yet (not scored by the speed metrics, although odometry is 1 m off).
    // Steps 1–4: odometry 0.1 m off in x, the wheel KF's pose 0.2 m off in y; the (v, ω)
    // KF's 0.05 m off on steps 3 and 4 only (the frames before had no accelerometers).
    LoopSnapshot first = step(0, truth.pose);
    first.odometry_pose = {2.0, 2.0, 0.5};
    metrics.add(first, truth);
    for (int k = 1; k <= 4; ++k) {
        LoopSnapshot s = step(k, truth.pose);
        s.odometry_pose = {1.1, 2.0, 0.5};
        s.speeds.valid = true;
        s.speeds.wheel_kf_pose = {1.0, 2.2, 0.5};
        s.speeds.body_kf_valid = k >= 3;
        s.speeds.body_kf_pose = {1.0, 2.0 - 0.05 * (k - 2), 0.5};  // 0.05, then 0.1 m off
        metrics.add(s, truth);
    }
    const TruthMetrics t = *metrics.result().truth;
    EXPECT_NEAR(t.rms_wheel_kf_position_error, 0.2, 1e-12);
    EXPECT_NEAR(t.final_wheel_kf_position_error, 0.2, 1e-12);
    EXPECT_NEAR(t.wheel_kf_position_to_odometry_ratio, 2.0, 1e-12);  // 0.2 / 0.1, step 0 out
    EXPECT_NEAR(t.rms_velocity_kf_position_error, std::sqrt((0.0025 + 0.01) / 2.0), 1e-12);
    EXPECT_NEAR(t.final_velocity_kf_position_error, 0.1, 1e-12);
    EXPECT_NEAR(t.velocity_kf_position_to_odometry_ratio, std::sqrt((0.0025 + 0.01) / 2.0) / 0.1,
                1e-12);
}

}  // namespace
}  // namespace legofeup
