// The built-in LegoFeup lesson: its steps are the experiments a–f, each step's checks pass
// for its own preset and fail on the runs of the steps they must tell it from, and the
// grading passes the reference tuning of step f on unseen seeds and fails the bad ones.
#include <gtest/gtest.h>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/submission.hpp"
#include "lesson_checks_test_support.hpp"

namespace legofeup::lessons {
namespace {

const LessonStep& step(const char* id) {
    const LessonStep* found = legofeup_lesson().find_step(id);
    EXPECT_NE(found, nullptr) << id;
    return *found;
}

bool all_pass(const std::vector<CheckResult>& results) {
    return failures(results).empty();
}

// Numbers and booleans averaged over runs; bounds (pairs) from the first run — as grading
// judges a submission.
nlohmann::json mean_metrics(const std::vector<nlohmann::json>& runs) {
    nlohmann::json mean = runs.front();
    for (auto& [name, value] : mean.items()) {
        if (!value.is_number() && !value.is_boolean()) {
            continue;
        }
        double sum = 0.0;
        for (const nlohmann::json& run : runs) {
            sum += run[name].is_boolean() ? (run[name].get<bool>() ? 1.0 : 0.0)
                                          : run[name].get<double>();
        }
        value = sum / static_cast<double>(runs.size());
    }
    return mean;
}

nlohmann::json graded_mean(const RunConfig& config, int seeds) {
    const GradingSpec& grading = *legofeup_lesson().grading;
    std::vector<nlohmann::json> runs;
    for (int i = 0; i < seeds; ++i) {
        runs.push_back(metrics_of(config, grading.first_seed + static_cast<std::uint64_t>(i)));
    }
    return mean_metrics(runs);
}

TEST(LegoFeupLesson, HasEightStepsWithTextsQuestionsChecksAndGrading) {
    const Lesson& lesson = legofeup_lesson();
    EXPECT_EQ(lesson.id, "legofeup");
    EXPECT_FALSE(lesson.goals.empty());
    ASSERT_EQ(lesson.steps.size(), 8u);  // the paper's a–f, and g–h: a bump, two gates
    for (const LessonStep& s : lesson.steps) {
        EXPECT_FALSE(s.observe.empty()) << s.id;
        EXPECT_GE(s.questions.size(), 2u) << s.id;
        EXPECT_LE(s.questions.size(), 3u) << s.id;
        EXPECT_GE(s.checks.size(), 1u) << s.id;
        EXPECT_LE(s.checks.size(), 3u) << s.id;
        for (const MetricCheck& check : s.checks) {
            EXPECT_FALSE(check.description.empty()) << s.id << " " << check.expression;
        }
    }
    ASSERT_TRUE(lesson.grading.has_value());
    EXPECT_EQ(lesson.grading->step, "f");
    EXPECT_EQ(lesson.grading->seeds, 20);
    EXPECT_EQ(lesson.grading->first_seed, 1001u);
    EXPECT_EQ(lesson.grading->tunable.front(), "filter");
    EXPECT_GE(lesson.grading->checks.size(), 3u);
}

TEST(LegoFeupLesson, TheExperimentsAreItsSteps) {
    const auto& experiments = legofeup_experiments();
    ASSERT_EQ(experiments.size(), legofeup_lesson().steps.size());
    for (std::size_t i = 0; i < experiments.size(); ++i) {
        const LessonStep& s = legofeup_lesson().steps[i];
        EXPECT_EQ(experiments[i].id, s.id);
        EXPECT_EQ(experiments[i].title, s.title);
        EXPECT_EQ(experiments[i].instructions, s.instructions);
        EXPECT_EQ(experiments[i].expectation, s.expectation);
        EXPECT_EQ(experiments[i].config.filter.q11, s.config.filter.q11);
        EXPECT_EQ(experiments[i].config.physical.ir_noise, s.config.physical.ir_noise);
    }
}

// Each test runs what it needs and nothing more: ctest runs every test in a process of its
// own, so runs cannot be shared between tests (a Debug run of two laps takes ~0.3 s).
class StepChecks : public ::testing::TestWithParam<const char*> {};

TEST_P(StepChecks, PassForItsOwnPresetOnSeedsOneAndTwo) {
    const LessonStep& s = step(GetParam());
    for (const std::uint64_t seed : {1u, 2u}) {
        const auto results = evaluate_checks(s.checks, metrics_of(s.config, seed));
        EXPECT_TRUE(all_pass(results)) << "seed " << seed << ":\n" << failures(results);
    }
}

INSTANTIATE_TEST_SUITE_P(LegoFeup, StepChecks,
                         ::testing::Values("a", "b", "c", "d", "e", "f", "g", "h"));

// Each step's checks capture what that step shows: on the run of a step it must be told
// from, at least one of them fails.
struct ChecksOnRun {
    const char* checks;
    const char* run;
};

// Names the case in test listings ("b's checks on a's run") instead of dumping its bytes.
void PrintTo(const ChecksOnRun& pair, std::ostream* out) {
    *out << pair.checks << "'s checks on " << pair.run << "'s run";
}

class StepChecksDiscriminate : public ::testing::TestWithParam<ChecksOnRun> {};

TEST_P(StepChecksDiscriminate, FailOnTheRunOfAnotherStep) {
    const auto [checks, run] = GetParam();
    EXPECT_FALSE(all_pass(evaluate_checks(step(checks).checks, metrics_of(step(run).config, 1))))
        << "step " << checks << "'s checks passed on step " << run << "'s run";
}

INSTANTIATE_TEST_SUITE_P(
    LegoFeup, StepChecksDiscriminate,
    ::testing::Values(ChecksOnRun{"a", "f"},  // odometry only: a filter using walls is not lost
                      ChecksOnRun{"b", "a"},  // ideal sensors: odometry only is lost
                      ChecksOnRun{"b", "c"},  // … and so are noisy sensors trusted blindly
                      ChecksOnRun{"c", "b"},  // noisy sensors: ideal ones do not jump
                      ChecksOnRun{"d", "f"},  // trusting odometry: a tuned filter moves at walls
                      ChecksOnRun{"e", "f"},  // distrusting odometry: a tuned filter is not lost
                      ChecksOnRun{"f", "c"},  // tuned: none of the badly tuned filters passes
                      ChecksOnRun{"f", "d"}, ChecksOnRun{"f", "e"},
                      ChecksOnRun{"h", "g"}));  // Mahalanobis gate: the fixed gates do not

TEST(LegoFeupLesson, GradingPassesTheReferenceTuningOnUnseenSeeds) {
    const auto results =
        evaluate_checks(legofeup_lesson().grading->checks, graded_mean(step("f").config, 3));
    EXPECT_TRUE(all_pass(results)) << failures(results);
}

class BadTuning : public ::testing::TestWithParam<const char*> {};

TEST_P(BadTuning, FailsTheGrading) {
    const Submission submission = parse_submission(
        std::string("lesson = \"legofeup\"\nstudents = \"Test\"\n[tuning.filter]\n") + GetParam(),
        "bad.toml", legofeup_lesson());
    const auto results =
        evaluate_checks(legofeup_lesson().grading->checks, graded_mean(submission.tuned, 1));
    EXPECT_FALSE(all_pass(results));
}

INSTANTIATE_TEST_SUITE_P(LegoFeup, BadTuning,
                         ::testing::Values("q11 = 1e-12\nq22 = 1e-12\n",  // Q of step d
                                           "q11 = 1e-1\nq22 = 1e-1\n",    // Q of step e
                                           "r11 = 1e-8\nr22 = 1e-8\n"));  // R of steps b, c

}  // namespace
}  // namespace legofeup::lessons
