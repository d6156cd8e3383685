// Lessons as data: a good lesson reads into its steps, questions, checks, presets and
// grading; a bad one is rejected with every problem at its line; checks evaluate against a
// run's metrics.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "input_problems_test_support.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lesson.hpp"

namespace legofeup::lessons {
namespace {

constexpr const char* kGoodLesson = R"(id = "demo"
title = "A demo lesson"
goals = "Learn *something*."

[base.filter]
q11 = 2e-7

[[step]]
id = "one"
title = "First"
instructions = "Drive."
observe = "The ellipse."
expectation = "It grows."
[[step.question]]
id = "q1"
text = "Why?"
[[step.question]]
id = "q2"
text = "How much?"
[[step.check]]
expression = "final_position_error_m > 0.2"
description = "Lost."
[[step.check]]
expression = "mean_nees within time_average_nees_95_bounds"
description = "Consistent."
[step.config.filter]
wall_updates = false

[[step]]
id = "two"
title = "Second"
instructions = "Drive again."
observe = "The walls."
expectation = "It snaps."
[[step.check]]
expression = "routine_finished"
description = "Finished."
[step.config.filter]
r11 = 1e-6

[grading]
step = "two"
seeds = 5
first_seed = 500
tunable = ["filter", "initial.var_x"]
[[grading.check]]
expression = "rms_position_error_m <= 0.05"
description = "Accurate."
)";

// The problems parse_lesson reports for `text` ("" when it parses).
std::vector<InputProblem> lesson_problems_of(const std::string& text) {
    try {
        parse_lesson(text, "bad.toml");
    } catch (const InputError& error) {
        return error.problems();
    }
    return {};
}

// The one problem at `line`, failing the test if there is none or several.
InputProblem problem_at(const std::vector<InputProblem>& problems, int line) {
    std::vector<InputProblem> found;
    for (const InputProblem& problem : problems) {
        if (problem.line == line) {
            found.push_back(problem);
        }
    }
    EXPECT_EQ(found.size(), 1u) << "problems at line " << line;
    return found.empty() ? InputProblem{} : found.front();
}

// A copy of the good lesson with `from` replaced by `to` (which must occur once).
std::string edited(const std::string& from, const std::string& to) {
    std::string text = kGoodLesson;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(Lesson, ReadsStepsQuestionsChecksPresetsAndGrading) {
    const Lesson lesson = parse_lesson(kGoodLesson, "demo.toml");
    EXPECT_EQ(lesson.id, "demo");
    EXPECT_EQ(lesson.title, "A demo lesson");
    EXPECT_EQ(lesson.goals, "Learn *something*.");
    EXPECT_EQ(lesson.source, "demo.toml");
    ASSERT_EQ(lesson.steps.size(), 2u);

    const LessonStep& one = lesson.steps[0];
    EXPECT_EQ(one.id, "one");
    EXPECT_EQ(one.instructions, "Drive.");
    EXPECT_EQ(one.observe, "The ellipse.");
    EXPECT_EQ(one.expectation, "It grows.");
    ASSERT_EQ(one.questions.size(), 2u);
    EXPECT_EQ(one.questions[1].id, "q2");
    EXPECT_EQ(one.questions[1].text, "How much?");
    ASSERT_EQ(one.checks.size(), 2u);
    EXPECT_EQ(one.checks[0].metric, "final_position_error_m");
    EXPECT_EQ(one.checks[0].op, MetricCheck::Op::Greater);
    EXPECT_EQ(one.checks[0].threshold, 0.2);
    EXPECT_EQ(one.checks[0].expression, "final_position_error_m > 0.2");
    EXPECT_EQ(one.checks[0].description, "Lost.");
    EXPECT_EQ(one.checks[0].line, 21);
    EXPECT_EQ(one.checks[0].source, "demo.toml:21");
    EXPECT_EQ(one.checks[1].op, MetricCheck::Op::Within);
    EXPECT_EQ(one.checks[1].metric, "mean_nees");
    EXPECT_EQ(one.checks[1].bounds_metric, "time_average_nees_95_bounds");

    // The defaults, then [base], then the step's own overlay.
    EXPECT_EQ(one.config.filter.q11, 2e-7);
    EXPECT_FALSE(one.config.filter.wall_updates);
    EXPECT_EQ(one.config.filter.r11, RunConfig{}.filter.r11);
    const LessonStep& two = *lesson.find_step("two");
    EXPECT_EQ(two.config.filter.q11, 2e-7);
    EXPECT_TRUE(two.config.filter.wall_updates);
    EXPECT_EQ(two.config.filter.r11, 1e-6);
    EXPECT_EQ(two.config.origins.at("filter.r11").line, 39);
    EXPECT_EQ(two.questions.size(), 0u);
    // A bare true/false metric must be true: at least 1 (so its mean over seeds is 1).
    ASSERT_EQ(two.checks.size(), 1u);
    EXPECT_EQ(two.checks[0].op, MetricCheck::Op::GreaterOrEqual);
    EXPECT_EQ(two.checks[0].threshold, 1.0);
    EXPECT_EQ(lesson.find_step("three"), nullptr);

    ASSERT_TRUE(lesson.grading.has_value());
    EXPECT_EQ(lesson.grading->step, "two");
    EXPECT_EQ(lesson.grading->seeds, 5);
    EXPECT_EQ(lesson.grading->first_seed, 500u);
    EXPECT_EQ(lesson.grading->tunable, (std::vector<std::string>{"filter", "initial.var_x"}));
    ASSERT_EQ(lesson.grading->checks.size(), 1u);
    EXPECT_EQ(lesson.grading->checks[0].op, MetricCheck::Op::LessOrEqual);
    EXPECT_EQ(lesson.grading->checks[0].threshold, 0.05);
}

TEST(Lesson, GradingIsOptionalWithDefaults) {
    const std::string text = kGoodLesson;
    const Lesson without = parse_lesson(text.substr(0, text.find("[grading]")), "demo.toml");
    EXPECT_FALSE(without.grading.has_value());
    const Lesson defaults = parse_lesson(
        text.substr(0, text.find("seeds = 5")) + "tunable = [\"filter\"]\n", "demo.toml");
    ASSERT_TRUE(defaults.grading.has_value());
    EXPECT_EQ(defaults.grading->seeds, 20);
    EXPECT_EQ(defaults.grading->first_seed, 1u);
    EXPECT_TRUE(defaults.grading->checks.empty());
}

TEST(Lesson, UnknownKeysAreNamedWithTheirLineAndASuggestion) {
    const auto top = lesson_problems_of(edited("goals = ", "gaols = \"x\"\ngoals = "));
    EXPECT_EQ(problem_at(top, 3).message(),
              "bad.toml:3: gaols: unknown key (did you mean 'goals'?)");
    const auto step =
        lesson_problems_of(edited("observe = \"The walls.\"", "observ = \"The walls.\""));
    EXPECT_EQ(problem_at(step, 33).key, "step.observ");
    EXPECT_NE(problem_at(step, 33).reason.find("did you mean 'observe'"), std::string::npos);
    // …and the step now lacks its `observe`, reported at the step's header.
    EXPECT_EQ(problem_at(step, 29).key, "step.observe");
    const auto setting = lesson_problems_of(edited("r11 = 1e-6", "r1 = 1e-6"));
    EXPECT_EQ(problem_at(setting, 39).message(),
              "bad.toml:39: filter.r1: unknown setting (did you mean 'filter.r11'?)");
}

TEST(Lesson, MissingOrEmptyTextsAreProblems) {
    const auto missing = lesson_problems_of(edited("expectation = \"It snaps.\"\n", ""));
    const InputProblem at_header = problem_at(missing, 29);
    EXPECT_EQ(at_header.key, "step.expectation");
    EXPECT_NE(at_header.reason.find("missing"), std::string::npos);
    const auto empty = lesson_problems_of(edited("text = \"Why?\"", "text = \"  \""));
    EXPECT_EQ(problem_at(empty, 16).key, "step.question.text");
    const auto wrong_type = lesson_problems_of(edited("title = \"First\"", "title = 3"));
    EXPECT_EQ(problem_at(wrong_type, 10).message(),
              "bad.toml:10: step.title = 3: must be a quoted text");
    const auto no_title = lesson_problems_of(edited("title = \"A demo lesson\"\n", ""));
    EXPECT_EQ(problem_at(no_title, 1).key, "title");
}

TEST(Lesson, DuplicateIdsAreProblems) {
    const auto steps = lesson_problems_of(edited("id = \"two\"", "id = \"one\""));
    EXPECT_EQ(problem_at(steps, 30).message(),
              "bad.toml:30: step.id = \"one\": duplicate step id (first used on line 9)");
    const auto questions = lesson_problems_of(edited("id = \"q2\"", "id = \"q1\""));
    EXPECT_NE(problem_at(questions, 18).reason.find("duplicate question id"), std::string::npos);
}

TEST(Lesson, MalformedChecksAreProblems) {
    struct Case {
        const char* expression;
        const char* reason_part;
    };
    const Case cases[] = {
        {"final_position_error_m > big", "'big' after > is not a number"},
        {"final_position_error_m is large", "cannot read this check"},
        {"", "must not be empty"},
        {"rms_position_eror_m < 0.1", "did you mean 'rms_position_error_m'?"},
        {"sharpness < 0.1", "no metric 'sharpness'"},
        {"mean_nees within mean_nis", "'mean_nis' is not a pair of bounds"},
        {"mean_nees within", "cannot read this check"},
        {"mean_nees", "is a number, not true/false"},
        {"nees_95_bounds < 3", "is a pair of bounds"},
        // One step's bounds cannot judge a time average: a pessimistic filter passes them.
        {"mean_nees within nees_95_bounds", "write `mean_nees within time_average_nees_95_bounds`"},
        {"< 3", "expected a metric name"},
        {"association < 3", "no metric 'association'"},
    };
    for (const Case& c : cases) {
        const auto problems =
            lesson_problems_of(edited("final_position_error_m > 0.2", c.expression));
        const InputProblem problem = problem_at(problems, 21);
        EXPECT_EQ(problem.key, "step.check.expression") << c.expression;
        EXPECT_NE(problem.reason.find(c.reason_part), std::string::npos)
            << c.expression << " → " << problem.reason;
    }
}

TEST(Lesson, BadPresetsAreProblems) {
    // A value the configuration reader refuses, and one only resolving the run refuses.
    const auto type = lesson_problems_of(edited("wall_updates = false", "wall_updates = 3"));
    EXPECT_EQ(problem_at(type, 27).message(),
              "bad.toml:27: filter.wall_updates = 3: must be true or false");
    const auto range = lesson_problems_of(edited("r11 = 1e-6", "r11 = -1.0"));
    EXPECT_EQ(problem_at(range, 39).key, "filter.r11");
    EXPECT_NE(problem_at(range, 39).reason.find("between"), std::string::npos);
    // A bad [base] setting is reported once, not once per step.
    const auto base = lesson_problems_of(edited("q11 = 2e-7", "q11 = -1.0"));
    EXPECT_EQ(base.size(), 1u) << testing::all_messages(base);
    EXPECT_EQ(problem_at(base, 6).key, "filter.q11");
}

TEST(Lesson, BadGradingIsAProblem) {
    const auto step = lesson_problems_of(edited("step = \"two\"", "step = \"three\""));
    EXPECT_EQ(problem_at(step, 42).message(),
              "bad.toml:42: grading.step = \"three\": no step with this id (the steps are: one, "
              "two)");
    const auto tunable =
        lesson_problems_of(edited("\"initial.var_x\"", "\"filtr\", \"initial.var\""));
    EXPECT_EQ(tunable.size(), 2u) << testing::all_messages(tunable);
    EXPECT_NE(tunable[0].reason.find("did you mean 'filter'"), std::string::npos);
    EXPECT_EQ(tunable[1].value, "\"initial.var\"");
    const auto seeds = lesson_problems_of(edited("seeds = 5", "seeds = 0"));
    EXPECT_EQ(problem_at(seeds, 43).message(),
              "bad.toml:43: grading.seeds = 0: must be between 1 and 100000");
    const auto check = lesson_problems_of(edited("<= 0.05", "<= fast"));
    EXPECT_EQ(problem_at(check, 47).key, "grading.check.expression");
}

TEST(Lesson, EveryProblemIsReportedAtOnceTopToBottom) {
    std::string text = kGoodLesson;
    text.replace(text.find("observe = \"The ellipse.\""), 24, "obsrve = \"The ellipse.\"");
    text.replace(text.find("> 0.2"), 5, "> x");
    text.replace(text.find("step = \"two\""), 12, "step = \"nine\"");
    const auto problems = lesson_problems_of(text);
    ASSERT_EQ(problems.size(), 4u) << testing::all_messages(problems);
    EXPECT_EQ(problems[0].line, 8);   // [[step]] one lacks `observe`
    EXPECT_EQ(problems[1].line, 12);  // the misspelt key
    EXPECT_EQ(problems[2].line, 21);  // the check
    EXPECT_EQ(problems[3].line, 42);  // the grading step
}

TEST(Lesson, SyntaxErrorsAndEmptyLessonsAreProblems) {
    const auto syntax = lesson_problems_of("id = \"x\"\ntitle = \n");
    ASSERT_EQ(syntax.size(), 1u);
    EXPECT_EQ(syntax[0].line, 2);
    const auto no_steps = lesson_problems_of("id = \"x\"\ntitle = \"t\"\ngoals = \"g\"\n");
    EXPECT_EQ(problem_at(no_steps, 1).reason, "a lesson needs at least one [[step]]");
    const auto step_table =
        lesson_problems_of(edited("[[step]]\nid = \"two\"", "[step.x]\nid = \"two\""));
    EXPECT_FALSE(step_table.empty());
}

TEST(Lesson, LoadsFromAFileAndFindsTheBuiltInOne) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "legofeup_test_lesson.toml";
    std::ofstream(path) << edited("> 0.2", "> zero");
    try {
        load_lesson_file(path);
        FAIL() << "a bad lesson file was accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(error.problems().at(0).source, path.string());
        EXPECT_EQ(error.problems().at(0).line, 21);
    }
    std::ofstream(path) << kGoodLesson;
    EXPECT_EQ(find_lesson(path.string()).id, "demo");
    std::filesystem::remove(path);
    EXPECT_EQ(find_lesson("legofeup").steps.size(), legofeup_lesson().steps.size());
    EXPECT_THROW(find_lesson("no-such-lesson"), InputError);
    EXPECT_THROW(load_lesson_file(path), InputError);
}

TEST(Checks, KnownMetricsAreSummaryJsonsNumbersBooleansAndBounds) {
    const auto& names = known_metrics();
    for (const char* name :
         {"rms_position_error_m", "mean_nees", "nees_95_bounds", "time_average_nees_95_bounds",
          "time_average_nees_99_9_bounds", "nees_effective_samples", "routine_finished",
          "updates_applied", "mean_nis"}) {
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    }
    // The association counts are an object: a check cannot compare it.
    EXPECT_EQ(std::find(names.begin(), names.end(), "association"), names.end());
}

MetricCheck check_of(const std::string& expression) {
    const std::string text = edited("final_position_error_m > 0.2", expression);
    return parse_lesson(text, "demo.toml").steps[0].checks[0];
}

TEST(Checks, ComparisonsEvaluateWithTheirBoundaries) {
    const nlohmann::json metrics = {{"final_position_error_m", 0.2}, {"mean_nees", 3.0}};
    const auto outcome = [&](const std::string& expression) {
        return evaluate_checks({check_of(expression)}, metrics).at(0);
    };
    EXPECT_FALSE(outcome("final_position_error_m > 0.2").passed);
    EXPECT_TRUE(outcome("final_position_error_m >= 0.2").passed);
    EXPECT_FALSE(outcome("final_position_error_m < 0.2").passed);
    EXPECT_TRUE(outcome("final_position_error_m <= 0.2").passed);
    EXPECT_TRUE(outcome("final_position_error_m<0.3").passed);  // spaces are optional
    EXPECT_TRUE(outcome("mean_nees > 2.5e0").passed);
    const CheckResult result = outcome("final_position_error_m > 0.1");
    EXPECT_EQ(result.actual, 0.2);
    EXPECT_EQ(result.message, "final_position_error_m = 0.2 > 0.1: passed");
    EXPECT_EQ(result.check.description, "Lost.");
    EXPECT_EQ(outcome("mean_nees < 1").message, "mean_nees = 3 < 1: failed");
}

TEST(Checks, BooleansCountAsOneOrZero) {
    const MetricCheck finished = check_of("routine_finished");
    EXPECT_TRUE(evaluate_checks({finished}, {{"routine_finished", true}}).at(0).passed);
    const CheckResult unfinished = evaluate_checks({finished}, {{"routine_finished", false}}).at(0);
    EXPECT_FALSE(unfinished.passed);
    EXPECT_EQ(unfinished.actual, 0.0);
    // A mean over seeds: 0.95 of the runs finished is not all of them.
    EXPECT_FALSE(evaluate_checks({finished}, {{"routine_finished", 0.95}}).at(0).passed);
    EXPECT_TRUE(evaluate_checks({check_of("routine_finished > 0.5")}, {{"routine_finished", true}})
                    .at(0)
                    .passed);
}

TEST(Checks, WithinUsesTheBoundsMetricInclusively) {
    const MetricCheck within = check_of("nees_inside_fraction within nees_95_bounds");
    const auto passed = [&](double value) {
        return evaluate_checks({within},
                               {{"nees_inside_fraction", value}, {"nees_95_bounds", {0.2, 9.3}}})
            .at(0)
            .passed;
    };
    EXPECT_TRUE(passed(3.0));
    EXPECT_TRUE(passed(0.2));
    EXPECT_TRUE(passed(9.3));
    EXPECT_FALSE(passed(0.19));
    EXPECT_FALSE(passed(9.31));
    const CheckResult no_bounds = evaluate_checks({within}, {{"nees_inside_fraction", 3.0}}).at(0);
    EXPECT_FALSE(no_bounds.passed);
    EXPECT_NE(no_bounds.message.find("nees_95_bounds is not among"), std::string::npos);
    EXPECT_EQ(
        evaluate_checks({within}, {{"nees_inside_fraction", 3.0}, {"nees_95_bounds", {0.2, 9.3}}})
            .at(0)
            .message,
        "nees_inside_fraction = 3 within nees_95_bounds [0.2, 9.3]: passed");
    // Bounds that need the truth, in a run without one: said so.
    const MetricCheck average = check_of("mean_nees within time_average_nees_95_bounds");
    const CheckResult blind =
        evaluate_checks({average}, {{"mean_nees", 3.0}, {"time_average_nees_95_bounds", nullptr}})
            .at(0);
    EXPECT_FALSE(blind.passed);
    EXPECT_NE(blind.message.find("needs the ground truth"), std::string::npos) << blind.message;
}

TEST(Checks, AMissingOrNonNumericMetricFails) {
    const MetricCheck check = check_of("final_position_error_m > 0.2");
    for (const nlohmann::json& metrics :
         {nlohmann::json::object(), nlohmann::json{{"final_position_error_m", "far"}},
          nlohmann::json(nullptr)}) {
        const CheckResult result = evaluate_checks({check}, metrics).at(0);
        EXPECT_FALSE(result.passed);
        EXPECT_TRUE(std::isnan(result.actual));
        EXPECT_EQ(result.message, "final_position_error_m is not among the run's metrics: failed");
    }
    EXPECT_TRUE(evaluate_checks({}, {{"x", 1}}).empty());
}

}  // namespace
}  // namespace legofeup::lessons
