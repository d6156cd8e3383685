#include "legofeup/lessons/link_run.hpp"

#include <chrono>
#include <cmath>

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

}  // namespace

GroundTruth unknown_truth(double time) {
    GroundTruth truth;
    truth.time = time;
    truth.pose = {std::nan(""), std::nan(""), std::nan("")};
    return truth;
}

std::optional<GroundTruth> UnknownTruth::truth_at(double time) {
    return unknown_truth(time);
}

bool truth_known(const GroundTruth& truth) {
    return std::isfinite(truth.pose.x) && std::isfinite(truth.pose.y)
           && std::isfinite(truth.pose.theta);
}

bool LinkStepper::step_without_frame(LegoFeupLoop& loop, const StepHandler& on_step) {
    // Due one period after the last frame, or after the last step without one.
    const double due = last_time_ + (stepped_without_frame_ + 1) * period_;
    ++frames_missing_;
    ++stepped_without_frame_;
    stepped_ = true;
    return on_step(loop.step_without_frame(due));
}

bool LinkStepper::advance(LegoFeupLoop& loop, RobotLink& link, const StepHandler& on_step) {
    stepped_ = false;
    const std::optional<SensorFrame> frame = link.next_frame();
    if (!frame) {
        if (++silent_periods_ >= kMaxSilentPeriods) {
            throw LinkSilent(have_frame_
                                 ? "the link delivered no frame for "
                                       + std::to_string(kMaxSilentPeriods) + " control periods"
                                 : "the link delivered no first frame");
        }
        // Before the first frame there is nothing to predict from; while the source is
        // paused no period goes by.
        return have_frame_ && !time_stood_still_ && step_without_frame(loop, on_step);
    }
    silent_periods_ = 0;
    const bool paused = have_frame_ && frame->time <= last_time_;  // time stood still
    bool done = false;
    if (!paused) {
        // Periods the sequence skipped and no timeout accounted for: predict through them.
        const std::uint32_t gap = have_frame_ ? frame->sequence - last_sequence_ - 1 : 0;
        for (std::uint32_t i = gap > stepped_without_frame_ ? gap - stepped_without_frame_ : 0;
             i > 0 && !done; --i) {
            done = step_without_frame(loop, on_step);
        }
        if (!done) {
            stepped_ = true;
            done = on_step(loop.step(*frame));
        }
    }
    have_frame_ = true;
    time_stood_still_ = paused;
    last_sequence_ = frame->sequence;
    last_time_ = frame->time;
    stepped_without_frame_ = 0;
    return done;
}

RunResult run_with_link(const ResolvedRun& run, RobotLink& link, TruthSource& truth_source,
                        RunObserver* observer, const ProgressCallback& progress) {
    const auto started = std::chrono::steady_clock::now();
    LegoFeupLoop loop(run.loop);
    LinkStepper stepper(run.config.simulator.control_period);
    RunMetricsAccumulator metrics;
    RunResult result;
    std::optional<GroundTruth> last_truth;

    // Every step is counted and seen by the observer; only a step with a known truth is
    // scored against it. A truth that has not arrived yet (UDP) is stood in for by the last
    // one; before the first, and on a real robot, the step has none.
    const auto record = [&](const LoopSnapshot& snapshot) {
        const std::optional<GroundTruth> truth = truth_source.truth_at(snapshot.time);
        if (truth) {
            last_truth = truth;
        }
        if (!truth || !truth_known(*truth)) {
            ++result.steps_without_truth;
        }
        const GroundTruth seen = last_truth ? *last_truth : unknown_truth(snapshot.time);
        if (truth_known(seen)) {
            metrics.add(snapshot, seen);
        } else {
            metrics.add(snapshot);
        }
        if (observer != nullptr) {
            observer->on_step(snapshot, seen);
        }
        result.routine_finished = snapshot.controller.finished;
        return result.routine_finished || snapshot.time >= run.max_duration;
    };

    for (std::uint64_t advances = 0; !stepper.advance(loop, link, record); ++advances) {
        if (stepper.stepped()) {
            link.send_command(loop.snapshot().wheels);
        }
        if (progress && advances % 200 == 0) {
            progress(progress_of(run, loop.snapshot()), loop.snapshot().time);
        }
    }
    result.frames_missing = stepper.frames_missing();
    result.metrics = metrics.result();
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace legofeup::lessons
