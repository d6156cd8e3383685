// Where students stand in a lesson (Qt-free): step states, answers, and what they hand in —
// the submission (read back by the lessons library's own parser) and the report's steps.

#include <gtest/gtest.h>

#include "legofeup/lessons/submission.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

report::StepOutcome ran(const std::string& step_id, int passed, int failed) {
    report::StepOutcome outcome;
    outcome.step_id = step_id;
    outcome.ran = true;
    for (int i = 0; i < passed + failed; ++i) {
        lessons::CheckResult check;
        check.passed = i < passed;
        outcome.checks.push_back(check);
    }
    return outcome;
}

}  // namespace

TEST(LessonProgress, AStepIsRunningThenDoneAndAnAbandonedRunKeepsTheEarlierOutcome) {
    LessonProgress progress(lessons::legofeup_lesson());
    EXPECT_EQ(progress.state("a"), StepState::NotRun);
    EXPECT_FALSE(progress.revealed("a"));
    progress.markRunning("a");
    progress.markAbandoned("a");  // stopped before the routine's end: not run
    EXPECT_EQ(progress.state("a"), StepState::NotRun);
    EXPECT_FALSE(progress.revealed("a"));

    progress.markRunning("a");
    EXPECT_EQ(progress.state("a"), StepState::Running);
    progress.setOutcome(ran("a", 1, 1));
    EXPECT_EQ(progress.state("a"), StepState::Done);
    EXPECT_TRUE(progress.revealed("a"));
    EXPECT_EQ(progress.checksPassed("a"), std::make_pair(1, 2));

    progress.markRunning("a");  // a second run, stopped: the first one's outcome stays
    EXPECT_TRUE(progress.revealed("a"));
    progress.markAbandoned("a");
    EXPECT_EQ(progress.state("a"), StepState::Done);
    EXPECT_EQ(progress.checksPassed("b"), std::make_pair(0, 0));
}

TEST(LessonProgress, AnswersToQuestionsTheLessonDoesNotHaveAreNotTaken) {
    LessonProgress progress(lessons::legofeup_lesson());
    progress.takeAnswers("Ana, Rui",
                         {{"a", {{"q1", "It grows."}, {"q99", "lost"}}}, {"zz", {{"q1", "lost"}}}});
    EXPECT_EQ(progress.students(), "Ana, Rui");
    EXPECT_EQ(progress.answer("a", "q1"), "It grows.");
    EXPECT_EQ(progress.answers().size(), 1U);
    EXPECT_EQ(progress.answers().at("a").size(), 1U);
    progress.setAnswer("a", "q1", "");  // emptied: gone, not kept as ""
    EXPECT_TRUE(progress.answers().empty());
}

TEST(LessonProgress, TheSubmissionCarriesTheAnswersAndOnlyTheTunedSettingsOfTheGradedStep) {
    const lessons::Lesson& lesson = lessons::legofeup_lesson();
    ASSERT_TRUE(lesson.grading.has_value());
    const lessons::LessonStep& graded = *lesson.find_step(lesson.grading->step);
    LessonProgress progress(lesson);
    progress.setStudents("Ana Silva, Rui Costa");
    progress.setAnswer("a", "q1", "It grows \"without\" bound.\nAlways.");

    // Untouched: nothing tuned.
    EXPECT_TRUE(progress.submission(graded.config).tuning_toml.empty());

    lessons::RunConfig current = graded.config;
    current.filter.q11 = 3e-7;         // tunable ("filter")
    current.physical.ir_noise = 0.05;  // not tunable: stays the preset's
    const lessons::Submission submission = progress.submission(current);
    EXPECT_EQ(submission.tuned.filter.q11, 3e-7);
    EXPECT_EQ(submission.tuned.physical.ir_noise, graded.config.physical.ir_noise);

    // What the GUI saves, the lessons library reads back to the same answers and tuning.
    const lessons::Submission read =
        lessons::parse_submission(lessons::submission_to_toml(submission), "saved.toml", lesson);
    EXPECT_EQ(read.students, "Ana Silva, Rui Costa");
    EXPECT_EQ(read.answers.at("a").at("q1"), "It grows \"without\" bound.\nAlways.");
    EXPECT_EQ(read.tuned.filter.q11, 3e-7);
    EXPECT_EQ(read.tuned.filter.r11, graded.config.filter.r11);
    EXPECT_EQ(read.tuned.physical.ir_noise, graded.config.physical.ir_noise);
}

TEST(LessonProgress, TheReportListsEveryStepInOrderWithItsOutcomeAndAnswers) {
    const lessons::Lesson& lesson = lessons::legofeup_lesson();
    LessonProgress progress(lesson);
    progress.setStudents("Ana");
    progress.setOutcome(ran("c", 2, 1));
    progress.setAnswer("c", "q2", "It jumps.");
    progress.setAnswer("e", "q1", "Not run yet, but answered.");

    const report::StudentReport report = progress.report("2024-05-01 10:00");
    EXPECT_EQ(report.students, "Ana");
    EXPECT_EQ(report.created, "2024-05-01 10:00");
    EXPECT_EQ(report.lesson.id, lesson.id);
    ASSERT_EQ(report.steps.size(), lesson.steps.size());
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const report::StepOutcome& step = report.steps[i];
        EXPECT_EQ(step.step_id, lesson.steps[i].id);
        EXPECT_EQ(step.ran, step.step_id == "c") << step.step_id;
    }
    EXPECT_EQ(report.steps[2].checks.size(), 3U);
    EXPECT_EQ(report.steps[2].answers.at("q2"), "It jumps.");
    EXPECT_EQ(report.steps[4].answers.at("q1"), "Not run yet, but answered.");
    EXPECT_TRUE(report.steps[0].answers.empty());
}
