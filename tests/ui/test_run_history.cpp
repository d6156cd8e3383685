// The history's memory is bounded (issue 21): after a 30-minute run it holds whole samples
// only for the recent steps, the latest batch and one step per second, but every step's
// record (the plots' and the arena's numbers) and trace row; a view asking for a dropped
// step's sample gets the nearest one kept.

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/ui/run_history.hpp"
#include "support/lockstep_history.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

constexpr double kPeriod = 0.05;  ///< s: the control period

/// `count` samples from step `first` on, 50 ms apart, each with a full laser scan.
std::vector<RunSample> synthetic_batch(std::size_t first, std::size_t count) {
    std::vector<RunSample> batch(count);
    for (std::size_t k = 0; k < count; ++k) {
        LoopSnapshot& snapshot = batch[k].snapshot;
        snapshot.step = first + k + 1;
        snapshot.time = static_cast<double>(first + k) * kPeriod;
        snapshot.frame.has_laser_scan = true;
        snapshot.frame.laser.beam_count = 682;
        snapshot.laser.expected.beam_count = 682;
        snapshot.covariance(kX, kX) = 1e-4 * static_cast<double>(first + k);
    }
    return batch;
}

/// Appends `steps` synthetic steps to `history` in batches of `batch` (a session's frames).
void run_for(RunHistory& history, std::size_t steps, std::size_t batch) {
    for (std::size_t first = history.size(); first < steps; first += batch) {
        history.append(synthetic_batch(first, std::min(batch, steps - first)));
    }
}

/// The most whole samples a history of `steps` steps may hold: the recent ones, one per
/// kKeptPeriod before them (and the first).
std::size_t most_whole_samples(std::size_t steps) {
    const double seconds = static_cast<double>(steps) * kPeriod;
    return RunHistory::kRecentSamples
           + static_cast<std::size_t>(std::ceil(seconds / RunHistory::kKeptPeriod)) + 1;
}

}  // namespace

TEST(RunHistory, AThirtyMinuteRunKeepsFewWholeSamplesButEveryRecord) {
    RunHistory history;
    history.restart({});
    const std::size_t steps = 30 * 60 * 20;  // 36,000
    run_for(history, steps, 2);
    ASSERT_EQ(history.size(), steps);
    ASSERT_EQ(history.records().size(), steps);
    EXPECT_LE(history.samples_kept(), most_whole_samples(steps));
    EXPECT_LT(history.samples_kept(), steps / 10);  // keeping everything would be 36,000
    // The recent run whole, the latest included.
    EXPECT_EQ(history.recent_begin(), steps - RunHistory::kRecentSamples);
    for (std::size_t i = history.recent_begin(); i < steps; ++i) {
        ASSERT_NE(history.sample(i), nullptr) << i;
        EXPECT_EQ(history.sample(i)->snapshot.step, i + 1);
    }
    EXPECT_EQ(history.latest().snapshot.step, steps);
    // Every record has its step's numbers.
    for (std::size_t i = 0; i < steps; i += 997) {
        EXPECT_DOUBLE_EQ(history.record(i).time, static_cast<double>(i) * kPeriod);
        EXPECT_EQ(history.record(i).pxx, static_cast<float>(1e-4 * static_cast<double>(i)));
    }
}

TEST(RunHistory, AThirtyMinuteRunHoldsItsRecordsAndFewSamplesInBoundedBytes) {
    RunHistory history;
    history.restart({});
    const std::size_t steps = 30 * 60 * 20;
    run_for(history, steps, 2);
    const RunHistory::Bytes bytes = history.bytes();
    // Every step's record, and no more than the vector's doubling adds to it.
    EXPECT_GE(bytes.records, steps * sizeof(StepRecord));
    EXPECT_LE(bytes.records, 2 * steps * sizeof(StepRecord));
    // Whole samples: the recent ones and one a second (~2,400 of 5.9 kB, not 36,000).
    EXPECT_EQ(bytes.samples, history.samples_kept() * sizeof(RunSample));
    EXPECT_LE(bytes.samples, most_whole_samples(steps) * sizeof(RunSample));
    // Together under a third of the 120 MB a 30-minute wall run may take (docs/gui.md).
    EXPECT_LT(bytes.total(), std::size_t{40} << 20);
}

