#pragma once
// Runs the loop against any link — the in-process simulator, a simulator server over UDP,
// an NXT brick (comms::NxtLink) — until the routine is finished or the time limit. The loop sees
// frames only; ground truth comes from a separate source, for metrics and plots.
//
// Over a real link frames can be lost, duplicated or late. The link hands over each frame
// once, in order; for every control period without a frame this runner makes the loop
// predict without one (LegoFeupLoop::step_without_frame) and flags it in the snapshot.

#include <functional>
#include <optional>
#include <stdexcept>

#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/robot_link.hpp"
#include "legofeup/core/run_metrics.hpp"
#include "legofeup/core/truth_source.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// Sees every step of a run: what the loop computed and what really happened (a NaN pose,
/// see truth_known, for a step without a truth).
class RunObserver {
  public:
    virtual ~RunObserver() = default;
    virtual void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) = 0;
};

struct RunResult {
    RunMetrics metrics;
    bool routine_finished = false;     ///< false: stopped at the time limit
    double wall_seconds = 0.0;         ///< how long the run took on this machine
    std::uint64_t frames_missing = 0;  ///< control periods run without a frame
    /// Steps whose own truth was not known: it had not arrived (the last one stood in for
    /// the metrics, if there was one), or the link has none (a real robot: every step).
    std::uint64_t steps_without_truth = 0;
};

/// A truth whose pose is unknown (NaN): what observers see for a step without one.
GroundTruth unknown_truth(double time);

/// A real robot's truth: nobody knows its pose. Every step gets unknown_truth, so observers
/// still see every step (the trace leaves the truth cells empty) and the metrics count it
/// without scoring it (RunMetrics::truth stays empty).
class UnknownTruth final : public TruthSource {
  public:
    std::optional<GroundTruth> truth_at(double time) override;
};

/// Whether `truth` is a known pose (not UnknownTruth's NaN).
bool truth_known(const GroundTruth& truth);

/// Called now and then with how far the run has got (0 … 1: laps and sides driven for a
/// path, otherwise simulated time over the time limit) and the simulated time in seconds.
using ProgressCallback = std::function<void(double fraction, double simulated)>;

/// Thrown when the link delivers no frame for kMaxSilentPeriods control periods in a row.
class LinkSilent : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};
inline constexpr int kMaxSilentPeriods = 40;

/// Feeds a loop from a link, one frame at a time, keeping the books of control periods: a
/// period without a frame (a timeout, or a gap in the sequence) gets a predict-only step; a
/// frame that does not advance time (a paused simulator) gets none. run_with_link() drives a
/// whole run with it; the GUI drives an open-ended one, changing the loop between frames.
class LinkStepper {
  public:
    /// Called after every step; returning true ends the advance early (the run is over).
    using StepHandler = std::function<bool(const LoopSnapshot&)>;

    explicit LinkStepper(double control_period) : period_(control_period) {}

    /// Waits for the link's next frame and steps `loop` for it. Returns true if `on_step`
    /// asked to stop. Throws LinkSilent after kMaxSilentPeriods periods without a frame.
    bool advance(LegoFeupLoop& loop, RobotLink& link, const StepHandler& on_step);

    /// Whether the last advance() ran the loop at all (false while paused or before the
    /// first frame): only then is a wheel command due.
    bool stepped() const { return stepped_; }
    std::uint64_t frames_missing() const { return frames_missing_; }

  private:
    bool step_without_frame(LegoFeupLoop& loop, const StepHandler& on_step);

    double period_;
    bool have_frame_ = false;
    std::uint32_t last_sequence_ = 0;
    double last_time_ = 0.0;
    std::uint32_t stepped_without_frame_ = 0;  ///< since the last frame
    /// The last frame did not advance time: the source is paused, so a wait without a frame
    /// is not a missed period (a slow paused server would otherwise grow P while paused).
    bool time_stood_still_ = false;
    int silent_periods_ = 0;
    bool stepped_ = false;
    std::uint64_t frames_missing_ = 0;
};

/// Runs the loop of `run` over `link`. The first frame the link delivers starts the run (it
/// only sets the encoder reference); the link's control period must be the run's
/// (run.config.simulator.control_period). Throws LinkSilent if the frames stop.
RunResult run_with_link(const ResolvedRun& run, RobotLink& link, TruthSource& truth,
                        RunObserver* observer = nullptr, const ProgressCallback& progress = {});

}  // namespace legofeup::lessons
