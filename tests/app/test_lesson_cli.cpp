// legofeup-cli lesson check and lesson show, as a teacher runs them.
#include <gtest/gtest.h>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;

using legofeup::testing::Result;

constexpr const char* kLesson = R"(id = "demo"
title = "A demo lesson"
goals = "Learn something."

[[step]]
id = "one"
title = "First step"
instructions = "Drive the square."
observe = "The ellipse."
expectation = "THE HIDDEN CONCLUSION"
[[step.question]]
id = "q1"
text = "Why does it grow?"
[[step.check]]
expression = "final_position_error_m > 0.2"
description = "Lost."
)";

class LessonCli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }
};

TEST_F(LessonCli, CheckAcceptsTheBuiltInLessonAndCountsItsStepsAndChecks) {
    const std::string file = LEGOFEUP_SOURCE_DIR "/resources/lessons/legofeup.toml";
    const Result result = run("lesson check " + file);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.out, file + ": ok — 8 steps, 23 checks\n");
    EXPECT_TRUE(result.err.empty()) << result.err;
}

TEST_F(LessonCli, CheckListsEveryProblemOfABrokenLessonWithItsLine) {
    std::string text = kLesson;
    text.replace(text.find("observe"), 7, "obsrve");                // line 9
    text.replace(text.find("> 0.2"), 5, "> far");                   // line 15
    text += "[grading]\nstep = \"two\"\ntunable = [\"filtre\"]\n";  // lines 17–19
    const fs::path file = write_file("broken.toml", text);
    const Result result = run("lesson check " + file.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_TRUE(result.out.empty()) << result.out;
    const std::string f = file.string();
    for (const std::string& line :
         {"error: " + f + ":5: step.observe: missing",
          "error: " + f + ":9: step.obsrve: unknown key (did you mean 'observe'?)",
          "error: " + f
              + ":15: step.check.expression = \"final_position_error_m > far\": 'far' "
                "after > is not a number",
          "error: " + f + ":18: grading.step = \"two\": no step with this id",
          "error: " + f
              + ":19: grading.tunable = \"filtre\": not a configuration section or key "
                "(did you mean 'filter'?)",
          f + ": 5 problems"}) {
        EXPECT_NE(result.err.find(line), std::string::npos) << line << "\n" << result.err;
    }
}

TEST_F(LessonCli, CheckRefusesAMissingFile) {
    const Result result = run("lesson check " + (dir_ / "none.toml").string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("cannot open the lesson file"), std::string::npos) << result.err;
}

TEST_F(LessonCli, ShowPrintsStepsAndQuestionsButNotTheConclusions) {
    const Result builtin = run("lesson show");
    EXPECT_EQ(builtin.exit_code, 0) << builtin.err;
    for (const char* text : {"EKF localisation of a LEGO robot", "Step a: Odometry only",
                             "Step f: Tuned filter", "Questions for the report"}) {
        EXPECT_NE(builtin.out.find(text), std::string::npos) << text;
    }
    EXPECT_EQ(builtin.out.find("The covariance grows without bound"), std::string::npos);

    const Result file = run("lesson show --lesson " + write_file("demo.toml", kLesson).string());
    EXPECT_EQ(file.exit_code, 0) << file.err;
    EXPECT_NE(file.out.find("Step one: First step"), std::string::npos) << file.out;
    EXPECT_NE(file.out.find("Drive the square."), std::string::npos);
    EXPECT_NE(file.out.find("q1. Why does it grow?"), std::string::npos);
    EXPECT_EQ(file.out.find("HIDDEN"), std::string::npos);

    const Result unknown = run("lesson show --lesson nonsense");
    EXPECT_EQ(unknown.exit_code, 1);
    EXPECT_NE(unknown.err.find("no such lesson file"), std::string::npos) << unknown.err;
}

}  // namespace
