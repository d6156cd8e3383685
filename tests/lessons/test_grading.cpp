// Grading: the submission's tuning on seeds the student never saw, aggregated and judged.
#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/grading.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lockstep_run.hpp"

namespace legofeup::lessons {
namespace {

MetricCheck check(std::string metric, MetricCheck::Op op, double threshold) {
    MetricCheck c;
    c.metric = std::move(metric);
    c.op = op;
    c.threshold = threshold;
    c.expression =
        c.metric + (op == MetricCheck::Op::Less ? " < " : " >= ") + std::to_string(threshold);
    return c;
}

// A lesson graded on step f, one lap per run to keep the tests quick.
Lesson graded_lesson() {
    Lesson lesson;
    lesson.id = "test";
    lesson.source = "test lesson";
    GradingSpec grading;
    grading.step = "f";
    grading.seeds = 3;
    grading.first_seed = 1001;
    grading.tunable = {"filter"};
    grading.checks = {check("rms_position_error_m", MetricCheck::Op::Less, 0.1),
                      check("routine_finished", MetricCheck::Op::GreaterOrEqual, 1.0)};
    lesson.grading = grading;
    return lesson;
}

Submission submission_of(const RunConfig& tuned) {
    Submission submission;
    submission.lesson = "test";
    submission.students = "Ana, Rui";
    submission.tuned = tuned;
    submission.tuned.laps = 1;
    submission.source = "ana.toml";
    return submission;
}

RunConfig reference_tuning() {
    return find_experiment("f")->config;
}

TEST(Grading, SeedsComeFromTheLessonUnlessTheTeacherOverridesThem) {
    const GradingSpec spec = *graded_lesson().grading;
    EXPECT_EQ(grading_seeds(spec, {}), (std::vector<std::uint64_t>{1001, 1002, 1003}));
    GradingRequest request;
    request.seeds = 2;
    request.first_seed = 77;
    EXPECT_EQ(grading_seeds(spec, request), (std::vector<std::uint64_t>{77, 78}));
}

TEST(Grading, AggregatesArePerSeedMetricsAveragedIndependentlyOfTheRunner) {
    const Lesson lesson = graded_lesson();
    const nlohmann::json grade = grade_submission(lesson, submission_of(reference_tuning()), {});
    ASSERT_EQ(grade["per_seed"].size(), 3u);

    // The same runs done one by one, here, with the plain lockstep runner.
    double sum = 0.0;
    double sum_squares = 0.0;
    double largest = 0.0;
    for (std::uint64_t seed = 1001; seed <= 1003; ++seed) {
        RunConfig config = submission_of(reference_tuning()).tuned;
        config.seed = seed;
        const double rms = run_lockstep(resolve(config)).metrics.truth.value().rms_position_error;
        sum += rms;
        sum_squares += rms * rms;
        largest = std::max(largest, rms);
        const nlohmann::json& row = grade["per_seed"][seed - 1001];
        EXPECT_EQ(row["seed"], seed);
        EXPECT_DOUBLE_EQ(row["metrics"]["rms_position_error_m"].get<double>(), rms);
        EXPECT_FALSE(row["metrics"].contains("wall_time_s"));  // machine-dependent: left out
    }
    const nlohmann::json& rms = grade["aggregate"]["rms_position_error_m"];
    EXPECT_NEAR(rms["mean"].get<double>(), sum / 3.0, 1e-15);
    const double variance = (sum_squares - 3.0 * (sum / 3.0) * (sum / 3.0)) / 2.0;
    EXPECT_NEAR(rms["std"].get<double>(), std::sqrt(variance), 1e-12);
    EXPECT_DOUBLE_EQ(rms["max"].get<double>(), largest);
    EXPECT_EQ(grade["aggregate"]["routine_finished"]["mean"], 1.0);  // booleans count 0/1
}

TEST(Grading, SameInputSameJsonWhateverTheNumberOfJobs) {
    const Lesson lesson = graded_lesson();
    GradingRequest one_job;
    one_job.jobs = 1;
    GradingRequest two_jobs;
    two_jobs.jobs = 2;
    const Submission submission = submission_of(reference_tuning());
    EXPECT_EQ(grade_submission(lesson, submission, one_job).dump(),
              grade_submission(lesson, submission, two_jobs).dump());
}

TEST(Grading, AGoodTuningPassesAndOdometryOnlyFails) {
    const Lesson lesson = graded_lesson();
    const nlohmann::json good = grade_submission(lesson, submission_of(reference_tuning()), {});
    EXPECT_TRUE(good["passed"].get<bool>()) << good["summary"];
    EXPECT_EQ(good["checks_passed"], 2);
    EXPECT_EQ(good["summary"].get<std::string>().rfind("PASS", 0), 0u) << good["summary"];

    RunConfig blind = reference_tuning();
    blind.filter.wall_updates = false;  // never uses the walls: drifts like odometry
    const nlohmann::json bad = grade_submission(lesson, submission_of(blind), {});
    EXPECT_FALSE(bad["passed"].get<bool>());
    EXPECT_EQ(bad["checks_passed"], 1);
    EXPECT_FALSE(bad["checks"][0]["passed"].get<bool>());
    EXPECT_GT(bad["checks"][0]["value"].get<double>(), 0.1);
    EXPECT_EQ(bad["summary"].get<std::string>().rfind("FAIL", 0), 0u) << bad["summary"];
}

TEST(Grading, ALessonWithoutGradingCannotGrade) {
    Lesson lesson = graded_lesson();
    lesson.grading.reset();
    EXPECT_THROW(grade_submission(lesson, submission_of(reference_tuning()), {}), InputError);
}

}  // namespace
}  // namespace legofeup::lessons
