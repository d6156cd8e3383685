#pragma once
// Which lesson step a live run belongs to, and what the step gave once the run finished.
//
// A run belongs to the step selected when it started, if its configuration is that step's
// (step_membership.hpp: the step's preset, tuned; not another lesson's experiment). When its
// routine finishes (all laps driven) with the configuration still the step's, the step's
// outcome — metrics, automatic checks, plots — comes from report::run_step with the
// configuration as run (the preset as the students tuned it, with its seed): a deterministic
// lockstep re-run, headless, so the lesson panel and the report show the numbers
// `legofeup-cli report` would. It runs on a worker thread (QtConcurrent): a fraction of a
// second, but never on the GUI thread. A run stopped, failed or reset before its end does
// not count, nor does a run of a configuration that is no step's.

#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <memory>
#include <string>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/session/live_run.hpp"

namespace legofeup::ui {

class Session;

class StepRunTracker : public QObject {
    Q_OBJECT

  public:
    explicit StepRunTracker(Session& session, QObject* parent = nullptr);
    ~StepRunTracker() override;

    /// The lesson and its step the next run belongs to. A new lesson forgets the run going
    /// (and an outcome being computed for the old one).
    void setStep(std::shared_ptr<const lessons::Lesson> lesson, const std::string& step_id);
    /// The step the next run belongs to if its configuration is the step's; nullptr if none.
    const lessons::LessonStep* selectedStep() const;
    /// The step whose live run is going; empty if none.
    const std::string& runningStep() const { return running_; }
    /// How many outcomes are being computed.
    int checking() const { return checking_; }

  signals:
    void stepStarted(const QString& step_id);
    /// The run ended before its routine did (stopped, failed, reset, replaced).
    void stepAbandoned(const QString& step_id);
    /// The routine finished; the outcome is being computed.
    void stepChecking(const QString& step_id);
    void outcomeReady(const legofeup::report::StepOutcome& outcome);
    /// The outcome could not be computed (the configuration as run does not resolve, …).
    void outcomeFailed(const QString& step_id, const QString& reason);

  private:
    struct Computed {
        std::shared_ptr<const lessons::Lesson> lesson;
        report::StepOutcome outcome;
        QString error;
    };

    void phaseChanged(RunPhase phase);
    void abandonRun();
    void check(const lessons::LessonStep& step);
    void computed(const Computed& result);

    Session& session_;
    std::shared_ptr<const lessons::Lesson> lesson_;
    std::string selected_;
    std::string running_;
    int checking_ = 0;
};

}  // namespace legofeup::ui
