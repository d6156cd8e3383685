#include "legofeup/lessons/link_run.hpp"

#include <chrono>

#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup::lessons {
namespace {

double progress_of(const ResolvedRun& run, const LoopSnapshot& snapshot) {
    const auto* path = std::get_if<FollowPath>(&run.loop.controller);
    if (path != nullptr && path->laps() > 0 && snapshot.controller.segment >= 0) {
        const double sides = static_cast<double>(path->segments().size());
        return (snapshot.controller.lap + snapshot.controller.segment / sides) / path->laps();
    }
    return snapshot.time / run.max_duration;
}

/// Keeps count of the control periods the loop has run and of those it ran without a frame,
/// so a frame whose sequence jumps (lost frames the link never timed out on) still gets one
/// predict-only step per missed period.
class PeriodBook {
  public:
    /// How many periods before `frame` went by with neither a frame nor a step without one.
    std::uint32_t unaccounted_before(const SensorFrame& frame) const {
        if (!have_frame_) {
            return 0;
        }
        const std::uint32_t gap = frame.sequence - last_sequence_ - 1;
        return gap > stepped_without_frame_ ? gap - stepped_without_frame_ : 0;
    }
    void took(const SensorFrame& frame) {
        have_frame_ = true;
        last_sequence_ = frame.sequence;
        last_time_ = frame.time;
        stepped_without_frame_ = 0;
    }
    void stepped_without_frame() { ++stepped_without_frame_; }
    /// A frame that does not advance time (a paused server) is not a new period.
    bool same_period(const SensorFrame& frame) const {
        return have_frame_ && frame.time <= last_time_;
    }
    double due_time(double period) const {
        return last_time_ + (stepped_without_frame_ + 1) * period;
    }
    bool started() const { return have_frame_; }

  private:
    bool have_frame_ = false;
    std::uint32_t last_sequence_ = 0;
    double last_time_ = 0.0;
    std::uint32_t stepped_without_frame_ = 0;
};

}  // namespace

RunResult run_with_link(const ResolvedRun& run, RobotLink& link, TruthSource& truth_source,
                        RunObserver* observer, const ProgressCallback& progress) {
    const auto started = std::chrono::steady_clock::now();
    const double period = run.config.simulator.control_period;
    LegoFeupLoop loop(run.loop);
    RunMetricsAccumulator metrics;
    RunResult result;
    std::optional<GroundTruth> last_truth;
    PeriodBook book;
    int silent_periods = 0;

    const auto record = [&](const LoopSnapshot& snapshot) {
        std::optional<GroundTruth> truth = truth_source.truth_at(snapshot.time);
        if (truth) {
            last_truth = truth;
        } else {
            ++result.steps_without_truth;
        }
        if (last_truth) {
            metrics.add(snapshot, last_truth->pose);
            if (observer != nullptr) {
                observer->on_step(snapshot, *last_truth);
            }
        }
        result.routine_finished = snapshot.controller.finished;
        return result.routine_finished || snapshot.time >= run.max_duration;
    };

    for (std::uint64_t step = 0;; ++step) {
        const std::optional<SensorFrame> frame = link.next_frame();
        bool done = false;
        if (!frame) {
            if (++silent_periods >= kMaxSilentPeriods) {
                throw LinkSilent(book.started()
                                     ? "the link delivered no frame for "
                                           + std::to_string(kMaxSilentPeriods) + " control periods"
                                     : "the link delivered no first frame");
            }
            if (!book.started()) {
                continue;  // nothing to predict from yet
            }
            ++result.frames_missing;
            done = record(loop.step_without_frame(book.due_time(period)));
            book.stepped_without_frame();
        } else {
            silent_periods = 0;
            if (book.same_period(*frame)) {
                book.took(*frame);
                continue;  // paused: nothing happened, nothing to answer
            }
            for (std::uint32_t i = book.unaccounted_before(*frame); i > 0 && !done; --i) {
                ++result.frames_missing;
                done = record(loop.step_without_frame(book.due_time(period)));
                book.stepped_without_frame();
            }
            if (!done) {
                done = record(loop.step(*frame));
            }
            book.took(*frame);
        }
        if (done) {
            break;
        }
        link.send_command(loop.snapshot().wheels);
        if (progress && step % 200 == 0) {
            progress(progress_of(run, loop.snapshot()), loop.snapshot().time);
        }
    }
    result.metrics = metrics.result();
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace legofeup::lessons
