#include "legofeup/ui/lesson/lesson_progress.hpp"

#include <algorithm>
#include <utility>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/ui/lesson/shown_run.hpp"

namespace legofeup::ui {

LessonProgress::LessonProgress(lessons::Lesson lesson)
    : lesson_(std::make_shared<const lessons::Lesson>(std::move(lesson))) {}

StepState LessonProgress::state(const std::string& step_id) const {
    const auto found = steps_.find(step_id);
    return found == steps_.end() ? StepState::NotRun : found->second.state;
}

const report::StepOutcome* LessonProgress::outcome(const std::string& step_id) const {
    const auto found = steps_.find(step_id);
    return found == steps_.end() || !found->second.outcome ? nullptr : &*found->second.outcome;
}

std::pair<int, int> LessonProgress::checksPassed(const std::string& step_id) const {
    const report::StepOutcome* ran = outcome(step_id);
    if (ran == nullptr) {
        return {0, 0};
    }
    const auto passed =
        std::count_if(ran->checks.begin(), ran->checks.end(),
                      [](const lessons::CheckResult& check) { return check.passed; });
    const int judged = static_cast<int>(ran->checks.size()) - checksNotJudged(step_id);
    return {static_cast<int>(passed), judged};
}

int LessonProgress::checksNotJudged(const std::string& step_id) const {
    const report::StepOutcome* ran = outcome(step_id);
    if (ran == nullptr) {
        return 0;
    }
    return static_cast<int>(std::count_if(
        ran->checks.begin(), ran->checks.end(),
        [&](const lessons::CheckResult& check) { return truth_missing(check, ran->metrics); }));
}

void LessonProgress::markRunning(const std::string& step_id) {
    steps_[step_id].state = StepState::Running;
}

void LessonProgress::markAbandoned(const std::string& step_id) {
    StepProgress& step = steps_[step_id];
    step.state = step.outcome ? StepState::Done : StepState::NotRun;
}

void LessonProgress::setOutcome(report::StepOutcome outcome) {
    StepProgress& step = steps_[outcome.step_id];
    step.state = StepState::Done;
    step.outcome = std::move(outcome);
}

std::string LessonProgress::answer(const std::string& step_id,
                                   const std::string& question_id) const {
    const auto step = answers_.find(step_id);
    if (step == answers_.end()) {
        return {};
    }
    const auto found = step->second.find(question_id);
    return found == step->second.end() ? std::string() : found->second;
}

void LessonProgress::setAnswer(const std::string& step_id, const std::string& question_id,
                               std::string text) {
    if (text.empty()) {
        const auto step = answers_.find(step_id);
        if (step != answers_.end()) {
            step->second.erase(question_id);
            if (step->second.empty()) {
                answers_.erase(step);
            }
        }
        return;
    }
    answers_[step_id][question_id] = std::move(text);
}

void LessonProgress::takeAnswers(const std::string& students, const Answers& answers) {
    students_ = students;
    answers_.clear();
    for (const lessons::LessonStep& step : lesson_->steps) {
        const auto given = answers.find(step.id);
        if (given == answers.end()) {
            continue;
        }
        for (const lessons::LessonQuestion& question : step.questions) {
            const auto text = given->second.find(question.id);
            if (text != given->second.end()) {
                setAnswer(step.id, question.id, text->second);
            }
        }
    }
}

lessons::Submission LessonProgress::submission(const lessons::RunConfig& current) const {
    lessons::Submission submission;
    submission.lesson = lesson_->id;
    submission.students = students_;
    submission.answers = answers_;
    const lessons::LessonStep* graded =
        lesson_->grading ? lesson_->find_step(lesson_->grading->step) : nullptr;
    if (graded != nullptr) {
        // The tunable settings as the configuration panel has them, over the graded preset.
        submission.tuning_toml = lessons::tuning_to_toml(current, *lesson_);
        submission.tuned = graded->config;
        lessons::apply_config_toml(submission.tuning_toml, "the configuration panel",
                                   submission.tuned);
    }
    return submission;
}

report::StudentReport LessonProgress::report(const std::string& created) const {
    report::StudentReport report;
    report.lesson = *lesson_;
    report.students = students_;
    report.created = created;
    for (const lessons::LessonStep& step : lesson_->steps) {
        report::StepOutcome outcome;
        if (const report::StepOutcome* ran = this->outcome(step.id)) {
            outcome = *ran;
        } else {
            outcome.step_id = step.id;
            outcome.ran = false;
        }
        const auto answers = answers_.find(step.id);
        outcome.answers =
            answers == answers_.end() ? std::map<std::string, std::string>() : answers->second;
        report.steps.push_back(std::move(outcome));
    }
    return report;
}

}  // namespace legofeup::ui
