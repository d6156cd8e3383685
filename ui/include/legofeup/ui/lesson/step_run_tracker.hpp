#pragma once
// Which lesson step a live run belongs to, and what the step gave once the run finished.
//
// A run belongs to the step selected when it started, if its configuration is that step's
// (step_membership.hpp: the step's preset, tuned; not another lesson's experiment). Its steps
// are taken into a ShownRun as the session appends them to its history, so the step is judged
// on the run the window showed — tuned half-way, paused, driven by keyboard for a while, or on
// an NXT (where the checks that need the true pose are not judged: shown_run.hpp). When its
// routine finishes (all laps driven) with the configuration still the step's, the outcome —
// metrics, automatic checks, plots — comes from those steps at once. A run stopped, failed or
// reset before its end does not count, nor does a run of a configuration that is no step's.
//
// The lockstep re-run of a configuration (report::run_step) is what `legofeup-cli report`
// shows and `legofeup-cli grade` repeats on unseen seeds; the panel no longer uses it.

#include <QObject>
#include <QString>
#include <memory>
#include <string>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/lesson/shown_run.hpp"
#include "legofeup/ui/session/live_run.hpp"

namespace legofeup::ui {

class Session;

class StepRunTracker : public QObject {
    Q_OBJECT

  public:
    explicit StepRunTracker(Session& session, QObject* parent = nullptr);

    /// The lesson and its step the next run belongs to. A new lesson forgets the run going.
    void setStep(std::shared_ptr<const lessons::Lesson> lesson, const std::string& step_id);
    /// The step whose live run is going; empty if none.
    const std::string& runningStep() const { return running_; }

  signals:
    void stepStarted(const QString& step_id);
    /// The run ended before its routine did (stopped, failed, reset, replaced).
    void stepAbandoned(const QString& step_id);
    /// The routine finished: the outcome of the run shown.
    void outcomeReady(const legofeup::report::StepOutcome& outcome);

  private:
    /// The step the next run belongs to if its configuration is the step's; nullptr if none.
    const lessons::LessonStep* selectedStep() const;
    void phaseChanged(RunPhase phase);
    void samplesAppended(int first, int count);
    void abandonRun();

    Session& session_;
    std::shared_ptr<const lessons::Lesson> lesson_;
    std::string selected_;
    std::string running_;
    ShownRun shown_;
};

}  // namespace legofeup::ui