TEST(RunHistory, TheTraceRowsAreKeptDeflated) {
    const ui::testing::LockstepRun run = ui::testing::lockstep_run("f", 1);  // ~1,700 steps
    const RunHistory history = ui::testing::history_of(run);
    const std::size_t text = history.trace_csv().size();
    const std::size_t kept = history.bytes().trace;
    // Blocks of 256 kB deflated to less than half (their buffers squeezed to what deflate
    // wrote: otherwise each keeps its input's size), and the open block's buffer, which
    // grows to twice a block as it fills past one.
    constexpr std::size_t kBlock = std::size_t{256} << 10;
    ASSERT_GT(text, 3 * kBlock);
    EXPECT_LT(kept, text / 2 + 2 * kBlock) << "kept " << kept << " bytes of " << text;
}

TEST(RunHistory, BeforeTheRecentRunOneWholeSampleASecondIsKept) {
    RunHistory history;
    history.restart({});
    const std::size_t steps = 5000;  // 250 s
    run_for(history, steps, 3);
    std::size_t kept_before_recent = 0;
    double last_kept_time = -1.0;
    for (std::size_t i = 0; i < history.recent_begin(); ++i) {
        if (const RunSample* sample = history.sample(i)) {
            ++kept_before_recent;
            if (last_kept_time >= 0.0) {
                // The first sample at or after a second from the last one kept.
                EXPECT_NEAR(sample->snapshot.time - last_kept_time, RunHistory::kKeptPeriod,
                            kPeriod + 1e-9);
            }
            last_kept_time = sample->snapshot.time;
        }
    }
    EXPECT_NE(history.sample(0), nullptr);  // the first step is always kept
    const double older_seconds = static_cast<double>(history.recent_begin()) * kPeriod;
    EXPECT_NEAR(static_cast<double>(kept_before_recent), older_seconds / RunHistory::kKeptPeriod,
                1.0);
    EXPECT_EQ(history.samples_kept(), kept_before_recent + RunHistory::kRecentSamples);
}

TEST(RunHistory, ParticleCloudsAreKeptForTheRecentSamplesOnly) {
    // A particle filter's run: every sample with a cloud of kParticlesShown points. 30
    // minutes of them would be 576 MB; the history keeps those of the recent samples.
    RunHistory history;
    history.restart({});
    const std::size_t steps = 3000;  // 150 s
    for (std::size_t first = 0; first < steps; first += 2) {
        std::vector<RunSample> batch = synthetic_batch(first, 2);
        for (RunSample& sample : batch) {
            sample.snapshot.particles.count = 10000;
            sample.particles = std::make_shared<const std::vector<ParticlePoint>>(
                kParticlesShown, ParticlePoint{1.0F, 2.0F, 0.0F, 1.0F});
        }
        history.append(std::move(batch));
    }
    std::size_t older_kept = 0;
    for (std::size_t i = 0; i < history.recent_begin(); ++i) {
        if (const RunSample* sample = history.sample(i)) {
            ++older_kept;
            EXPECT_EQ(sample->particles, nullptr) << i;  // kept for its scan, not its cloud
        }
    }
    EXPECT_GT(older_kept, 100U);  // one a second of the first 120 s
    for (std::size_t i = history.recent_begin(); i < steps; ++i) {
        ASSERT_NE(history.sample(i)->particles, nullptr) << i;
    }
    EXPECT_EQ(history.bytes().particles,
              RunHistory::kRecentSamples * kParticlesShown * sizeof(ParticlePoint));
    EXPECT_EQ(history.bytes().total(), history.bytes().records + history.bytes().samples
                                           + history.bytes().trace + history.bytes().particles);
}

TEST(RunHistory, TheLatestBatchIsWholeHoweverLarge) {
    RunHistory history;
    history.restart({});
    run_for(history, 100, 100);
    const std::size_t big = 3 * RunHistory::kRecentSamples;
    history.append(synthetic_batch(100, big));
    for (std::size_t i = 100; i < 100 + big; ++i) {
        ASSERT_NE(history.sample(i), nullptr) << i;  // whoever is told of the batch reads it
    }
    history.append(synthetic_batch(100 + big, 1));
    EXPECT_EQ(history.recent_begin(), 101 + big - RunHistory::kRecentSamples);
    EXPECT_EQ(history.sample(history.recent_begin() - 7), nullptr);  // 0.35 s before: dropped
    EXPECT_LE(history.samples_kept(), most_whole_samples(history.size()));
}

