// The particle filter in whole runs: in the laser lesson's office it weighs every scan
// against the map's likelihood field (not ICP) and tracks the lap; started knowing nothing
// it spreads over the office's free space. Short runs (20 s), 300 particles, so that they
// fit the sanitizer builds; docs/particle_filter.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kTwinOffset = 6.0;  // m: the east hall is the west hall moved 6 m east

struct CloudStep {
    double time = 0.0;
    double position_error = 0.0;
    double twin_error = 0.0;  ///< from the same place in the other twin hall (6 m east)
    bool scan = false;
    StepStatus scan_status = StepStatus::NotAttempted;
    ParticleSummary particles;
};

class CloudRecorder : public RunObserver {
  public:
    void on_step(const LoopSnapshot& s, const GroundTruth& truth) override {
        records.push_back(
            {s.time, std::hypot(s.estimate(kX) - truth.pose.x, s.estimate(kY) - truth.pose.y),
             std::hypot(s.estimate(kX) - truth.pose.x - kTwinOffset, s.estimate(kY) - truth.pose.y),
             s.laser.scan_received, s.laser.status, s.particles});
    }
    std::vector<CloudStep> records;
};

RunConfig laser_lap(std::uint64_t seed) {
    const Experiment* a = find_experiment("laser:a");
    EXPECT_NE(a, nullptr);
    RunConfig config = a->config;
    config.seed = seed;
    config.duration = 20.0;
    config.lesson.kind = FilterKind::Pf;
    config.lesson.particles.particle_count = 300;
    return config;
}

TEST(ParticleFilterRuns, TracksTheOfficeLapByWeighingEveryScan) {
    for (const std::uint64_t seed : {5u, 6u}) {
        CloudRecorder recorder;
        run_lockstep(resolve(laser_lap(seed)), &recorder);
        ASSERT_GT(recorder.records.size(), 300u);
        int scans = 0;
        for (const CloudStep& r : recorder.records) {
            ASSERT_EQ(r.particles.count, 300) << r.time;
            ASSERT_GT(r.particles.effective, 0.0);
            ASSERT_LE(r.particles.effective, 300.0 + 1e-9);
            ASSERT_LT(r.position_error, 0.3) << "seed " << seed << " at " << r.time << " s";
            if (r.scan) {
                ++scans;
                ASSERT_EQ(r.scan_status, StepStatus::Applied) << r.time;
            }
        }
        EXPECT_GT(scans, 150) << seed;  // one every 0.1 s
        EXPECT_LT(recorder.records.back().position_error, 0.1) << seed;
    }
}

// Started with no idea where it is, the particle filter's cloud covers the whole office's
// free space: its mean is near the building's centroid, its covariance metres wide and no
// cluster holds the weight; the EKF, given the same "unknown", takes that region's mean and
// covariance. (Whether the cloud then collapses onto the robot is not asserted: measured on
// laser:a seeds 11–14 with 2000 particles it found the robot on one seed only — the twin
// halls and a likelihood of 80 independent beams make it lock onto a wrong place; the
// closing note of the particle filter's issue says so.)
TEST(ParticleFilterRuns, AnUnknownPoseSpreadsTheBeliefOverTheOfficesFreeSpace) {
    RunConfig config = laser_lap(11);
    config.initial.unknown_pose = true;
    config.lesson.particles.particle_count = 5000;
    const ResolvedRun run = resolve(config);
    const LegoFeupLoop particles(run.loop);
    EXPECT_LT(particles.snapshot().particles.near_mean_share, 0.2);
    EXPECT_GT(particles.snapshot().covariance(kX, kX), 4.0);          // the office is 12 m wide
    EXPECT_GT(particles.snapshot().covariance(kTheta, kTheta), 3.0);  // π²/3 ≈ 3.3
    config.lesson.kind = FilterKind::Ekf;
    const LegoFeupLoop ekf(resolve(config).loop);
    EXPECT_EQ(ekf.snapshot().particles.count, 0);
    // Both describe the same region: the EKF its exact moments, the cloud their sample.
    for (const int k : {kX, kY}) {
        EXPECT_NEAR(particles.snapshot().estimate(k), ekf.snapshot().estimate(k), 0.15) << k;
        EXPECT_NEAR(particles.snapshot().covariance(k, k), ekf.snapshot().covariance(k, k),
                    0.1 * ekf.snapshot().covariance(k, k))
            << k;
    }
}

}  // namespace
}  // namespace legofeup::lessons
