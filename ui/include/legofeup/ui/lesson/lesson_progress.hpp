#pragma once
// Where a pair of students stands in a lesson: which steps they ran (and what each run gave),
// their names and their answers. It builds what they hand in — the submission (answers and the
// graded step's tuning) and the student report — from the same state the lesson panel shows.
// Qt-free: the panel shows it, the tests check it directly.

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/submission.hpp"
#include "legofeup/report/student_report.hpp"

namespace legofeup::ui {

enum class StepState : std::uint8_t {
    NotRun,   ///< no finished run yet
    Running,  ///< its run is going (a previous outcome, if any, is kept until it finishes)
    Done,     ///< ran: outcome() holds the metrics and checks
};

/// step id → question id → answer, as typed.
using Answers = std::map<std::string, std::map<std::string, std::string>>;

class LessonProgress {
  public:
    explicit LessonProgress(lessons::Lesson lesson);

    const lessons::Lesson& lesson() const { return *lesson_; }
    /// The lesson, shared with work that outlives a change of lesson (an outcome computed
    /// on a worker thread).
    std::shared_ptr<const lessons::Lesson> sharedLesson() const { return lesson_; }

    StepState state(const std::string& step_id) const;
    /// The latest finished run's outcome, or nullptr.
    const report::StepOutcome* outcome(const std::string& step_id) const;
    /// Whether the step's conclusion may be shown: once it has run.
    bool revealed(const std::string& step_id) const { return outcome(step_id) != nullptr; }
    /// Checks passed and checks judged in the latest outcome (0/0 before any): a check whose
    /// metric needs the true pose the run did not have (a real NXT) is not judged.
    std::pair<int, int> checksPassed(const std::string& step_id) const;
    /// Checks of the latest outcome that could not be judged for want of the true pose.
    int checksNotJudged(const std::string& step_id) const;

    void markRunning(const std::string& step_id);
    /// The run ended without finishing its routine (stopped, failed, reset): back to Done if
    /// an earlier run finished, else NotRun.
    void markAbandoned(const std::string& step_id);
    void setOutcome(report::StepOutcome outcome);

    const std::string& students() const { return students_; }
    void setStudents(std::string students) { students_ = std::move(students); }
    const Answers& answers() const { return answers_; }
    std::string answer(const std::string& step_id, const std::string& question_id) const;
    void setAnswer(const std::string& step_id, const std::string& question_id, std::string text);
    /// Takes the names and the answers of `submission` (to questions this lesson has).
    void takeAnswers(const std::string& students, const Answers& answers);

    /// The submission to save: names, the non-empty answers, and — if the lesson has a graded
    /// step — that step's preset with the tunable settings as `current` has them.
    lessons::Submission submission(const lessons::RunConfig& current) const;
    /// The report to export: every step in lesson order, the ones run with their outcome,
    /// each with its answers.
    report::StudentReport report(const std::string& created) const;

  private:
    struct StepProgress {
        StepState state = StepState::NotRun;
        std::optional<report::StepOutcome> outcome;
    };

    std::shared_ptr<const lessons::Lesson> lesson_;
    std::map<std::string, StepProgress> steps_;
    std::string students_;
    Answers answers_;
};

}  // namespace legofeup::ui
