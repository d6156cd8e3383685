#pragma once
// Re-filtering: the recorded raw readings of a run replayed through a fresh loop with other
// settings (Q, R, gate, P0, …) — "what if" on identical noise and identical motion.
//
// The replay is open loop: the robot's motion is what it was, so the recorded frames (and
// the recorded wheel commands) stand; the new loop's controller runs, but its commands are
// ignored, since they could not have changed the recorded readings. Hence a new tuning
// shows how the estimate would have differed, not how the robot would have driven.

#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/run_metrics.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// Feeds every record of `log` into `loop` exactly as the recording loop got it: a frame
/// with LegoFeupLoop::step, a missing frame with step_without_frame at its due time (the
/// first frame only sets the encoder reference, as in the run). `on_step` sees each record
/// with the loop's snapshot after it.
void replay_run_log(const RunLog& log, LegoFeupLoop& loop,
                    const std::function<void(const RunLogRecord&, const LoopSnapshot&)>& on_step);

/// One step of a re-filtered run.
struct RefilterStep {
    double time = 0.0;
    bool frame_missing = false;
    std::optional<Pose2> truth;                      ///< none for a real robot
    StateVector old_estimate = StateVector::Zero();  ///< replay with the recorded configuration
    StateCovariance old_covariance = StateCovariance::Zero();
    StateVector new_estimate = StateVector::Zero();  ///< replay with the new configuration
    StateCovariance new_covariance = StateCovariance::Zero();
};

struct RefilterResult {
    std::vector<RefilterStep> steps;
    /// Metrics of each replay: the counts over every step, the errors and NEES
    /// (RunMetrics::truth) over the steps with a recorded truth — none for a real robot.
    RunMetrics old_metrics;
    RunMetrics new_metrics;
    /// Largest |difference| between the old replay and the estimates / covariances stored in
    /// the log: 0 when the replay reproduces the recorded run exactly (it should).
    double old_replay_deviation = 0.0;
    bool reproduces_recording() const { return old_replay_deviation == 0.0; }
};

/// Told how far a re-filtering is, `done` of `total` replayed steps (total is twice the
/// log's records: two replays), after every step; returning false stops it (RefilterCancelled).
/// The GUI runs refilter() on a worker with this as its progress bar and its cancel button.
using RefilterProgress = std::function<bool(std::size_t done, std::size_t total)>;

/// Thrown by refilter() when its RefilterProgress returned false.
class RefilterCancelled : public std::runtime_error {
  public:
    RefilterCancelled() : std::runtime_error("re-filtering cancelled") {}
};

/// Replays `log` through a loop built from its recorded configuration and through one built
/// from `new_config` (resolve(new_config).loop), open loop (see above). Throws InputError if
/// `new_config` does not resolve, RefilterCancelled if `progress` stopped it.
RefilterResult refilter(const RunLog& log, const RunConfig& new_config,
                        const RefilterProgress& progress = {});

}  // namespace legofeup::lessons
