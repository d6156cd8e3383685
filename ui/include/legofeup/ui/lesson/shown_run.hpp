#pragma once
// The run the window showed, as a lesson step's outcome: its metrics — the CLI's, from the
// same RunMetricsAccumulator and result_metrics_to_json — computed from the run's own steps
// as they arrived, and the step's checks evaluated on them.
//
// A run tuned half-way, paused, driven by keyboard for a while or run on an NXT is judged on
// what the students watched, not on a re-run of the configuration it ended with. The metrics
// are accumulated step by step (sums, never the steps themselves), so a long run costs no
// more memory than a short one; the plots for the report keep at most
// 2 · kShownRunPlotSteps + 1 of its steps, evenly spaced, and the last.
//
// Over a link without a ground truth (a real NXT) the steps are counted, not scored: the
// metrics that need the truth are null, and truth_missing() tells a check on one from a
// check that failed. Qt-free: the tracker feeds it, the tests check it directly.

#include <chrono>
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "legofeup/core/run_metrics.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/report/student_report.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// Steps of a shown run kept for the report's plots: up to twice this many (the report thins
/// them to this many).
inline constexpr std::size_t kShownRunPlotSteps = report::kReportPlotSteps;

class ShownRun {
  public:
    /// Adds the run's next step, in order. A sample without a known truth is counted only.
    void add(const RunSample& sample);

    std::uint64_t steps() const { return steps_; }
    /// The run as the CLI's runner reports one: metrics, routine finished (the last step's
    /// routine), frames missing, steps without a truth and the wall time from first to last.
    /// A step whose truth had not arrived yet carries the last one (LiveRun stands it in, as
    /// run_with_link does) and counts as with a truth here: the sample does not say which.
    lessons::RunResult result() const;
    /// `step`'s outcome on this run: summary.json's metrics, the checks evaluated on them, the
    /// plotted steps; `config` (the configuration the run ended with) and `world` are recorded
    /// with it for the report.
    report::StepOutcome outcome(const lessons::LessonStep& step, const lessons::RunConfig& config,
                                const sim::WorldSpec& world) const;

  private:
    void record(const RunSample& sample);

    RunMetricsAccumulator metrics_;
    std::uint64_t steps_ = 0;
    std::uint64_t frames_missing_ = 0;
    std::uint64_t steps_without_truth_ = 0;
    bool routine_finished_ = false;
    std::chrono::steady_clock::time_point first_arrival_;
    std::chrono::steady_clock::time_point last_arrival_;

    report::RunRecording recording_;
    std::uint64_t stride_ = 1;  ///< every stride-th step is plotted; doubles as the run grows
    std::optional<RunSample> unrecorded_last_;  ///< the latest step when the stride skipped it
};

/// Whether `result`'s check could not be judged because its metric needs the ground truth and
/// the run had none (`metrics`: the run's summary.json metrics, its truth metrics null).
bool truth_missing(const lessons::CheckResult& result, const nlohmann::json& metrics);

}  // namespace legofeup::ui
