#include "legofeup/ui/lesson/step_run_tracker.hpp"

#include <QtConcurrent/QtConcurrentRun>
#include <exception>

#include "legofeup/ui/lesson/step_membership.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {

StepRunTracker::StepRunTracker(Session& session, QObject* parent)
    : QObject(parent), session_(session) {
    connect(&session_, &Session::phaseChanged, this, &StepRunTracker::phaseChanged);
}

StepRunTracker::~StepRunTracker() {
    // The workers hold their own copies; this only joins them before the watchers go.
    for (auto* watcher : findChildren<QFutureWatcher<Computed>*>()) {
        watcher->disconnect(this);
        watcher->waitForFinished();
    }
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

void StepRunTracker::phaseChanged(RunPhase phase) {
    switch (phase) {
        case RunPhase::Connecting:
            abandonRun();  // a new run replaces one that had not finished
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
            if (const lessons::LessonStep* step =
                    lesson_ == nullptr ? nullptr : lesson_->find_step(running_)) {
                if (!is_step_configuration(session_.config(), *step)) {
                    abandonRun();  // changed while running into another experiment
                    return;
                }
                running_.clear();
                check(*step);
            }
            return;
        case RunPhase::Idle:
        case RunPhase::Stopped:
        case RunPhase::Failed:
            abandonRun();
            return;
    }
}

void StepRunTracker::check(const lessons::LessonStep& step) {
    emit stepChecking(QString::fromStdString(step.id));
    ++checking_;
    auto* watcher = new QFutureWatcher<Computed>(this);
    connect(watcher, &QFutureWatcher<Computed>::finished, this, [this, watcher] {
        --checking_;
        computed(watcher->result());
        watcher->deleteLater();
    });
    // Copies only: the worker never touches what the GUI thread may change meanwhile.
    watcher->setFuture(
        QtConcurrent::run([lesson = lesson_, step, config = session_.config()]() -> Computed {
            Computed result{lesson, {}, {}};
            try {
                result.outcome = report::run_step(step, config);
            } catch (const std::exception& error) {
                result.error = QString::fromUtf8(error.what());
            }
            result.outcome.step_id = step.id;
            return result;
        }));
}

void StepRunTracker::computed(const Computed& result) {
    if (result.lesson != lesson_) {
        return;  // the lesson changed meanwhile: the outcome belongs to no step shown
    }
    const QString step_id = QString::fromStdString(result.outcome.step_id);
    if (!result.error.isEmpty()) {
        emit outcomeFailed(step_id, result.error);
        return;
    }
    emit outcomeReady(result.outcome);
}

}  // namespace legofeup::ui
