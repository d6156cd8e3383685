// The built-in LegoFeup lesson: its steps are the experiments a–f, each step's checks pass
// for its own preset and fail on the runs of the steps they must tell it from, and the
// grading passes the reference tuning of step f on unseen seeds and fails the bad ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/grading.hpp"
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

Submission submission_of(const std::string& tuning) {
    return parse_submission("lesson = \"legofeup\"\nstudents = \"Test\"\n" + tuning, "test.toml",
                            legofeup_lesson());
}

// The lesson's grading of `submission` on `seeds` seeds from `first_seed` (the lesson's own
// first seed when unset): the grading code itself, pooled bounds and all.
nlohmann::json grade_of(const Submission& submission, int seeds,
                        std::optional<std::uint64_t> first_seed = std::nullopt) {
    GradingRequest request;
    request.seeds = seeds;
    request.first_seed = first_seed;
    return grade_submission(legofeup_lesson(), submission, request);
}

const nlohmann::json& check_named(const nlohmann::json& grade, const std::string& expression) {
    for (const nlohmann::json& check : grade["checks"]) {
        if (check["expression"] == expression) {
            return check;
        }
    }
    throw std::runtime_error("no grading check " + expression);
}

// Step f's reference tuning with Q and R scaled together by k.
std::string scaled_reference(double k) {
    char text[160];
    std::snprintf(text, sizeof text,
                  "[tuning.filter]\nq11 = %.6g\nq22 = %.6g\nr11 = %.6g\nr22 = %.6g\n", 1e-6 * k,
                  1e-5 * k, 1.3e-4 * k, 1.3e-4 * k);
    return text;
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
    const nlohmann::json grade = grade_of(submission_of(scaled_reference(1.0)), 3);
    EXPECT_TRUE(grade["passed"].get<bool>()) << grade["summary"].get<std::string>();
}

class BadTuning : public ::testing::TestWithParam<const char*> {};

TEST_P(BadTuning, FailsTheGrading) {
    const nlohmann::json grade =
        grade_of(submission_of(std::string("[tuning.filter]\n") + GetParam()), 1);
    EXPECT_FALSE(grade["passed"].get<bool>()) << grade["summary"].get<std::string>();
}

// Q and R scaled together by k leave the gain as it is and, after the start, scale P by k,
// so the NEES by 1/k:
// × 10 is pessimistic (mean NEES ≈ 0.35), ÷ 3 overconfident (≈ 10). The consistency check
// itself must say so — not only the share of steps inside one step's bounds — and pass the
// reference. Seeds 8001–8020: used by no other test, nor to choose the reference.
TEST(LegoFeupLesson, ConsistencyCheckTellsTheReferenceFromPessimisticAndOverconfidentQAndR) {
    constexpr const char* consistency = "mean_nees within time_average_nees_99_9_bounds";
    constexpr std::uint64_t first_seed = 8001;
    const nlohmann::json reference = grade_of(submission_of(scaled_reference(1.0)), 20, first_seed);
    EXPECT_TRUE(check_named(reference, consistency)["passed"].get<bool>())
        << reference["summary"].get<std::string>();
    EXPECT_TRUE(reference["passed"].get<bool>()) << reference["summary"].get<std::string>();
    // The bounds are χ²(3N)/N with N = 20² / Σ 1/N_i over the seeds, divided by the seeds'
    // dispersion when above 1 — worked out here from the per-seed numbers.
    std::vector<double> averages;
    std::vector<double> effective;
    for (const nlohmann::json& seed : reference["per_seed"]) {
        averages.push_back(seed["metrics"]["mean_nees"].get<double>());
        effective.push_back(seed["metrics"]["nees_effective_samples"].get<double>());
    }
    double inverse_sum = 0.0;
    double mean = 0.0;
    for (std::size_t i = 0; i < averages.size(); ++i) {
        inverse_sum += 1.0 / effective[i];
        mean += averages[i] / 20.0;
    }
    double pearson = 0.0;
    for (std::size_t i = 0; i < averages.size(); ++i) {
        pearson += std::pow(averages[i] / mean - 1.0, 2) * 1.5 * effective[i];
    }
    const double dispersion = pearson / 19.0;
    EXPECT_NEAR(reference["aggregate"]["nees_dispersion"].get<double>(), dispersion, 1e-9);
    const ChiSquareInterval expected =
        time_average_chi_square_interval(3, 400.0 / inverse_sum / std::max(dispersion, 1.0), 0.999);
    const nlohmann::json& bounds = reference["aggregate"]["time_average_nees_99_9_bounds"];
    EXPECT_NEAR(bounds[0].get<double>(), expected.lower, 1e-9);
    EXPECT_NEAR(bounds[1].get<double>(), expected.upper, 1e-9);
    for (const double k : {10.0, 1.0 / 3.0}) {
        const nlohmann::json grade = grade_of(submission_of(scaled_reference(k)), 20, first_seed);
        EXPECT_FALSE(check_named(grade, consistency)["passed"].get<bool>())
            << "Q and R × " << k << ": " << grade["summary"].get<std::string>();
    }
}

INSTANTIATE_TEST_SUITE_P(LegoFeup, BadTuning,
                         ::testing::Values("q11 = 1e-12\nq22 = 1e-12\n",  // Q of step d
                                           "q11 = 1e-1\nq22 = 1e-1\n",    // Q of step e
                                           "r11 = 1e-8\nr22 = 1e-8\n"));  // R of steps b, c

}  // namespace
}  // namespace legofeup::lessons
