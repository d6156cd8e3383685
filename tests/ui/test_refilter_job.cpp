// The Re-filter dialog's workers: lessons::refilter and the reading of a run log, each on a
// thread of its own (BackgroundTask), their progress and outcome through a mailbox. Its result is
// the library's, bit for bit; a configuration that does not resolve finishes with resolve()'s
// message, not a throw on the GUI thread.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "../lessons/scratch_dir_test_support.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/ui/refilter/refilter_job.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

/// A one-lap run of experiment f, recorded into `path`.
std::filesystem::path record_lap(const std::filesystem::path& path) {
    lessons::RunConfig config = lessons::find_experiment("f")->config;
    config.laps = 1;
    const lessons::ResolvedRun run = lessons::resolve(config);
    {
        lessons::RunLogWriter writer(path, run, "one lap");
        lessons::run_lockstep(run, &writer);
        writer.close();
    }
    return path;
}

/// The same, read back.
std::shared_ptr<const lessons::RunLog> recorded_lap() {
    return std::make_shared<const lessons::RunLog>(
        lessons::load_run_log(record_lap(lessons::scratch_testing::temp_dir() / "lap.log")));
}

template <class Job>
typename Job::Outcome wait_for(Job& job) {
    while (!job.finished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::optional<typename Job::Outcome> outcome = job.take();
    EXPECT_TRUE(outcome.has_value());
    EXPECT_FALSE(job.take().has_value());  // taken once
    return outcome.value_or(typename Job::Outcome{});
}

}  // namespace

TEST(RefilterJob, GivesTheLibrarysResultAndItsProgressEndsAtOne) {
    const auto log = recorded_lap();
    lessons::RunConfig tuned = log->config;
    tuned.filter.q11 *= 10.0;
    RefilterJob job(log, tuned);
    const RefilterJob::Outcome outcome = wait_for(job);
    EXPECT_EQ(job.progress(), 1.0);
    ASSERT_TRUE(outcome.result.has_value()) << outcome.error;
    EXPECT_TRUE(outcome.error.empty());
    const lessons::RefilterResult direct = lessons::refilter(*log, tuned);
    ASSERT_EQ(outcome.result->steps.size(), direct.steps.size());
    for (std::size_t i = 0; i < direct.steps.size(); ++i) {
        ASSERT_EQ(outcome.result->steps[i].new_estimate, direct.steps[i].new_estimate) << i;
        ASSERT_EQ(outcome.result->steps[i].old_estimate, direct.steps[i].old_estimate) << i;
    }
    EXPECT_TRUE(outcome.result->reproduces_recording());
    EXPECT_NE(outcome.result->steps.front().new_estimate,
              outcome.result->steps.back().new_estimate);
}

TEST(RefilterJob, AConfigurationThatDoesNotResolveFinishesWithItsMessage) {
    const auto log = recorded_lap();
    lessons::RunConfig broken = log->config;
    broken.filter.r11 = -1.0;
    RefilterJob job(log, broken);
    const RefilterJob::Outcome outcome = wait_for(job);
    EXPECT_FALSE(outcome.result.has_value());
    EXPECT_NE(outcome.error.find("r11"), std::string::npos) << outcome.error;
}

TEST(RunLogReadJob, ReadsTheLogAndItsWorldsWalls) {
    const std::filesystem::path path =
        record_lap(lessons::scratch_testing::temp_dir() / "read.log");
    RunLogReadJob job(path.string());
    const RunLogReadJob::Outcome outcome = wait_for(job);
    ASSERT_TRUE(outcome.result.has_value()) << outcome.error;
    const lessons::RunLog direct = lessons::load_run_log(path);
    ASSERT_NE(outcome.result->log, nullptr);
    EXPECT_EQ(outcome.result->log->records.size(), direct.records.size());
    EXPECT_GT(direct.records.size(), 100u);
    EXPECT_EQ(outcome.result->walls.size(), lessons::resolve(direct.config).world.walls.size());
    EXPECT_EQ(outcome.result->walls.size(), 4u);  // the arena's four walls
    EXPECT_EQ(job.progress(), 1.0);
}

TEST(RunLogReadJob, AFileThatDoesNotReadFinishesWithItsMessage) {
    const std::filesystem::path path = lessons::scratch_testing::temp_dir() / "missing.log";
    std::filesystem::remove(path);
    RunLogReadJob job(path.string());
    const RunLogReadJob::Outcome outcome = wait_for(job);
    EXPECT_FALSE(outcome.result.has_value());
    EXPECT_NE(outcome.error.find("missing.log"), std::string::npos) << outcome.error;
}

TEST(BackgroundTask, CancellingStopsTheWorkAtItsNextReport) {
    std::atomic<int> reports{0};
    {
        BackgroundTask<int> task([&reports](const TaskProgress& progress) {
            for (int i = 0;; ++i) {
                ++reports;
                if (!progress.report(0.5)) {
                    throw std::runtime_error("stopped after " + std::to_string(i + 1));
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            }
            return 0;
        });
        while (reports.load() < 3) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        EXPECT_FALSE(task.finished());
        EXPECT_EQ(task.progress(), 0.5);
        task.cancel();
        const auto outcome = wait_for(task);
        EXPECT_FALSE(outcome.result.has_value());
        EXPECT_EQ(outcome.error.rfind("stopped after ", 0), 0u) << outcome.error;
    }
    const int after_cancel = reports.load();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(reports.load(), after_cancel);  // joined: the work runs no more
}