TEST(RunHistory, ADroppedStepShowsTheNearestSampleKept) {
    RunHistory history;
    history.restart({});
    run_for(history, 4000, 2);
    // Steps 0, 20, 40, … are the ones kept a second apart (50 ms steps).
    ASSERT_NE(history.sample(20), nullptr);
    ASSERT_EQ(history.sample(27), nullptr);
    EXPECT_EQ(history.nearest_sample(27).first, 20U);
    EXPECT_EQ(history.nearest_sample(27).second, history.sample(20));
    EXPECT_EQ(history.nearest_sample(33).first, 40U);
    EXPECT_EQ(history.nearest_sample(30).first, 40U);  // a tie: the later one
    const std::size_t recent = history.recent_begin();
    EXPECT_EQ(history.nearest_sample(recent + 5).first, recent + 5);
    EXPECT_EQ(history.nearest_sample(recent - 1).first, recent);
    EXPECT_EQ(history.nearest_sample(99999).first, history.size() - 1);
}

TEST(RunHistory, RestartDropsEverything) {
    RunHistory history;
    history.restart({});
    run_for(history, 1000, 10);
    const std::uint64_t epoch = history.epoch();
    history.restart({});
    EXPECT_TRUE(history.empty());
    EXPECT_EQ(history.samples_kept(), 0U);
    EXPECT_EQ(history.epoch(), epoch + 1);
    run_for(history, 10, 10);
    EXPECT_EQ(history.sample(0)->snapshot.step, 1U);
}

TEST(RunHistory, EveryRecordHasItsSamplesNumbersAndTheTraceEveryRow) {
    const ui::testing::LockstepRun run = ui::testing::lockstep_run("f", 1);  // ~1,700 steps
    RunHistory history = ui::testing::history_of(run);
    ASSERT_GT(run.samples.size(), 2 * RunHistory::kRecentSamples);
    ASSERT_EQ(history.size(), run.samples.size());
    ASSERT_LT(history.samples_kept(), run.samples.size() / 2);  // most samples dropped
    for (std::size_t i = 0; i < run.samples.size(); ++i) {
        const LoopSnapshot& x = run.samples[i].snapshot;
        const StepRecord& record = history.record(i);
        ASSERT_EQ(record.time, x.time) << i;
        ASSERT_EQ(record.estimate, to_pose(x.estimate)) << i;
        // The plots' numbers as floats (run_history.hpp), the poses as doubles.
        ASSERT_EQ(record.pxx, static_cast<float>(x.covariance(kX, kX))) << i;
        ASSERT_EQ(record.pxy, static_cast<float>(x.covariance(kX, kY))) << i;
        ASSERT_EQ(record.ptt, static_cast<float>(x.covariance(kTheta, kTheta))) << i;
        ASSERT_EQ(record.odometry.x(), static_cast<float>(x.odometry_pose.x)) << i;
        ASSERT_EQ(record.wheels.right, static_cast<float>(x.wheels.right)) << i;
        ASSERT_TRUE(record.has_truth);
        ASSERT_EQ(record.truth, run.samples[i].truth->pose) << i;
        ASSERT_TRUE(std::isnan(record.nees) == std::isnan(run.samples[i].nees)) << i;
        if (x.update.status != StepStatus::NotAttempted && std::isfinite(x.update.nis)) {
            ASSERT_EQ(record.wall_nis, static_cast<float>(x.update.nis)) << i;
        } else {
            ASSERT_TRUE(std::isnan(record.wall_nis)) << i;
        }
    }
    // The trace export is the CLI's trace of the same steps, byte for byte.
    std::ostringstream cli;
    lessons::TraceCsvWriter writer(cli, *run.scene.loop);
    for (const RunSample& sample : run.samples) {
        writer.on_step(sample.snapshot, *sample.truth);
    }
    EXPECT_EQ(history.trace_csv(), cli.str());
}
