// Submissions: answers and a tuning of the graded step, checked against the lesson, and
// written back to the same document.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "input_problems_test_support.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/submission.hpp"

namespace legofeup::lessons {
namespace {

constexpr const char* kGood = R"(lesson = "legofeup"
students = "Ana Silva, Rui Costa"

[answers.a]
q1 = """
The ellipse keeps growing: nothing corrects it."""
q2 = "About 2 m."

[answers.f]
q1 = "Q11 = 2e-7"

[tuning.filter]
q11 = 2e-7
r22 = 2e-4
)";

std::vector<InputProblem> submission_problems_of(const std::string& text) {
    try {
        parse_submission(text, "sub.toml", legofeup_lesson());
    } catch (const InputError& error) {
        return error.problems();
    }
    return {};
}

const RunConfig& graded_preset() {
    return legofeup_lesson().find_step(legofeup_lesson().grading->step)->config;
}

TEST(Submission, ReadsStudentsAnswersAndTheTunedStep) {
    const Submission submission = parse_submission(kGood, "sub.toml", legofeup_lesson());
    EXPECT_EQ(submission.lesson, "legofeup");
    EXPECT_EQ(submission.students, "Ana Silva, Rui Costa");
    EXPECT_EQ(submission.source, "sub.toml");
    EXPECT_EQ(submission.answers.at("a").at("q1"),
              "The ellipse keeps growing: nothing corrects it.");
    EXPECT_EQ(submission.answers.at("a").at("q2"), "About 2 m.");
    EXPECT_EQ(submission.answers.at("f").size(), 1u);
    // The tuning over step f's preset: what it sets changes, the rest is the preset's.
    EXPECT_EQ(submission.tuned.filter.q11, 2e-7);
    EXPECT_EQ(submission.tuned.filter.r22, 2e-4);
    EXPECT_EQ(submission.tuned.filter.r11, graded_preset().filter.r11);
    EXPECT_EQ(submission.tuned.filter.q22, graded_preset().filter.q22);
    EXPECT_EQ(submission.tuned.physical.ir_noise, graded_preset().physical.ir_noise);
    EXPECT_EQ(submission.tuned.origins.at("filter.q11").source, "sub.toml");
    EXPECT_EQ(submission.tuned.origins.at("filter.q11").line, 13);
    EXPECT_EQ(submission.tuning_toml, "[filter]\nq11 = 2e-07\nr22 = 2e-04\n");
}

TEST(Submission, WithoutTuningIsTheGradedPreset) {
    const Submission submission = parse_submission("lesson = \"legofeup\"\nstudents = \"Ana\"\n",
                                                   "sub.toml", legofeup_lesson());
    EXPECT_TRUE(submission.answers.empty());
    EXPECT_TRUE(submission.tuning_toml.empty());
    EXPECT_EQ(submission.tuned.filter.q11, graded_preset().filter.q11);
    EXPECT_EQ(submission.tuned.physical.ir_noise, graded_preset().physical.ir_noise);
}

TEST(Submission, WritesWhatItReadsBack) {
    Submission submission = parse_submission(kGood, "sub.toml", legofeup_lesson());
    // Texts TOML must escape: quotes (three in a row too), backslashes, line breaks at both
    // ends, tabs, carriage returns and other control characters; and plain Unicode.
    submission.students = "Zoë \"Z\" O'Neil\\";
    submission.answers["b"]["q1"] =
        "\nStarts with a break, \"\"\"quotes\"\"\"\tand\r\n\\n\x01 ends\n";
    submission.answers["b"]["q2"] = "";
    const std::string text = submission_to_toml(submission);
    const Submission back = parse_submission(text, "back.toml", legofeup_lesson());
    EXPECT_EQ(back.students, submission.students);
    EXPECT_EQ(back.answers, submission.answers);
    EXPECT_EQ(back.tuning_toml, submission.tuning_toml);
    EXPECT_EQ(back.tuned.filter.q11, 2e-7);
    EXPECT_EQ(back.tuned.filter.r22, 2e-4);
    EXPECT_NE(text.find("[tuning.filter]\nq11 = 2e-07\n"), std::string::npos) << text;
}

TEST(Submission, TuningToTomlListsTheTunableSettingsThatChanged) {
    const Lesson& lesson = legofeup_lesson();
    RunConfig tuned = graded_preset();
    EXPECT_EQ(tuning_to_toml(tuned, lesson), "");
    tuned.filter.q22 = 3e-5;
    tuned.initial.var_x = 2e-4;
    tuned.physical.ir_noise = 0.05;  // not tunable: never part of a tuning
    EXPECT_EQ(tuning_to_toml(tuned, lesson), "[filter]\nq22 = 3e-05\n\n[initial]\nvar_x = 2e-04\n");
    Submission submission;
    submission.lesson = "legofeup";
    submission.students = "Ana";
    submission.tuning_toml = tuning_to_toml(tuned, lesson);
    const Submission back = parse_submission(submission_to_toml(submission), "back.toml", lesson);
    EXPECT_EQ(back.tuned.filter.q22, 3e-5);
    EXPECT_EQ(back.tuned.initial.var_x, 2e-4);
    EXPECT_EQ(back.tuned.physical.ir_noise, graded_preset().physical.ir_noise);
}

TEST(Submission, SettingsOutsideTheTunableListAreRejectedWithTheAllowedList) {
    const auto problems = submission_problems_of(
        "lesson = \"legofeup\"\nstudents = \"A\"\n[tuning.simulator]\nir_noise = 0.0\n"
        "[tuning]\nlaps = 1\n");
    ASSERT_EQ(problems.size(), 2u) << testing::all_messages(problems);
    EXPECT_EQ(problems[0].message(),
              "sub.toml:4: tuning.simulator.ir_noise = 0.0: lesson \"legofeup\" lets students "
              "tune only: filter, initial");
    EXPECT_EQ(problems[1].line, 6);
    EXPECT_EQ(problems[1].key, "tuning.laps");
}

TEST(Submission, BadAnswersAndValuesAreProblemsAtTheirLines) {
    const auto problems = submission_problems_of(R"(lesson = "legofeup"
students = "A"
colour = "blue"
[answers.z]
q1 = "?"
[answers.a]
q9 = "?"
q1 = 3
[tuning.filter]
q11 = -1.0
q1 = 2
)");
    ASSERT_EQ(problems.size(), 5u) << testing::all_messages(problems);
    EXPECT_EQ(problems[0].line, 3);
    EXPECT_EQ(problems[0].key, "colour");
    EXPECT_EQ(problems[1].line, 4);
    EXPECT_NE(problems[1].reason.find("no such step"), std::string::npos);
    EXPECT_EQ(problems[2].line, 7);
    EXPECT_NE(problems[2].reason.find("its questions: q1, q2, q3"), std::string::npos);
    EXPECT_EQ(problems[3].message(), "sub.toml:8: answers.a.q1 = 3: must be a quoted text");
    EXPECT_EQ(problems[4].line, 11);
    EXPECT_NE(problems[4].reason.find("did you mean 'filter.q11'"), std::string::npos);
    // Once the keys are right, the values are checked as a run would check them.
    const auto range = submission_problems_of(
        "lesson = \"legofeup\"\nstudents = \"A\"\n[tuning.filter]\nq11 = -1.0\n");
    ASSERT_EQ(range.size(), 1u) << testing::all_messages(range);
    EXPECT_EQ(range[0].line, 4);
    EXPECT_EQ(range[0].key, "filter.q11");
}

TEST(Submission, AnotherLessonOrMissingNamesAreProblems) {
    const auto other = submission_problems_of("lesson = \"kalman-101\"\nstudents = \"A\"\n");
    ASSERT_EQ(other.size(), 1u);
    EXPECT_EQ(other[0].message(),
              "sub.toml:1: lesson = \"kalman-101\": this submission is for another lesson "
              "(expected \"legofeup\")");
    const auto nobody = submission_problems_of("lesson = \"legofeup\"\n");
    ASSERT_EQ(nobody.size(), 1u);
    EXPECT_EQ(nobody[0].key, "students");
    const auto syntax = submission_problems_of("lesson = \"legofeup\"\nstudents = \n");
    ASSERT_EQ(syntax.size(), 1u);
    EXPECT_EQ(syntax[0].line, 2);
}

TEST(Submission, ALessonWithoutGradingTakesNoTuning) {
    const Lesson lesson = parse_lesson(R"(id = "plain"
title = "t"
goals = "g"
[[step]]
id = "a"
title = "t"
instructions = "i"
observe = "o"
expectation = "e"
[[step.question]]
id = "q1"
text = "?"
)",
                                       "plain.toml");
    const std::string answers = "lesson = \"plain\"\nstudents = \"A\"\n[answers.a]\nq1 = \"!\"\n";
    EXPECT_EQ(parse_submission(answers, "s.toml", lesson).answers.at("a").at("q1"), "!");
    try {
        parse_submission(answers + "[tuning.filter]\nq11 = 1e-6\n", "s.toml", lesson);
        FAIL() << "a tuning for a lesson without grading was accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(error.problems().at(0).line, 5);
        EXPECT_NE(error.problems().at(0).reason.find("grades no step"), std::string::npos);
    }
}

TEST(Submission, LoadsFromAFile) {
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / "legofeup_test_submission.toml";
    std::ofstream(path) << kGood;
    EXPECT_EQ(load_submission_file(path, legofeup_lesson()).students, "Ana Silva, Rui Costa");
    std::filesystem::remove(path);
    try {
        load_submission_file(path, legofeup_lesson());
        FAIL() << "a missing file was accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(error.problems().at(0).source, path.string());
    }
}

}  // namespace
}  // namespace legofeup::lessons
