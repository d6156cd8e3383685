#include "legofeup/ui/lesson/shown_run.hpp"

#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::ui {
namespace {

/// The sample's truth if it is known, else the CLI's unknown truth (NaN pose).
GroundTruth truth_of(const RunSample& sample) {
    if (sample.truth && lessons::truth_known(*sample.truth)) {
        return *sample.truth;
    }
    return lessons::unknown_truth(sample.snapshot.time);
}

}  // namespace

void ShownRun::add(const RunSample& sample) {
    const auto now = std::chrono::steady_clock::now();
    if (steps_ == 0) {
        first_arrival_ = now;
    }
    last_arrival_ = now;
    // As lessons::run_with_link feeds its accumulator: scored where the truth is known (a
    // truth that had not arrived yet stands in as the last one, as LiveRun passes it on).
    if (sample.truth && lessons::truth_known(*sample.truth)) {
        metrics_.add(sample.snapshot, *sample.truth);
    } else {
        metrics_.add(sample.snapshot);
        ++steps_without_truth_;
    }
    frames_missing_ += sample.snapshot.frame_missing ? 1 : 0;
    routine_finished_ = sample.snapshot.controller.finished;
    record(sample);
    ++steps_;
}

void ShownRun::record(const RunSample& sample) {
    if (steps_ % stride_ != 0) {
        unrecorded_last_ = sample;
        return;
    }
    unrecorded_last_.reset();
    recording_.on_step(sample.snapshot, truth_of(sample));
    // 2N + 1 steps 0, s, …, 2N·s become N + 1 steps 0, 2s, …, 2N·s: still evenly spaced, and
    // the next step plotted (2(N+1)·s) keeps the spacing.
    if (recording_.steps().size() > 2 * kShownRunPlotSteps) {
        recording_ = recording_.thinned(kShownRunPlotSteps + 1);
        stride_ *= 2;
    }
}

lessons::RunResult ShownRun::result() const {
    lessons::RunResult result;
    result.metrics = metrics_.result();
    result.routine_finished = routine_finished_;
    result.frames_missing = frames_missing_;
    result.steps_without_truth = steps_without_truth_;
    result.wall_seconds = std::chrono::duration<double>(last_arrival_ - first_arrival_).count();
    return result;
}

report::StepOutcome ShownRun::outcome(const lessons::LessonStep& step,
                                      const lessons::RunConfig& config,
                                      const sim::WorldSpec& world) const {
    report::StepOutcome outcome;
    outcome.step_id = step.id;
    outcome.ran = true;
    outcome.config = config;
    outcome.world = world;
    outcome.metrics = lessons::result_metrics_to_json(result());
    outcome.checks = lessons::evaluate_checks(step.checks, outcome.metrics);
    outcome.recording = recording_;
    if (unrecorded_last_) {
        outcome.recording.on_step(unrecorded_last_->snapshot, truth_of(*unrecorded_last_));
    }
    return outcome;
}

bool truth_missing(const lessons::CheckResult& result, const nlohmann::json& metrics) {
    // A truth metric is null, never absent, in a run without truth (metrics_to_json); the
    // bounds of a `within` check may need the truth too.
    const auto null_truth = [&](const std::string& name) {
        return !name.empty() && lessons::is_truth_metric(name) && metrics.is_object()
               && metrics.contains(name) && metrics[name].is_null();
    };
    return !result.passed
           && (null_truth(result.check.metric) || null_truth(result.check.bounds_metric));
}

}  // namespace legofeup::ui
