// Runs on worker threads: results in input order and identical for any number of jobs,
// consumption in index order on the calling thread, progress, errors, and --shard.

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

#include "analysis_test_support.hpp"
#include "legofeup/lessons/analysis/batch_run.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

using testing::seeded_runs;
using testing::short_run_config;

TEST(BatchRun, ResultsAreInInputOrderAndTheSameForAnyNumberOfJobs) {
    const std::vector<ResolvedRun> runs = seeded_runs(short_run_config(), 5, 5);
    const std::vector<RunResult> one = run_batch(runs, 1);
    const std::vector<RunResult> three = run_batch(runs, 3);
    ASSERT_EQ(one.size(), runs.size());
    ASSERT_EQ(three.size(), runs.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        // Each result is the run of its own seed, whoever ran it.
        const RunResult alone = run_lockstep(runs[k]);
        EXPECT_EQ(one[k].metrics.truth.value().rms_position_error,
                  alone.metrics.truth.value().rms_position_error)
            << k;
        EXPECT_EQ(three[k].metrics.truth.value().rms_position_error,
                  alone.metrics.truth.value().rms_position_error)
            << k;
        EXPECT_EQ(three[k].metrics.truth.value().mean_nees, alone.metrics.truth.value().mean_nees)
            << k;
        EXPECT_EQ(three[k].metrics.steps, alone.metrics.steps) << k;
    }
    // Different seeds really gave different runs.
    EXPECT_NE(one[0].metrics.truth.value().rms_position_error,
              one[1].metrics.truth.value().rms_position_error);
}

// Counts its steps, and remembers which thread made it.
class Counter final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& /*snapshot*/, const GroundTruth& /*truth*/) override {
        ++steps;
    }
    std::uint64_t steps = 0;
};

TEST(BatchRun, ConsumesInIndexOrderOnTheCallingThreadWithItsObserver) {
    const std::vector<ResolvedRun> runs = seeded_runs(short_run_config(3.0), 1, 7);
    const std::thread::id caller = std::this_thread::get_id();
    std::vector<std::size_t> order;
    std::vector<std::size_t> progress_seen;
    run_batch(
        runs, 3, [](std::size_t) { return std::make_unique<Counter>(); },
        [&](std::size_t index, const RunResult& result, std::unique_ptr<RunObserver> observer) {
            EXPECT_EQ(std::this_thread::get_id(), caller);
            ASSERT_NE(observer, nullptr);
            // The observer saw exactly the run's steps.
            EXPECT_EQ(static_cast<Counter&>(*observer).steps, result.metrics.steps);
            order.push_back(index);
        },
        [&](std::size_t finished, std::size_t total) {
            EXPECT_EQ(std::this_thread::get_id(), caller);
            EXPECT_EQ(total, runs.size());
            progress_seen.push_back(finished);
        });
    ASSERT_EQ(order.size(), runs.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        EXPECT_EQ(order[k], k);
    }
    ASSERT_FALSE(progress_seen.empty());
    for (std::size_t k = 1; k < progress_seen.size(); ++k) {
        EXPECT_GT(progress_seen[k], progress_seen[k - 1]);  // monotone, never repeated
    }
    EXPECT_EQ(progress_seen.back(), runs.size());
}

TEST(BatchRun, AnErrorInARunIsRethrownAfterTheWorkersStop) {
    const std::vector<ResolvedRun> runs = seeded_runs(short_run_config(2.0), 1, 6);
    std::size_t consumed = 0;
    const auto failing_observers = [](std::size_t index) -> std::unique_ptr<RunObserver> {
        if (index == 2) {
            throw std::runtime_error("observer of run 2 failed");
        }
        return nullptr;
    };
    try {
        run_batch(runs, 2, failing_observers,
                  [&](std::size_t, const RunResult&, std::unique_ptr<RunObserver>) { ++consumed; });
        FAIL() << "expected the run's error";
    } catch (const std::runtime_error& error) {
        EXPECT_STREQ(error.what(), "observer of run 2 failed");
    }
    EXPECT_LE(consumed, 2U);  // nothing after the failed run is consumed
}

TEST(BatchRun, AnErrorInTheConsumerIsRethrown) {
    const std::vector<ResolvedRun> runs = seeded_runs(short_run_config(2.0), 1, 4);
    EXPECT_THROW(run_batch(runs, 2, {},
                           [](std::size_t index, const RunResult&, std::unique_ptr<RunObserver>) {
                               if (index == 1) {
                                   throw std::logic_error("consumer");
                               }
                           }),
                 std::logic_error);
}

TEST(BatchRun, NoRunsNoCalls) {
    bool called = false;
    run_batch({}, 2, {},
              [&](std::size_t, const RunResult&, std::unique_ptr<RunObserver>) { called = true; });
    EXPECT_FALSE(called);
    EXPECT_GE(available_jobs(), 1);
}

TEST(Shard, ParsesIAndNAndSplitsItemsRoundRobin) {
    const Shard shard = parse_shard("2/3");
    EXPECT_EQ(shard.index, 2);
    EXPECT_EQ(shard.count, 3);
    std::vector<std::size_t> taken;
    for (std::size_t item = 0; item < 8; ++item) {
        if (shard.takes(item)) {
            taken.push_back(item);
        }
    }
    EXPECT_EQ(taken, (std::vector<std::size_t>{1, 4, 7}));
    EXPECT_TRUE(Shard{}.takes(5));  // the default takes everything
}

TEST(Shard, RejectsWhatIsNotIOfN) {
    for (const char* text : {"", "3", "0/4", "5/4", "1/0", "a/b", "1/2/3", "-1/2", "1.5/2", "1/"}) {
        try {
            parse_shard(text);
            ADD_FAILURE() << text;
        } catch (const InputError& error) {
            ASSERT_EQ(error.problems().size(), 1U);
            EXPECT_EQ(error.problems()[0].key, "--shard");
            EXPECT_EQ(error.problems()[0].value, text);
            EXPECT_FALSE(error.problems()[0].reason.empty());
        }
    }
}

}  // namespace
}  // namespace legofeup::lessons::analysis
