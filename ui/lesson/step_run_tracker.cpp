#include "legofeup/ui/lesson/step_run_tracker.hpp"

#include "legofeup/ui/lesson/step_membership.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

StepRunTracker::StepRunTracker(Session& session, QObject* parent)
    : QObject(parent), session_(session) {
    connect(&session_, &Session::phaseChanged, this, &StepRunTracker::phaseChanged);
    connect(&session_, &Session::samplesAppended, this, &StepRunTracker::samplesAppended);
}

void StepRunTracker::setStep(std::shared_ptr<const lessons::Lesson> lesson,
                             const std::string& step_id) {
    if (lesson != lesson_) {
        running_.clear();  // a run of the old lesson's step belongs to nothing now
    }
    lesson_ = std::move(lesson);
    selected_ = step_id;
}

const lessons::LessonStep* StepRunTracker::selectedStep() const {
    return lesson_ == nullptr ? nullptr : lesson_->find_step(selected_);
}

void StepRunTracker::abandonRun() {
    if (!running_.empty()) {
        emit stepAbandoned(QString::fromStdString(running_));
        running_.clear();
    }
}

void StepRunTracker::samplesAppended(int first, int count) {
    if (running_.empty()) {
        return;
    }
    // The latest batch: the history keeps its samples whole.
    const RunHistory& history = session_.history();
    for (int i = first; i < first + count; ++i) {
        if (const RunSample* sample = history.sample(static_cast<std::size_t>(i))) {
            shown_.add(*sample);
        }
    }
}

void StepRunTracker::phaseChanged(RunPhase phase) {
    switch (phase) {
        case RunPhase::Connecting:
            abandonRun();  // a new run replaces one that had not finished
            // The session has just restarted its history: the run's steps come from here on.
            shown_ = ShownRun();
            if (const lessons::LessonStep* step = selectedStep();
                step != nullptr && is_step_configuration(session_.config(), *step)) {
                running_ = selected_;
                emit stepStarted(QString::fromStdString(running_));
            }
            return;
        case RunPhase::Running:
        case RunPhase::Paused:
            return;
        case RunPhase::Finished:
            // The session appends a run's last steps before it reports the phase they led to.
            if (const lessons::LessonStep* step =
                    lesson_ == nullptr ? nullptr : lesson_->find_step(running_)) {
                if (!is_step_configuration(session_.config(), *step)) {
                    abandonRun();  // changed while running into another experiment
                    return;
                }
                running_.clear();
                emit outcomeReady(
                    shown_.outcome(*step, session_.config(), session_.resolved().world));
            }
            return;
        case RunPhase::Idle:
        case RunPhase::Stopped:
        case RunPhase::Failed:
            abandonRun();
            return;
    }
}

}  // namespace legofeup::ui
