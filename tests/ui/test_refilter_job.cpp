// The Re-filter dialog's worker: lessons::refilter on a thread of its own, its progress and
// its outcome through a mailbox. Its result is the library's, bit for bit; a configuration
// that does not resolve finishes with resolve()'s message, not a throw on the GUI thread.

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
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

/// A one-lap run of experiment f, recorded and read back.
std::shared_ptr<const lessons::RunLog> recorded_lap() {
    const std::filesystem::path path = lessons::scratch_testing::temp_dir() / "lap.log";
    lessons::RunConfig config = lessons::find_experiment("f")->config;
    config.laps = 1;
    const lessons::ResolvedRun run = lessons::resolve(config);
    {
        lessons::RunLogWriter writer(path, run, "one lap");
        lessons::run_lockstep(run, &writer);
        writer.close();
    }
    return std::make_shared<const lessons::RunLog>(lessons::load_run_log(path));
}

RefilterJob::Outcome wait_for(RefilterJob& job) {
    while (!job.finished()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::optional<RefilterJob::Outcome> outcome = job.take();
    EXPECT_TRUE(outcome.has_value());
    EXPECT_FALSE(job.take().has_value());  // taken once
    return outcome.value_or(RefilterJob::Outcome{});
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
