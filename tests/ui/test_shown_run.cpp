// The run the window showed, judged from its own steps (Qt-free): for a run nobody touched,
// the CLI's metrics to the bit; over a link without truth, the checks that need it not judged
// (and the others judged); the report's plotted steps bounded and evenly spaced however long
// the run.

#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/lesson/shown_run.hpp"
#include "legofeup/ui/session/run_samples.hpp"
#include "support/lockstep_history.hpp"
#include "support/short_run.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

/// summary.json's metrics without those that measure the machine (wall time).
nlohmann::json reproducible(nlohmann::json metrics) {
    for (auto it = metrics.begin(); it != metrics.end();) {
        it = lessons::is_machine_dependent_metric(it.key()) ? metrics.erase(it) : std::next(it);
    }
    return metrics;
}

/// `step`'s preset cut short, run in lockstep: its result, and its steps as the GUI gets them.
struct LockstepRun {
    lessons::RunResult result;
    std::vector<RunSample> samples;
};

LockstepRun run_short(const lessons::LessonStep& step) {
    SampleCollector collector;
    LockstepRun run;
    run.result =
        lessons::run_lockstep(lessons::resolve(ui::testing::short_run(step.config)), &collector);
    run.samples = collector.take();
    return run;
}

}  // namespace

TEST(ShownRun, ARunNobodyTouchedGivesTheClisMetricsAndChecks) {
    const lessons::LessonStep& step = *lessons::legofeup_lesson().find_step("f");
    const LockstepRun cli = run_short(step);
    ShownRun shown;
    for (const RunSample& sample : cli.samples) {
        shown.add(sample);
    }
    ASSERT_EQ(shown.steps(), cli.samples.size());
    const nlohmann::json expected = reproducible(lessons::result_metrics_to_json(cli.result));
    ASSERT_FALSE(expected["rms_position_error_m"].is_null());
    const report::StepOutcome outcome =
        shown.outcome(step, step.config, lessons::resolve(step.config).world);
    EXPECT_EQ(reproducible(outcome.metrics), expected) << outcome.metrics.dump();
    const std::vector<lessons::CheckResult> checks =
        lessons::evaluate_checks(step.checks, lessons::result_metrics_to_json(cli.result));
    ASSERT_EQ(outcome.checks.size(), checks.size());
    for (std::size_t i = 0; i < checks.size(); ++i) {
        EXPECT_EQ(outcome.checks[i].message, checks[i].message);
        EXPECT_FALSE(truth_missing(outcome.checks[i], outcome.metrics));
    }
    EXPECT_EQ(outcome.recording.steps().size(), cli.samples.size());  // short: every step
}

TEST(ShownRun, WithoutATruthTheChecksThatNeedOneAreNotJudgedAndTheOthersAre) {
    // Step a: "updates_applied <= 0" needs no truth, "final_position_error_m > 0.5" does.
    const lessons::Lesson& lesson = lessons::legofeup_lesson();
    const lessons::LessonStep& step = *lesson.find_step("a");
    ASSERT_EQ(step.checks.size(), 2U);
    ShownRun shown;
    for (RunSample sample : run_short(step).samples) {
        sample.truth.reset();  // what a real NXT gives
        shown.add(sample);
    }
    const report::StepOutcome outcome =
        shown.outcome(step, step.config, lessons::resolve(step.config).world);
    EXPECT_EQ(outcome.metrics["steps_without_truth"], shown.steps());
    EXPECT_TRUE(outcome.metrics["final_position_error_m"].is_null());
    EXPECT_EQ(outcome.metrics["updates_applied"], 0);
    for (const lessons::CheckResult& check : outcome.checks) {
        EXPECT_EQ(truth_missing(check, outcome.metrics),
                  lessons::is_truth_metric(check.check.metric))
            << check.check.expression;
    }
    EXPECT_TRUE(outcome.checks[0].passed);

    LessonProgress progress(lesson);
    progress.setOutcome(outcome);
    EXPECT_EQ(progress.checksPassed("a"), std::make_pair(1, 1));
    EXPECT_EQ(progress.checksNotJudged("a"), 1);
}

TEST(ShownRun, AFailedCheckOnAMetricMeasuredWithoutTruthIsJudged) {
    lessons::CheckResult failed;
    failed.check.metric = "updates_applied";
    failed.passed = false;
    const nlohmann::json metrics = {{"updates_applied", 0}, {"final_position_error_m", nullptr}};
    EXPECT_FALSE(truth_missing(failed, metrics));
    failed.check.metric = "final_position_error_m";
    EXPECT_TRUE(truth_missing(failed, metrics));
    failed.passed = true;  // (cannot happen on a null metric, but passed is never "not judged")
    EXPECT_FALSE(truth_missing(failed, metrics));
}

TEST(ShownRun, ALongRunPlotsAtMostTwiceTheReportsStepsEvenlySpacedAndItsLast) {
    const std::vector<RunSample> samples =
        ui::testing::lockstep_run("f", 2).samples;  // about 3,400 steps
    const std::size_t n = samples.size();
    const std::size_t most = 2 * kShownRunPlotSteps + 1;
    ASSERT_GT(n, 4 * most);  // the stride doubles at least twice
    // The stride the run ends with: the smallest power of two keeping ⌊(n−1)/s⌋ + 1 ≤ most.
    std::size_t stride = 1;
    while ((n - 1) / stride + 1 > most) {
        stride *= 2;
    }
    ASSERT_GE(stride, 4U);

    ShownRun shown;
    for (const RunSample& sample : samples) {
        shown.add(sample);
    }
    const report::StepOutcome outcome = shown.outcome(lessons::legofeup_lesson().steps.back(),
                                                      lessons::RunConfig{}, sim::WorldSpec{});
    const auto& plotted = outcome.recording.steps();
    const std::size_t evenly = (n - 1) / stride + 1;
    const bool last_extra = (n - 1) % stride != 0;
    ASSERT_EQ(plotted.size(), evenly + (last_extra ? 1 : 0));
    for (std::size_t i = 0; i < evenly; ++i) {
        ASSERT_EQ(plotted[i].time, samples[i * stride].snapshot.time) << i;
    }
    EXPECT_EQ(plotted.back().time, samples.back().snapshot.time);
    // The metrics still cover every step.
    EXPECT_EQ(outcome.metrics["steps"], n);
}
