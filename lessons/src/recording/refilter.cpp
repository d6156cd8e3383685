#include "legofeup/lessons/recording/refilter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace legofeup::lessons {
namespace {

/// Largest |a − b| over the estimate and the covariance; +∞ if either holds a NaN where the
/// other does not (a NaN never equals anything, so it must not hide a difference).
double deviation(const RunLogRecord& record, const LoopSnapshot& snapshot) {
    double largest = 0.0;
    const auto compare = [&](double recorded, double replayed) {
        if (std::isnan(recorded) || std::isnan(replayed)) {
            if (std::isnan(recorded) != std::isnan(replayed)) {
                largest = std::numeric_limits<double>::infinity();
            }
            return;
        }
        largest = std::max(largest, std::abs(recorded - replayed));
    };
    for (int i = 0; i < kStateSize; ++i) {
        compare(record.estimate(i), snapshot.estimate(i));
        for (int j = 0; j < kStateSize; ++j) {
            compare(record.covariance(i, j), snapshot.covariance(i, j));
        }
    }
    return largest;
}

}  // namespace

void replay_run_log(const RunLog& log, LegoFeupLoop& loop,
                    const std::function<void(const RunLogRecord&, const LoopSnapshot&)>& on_step) {
    // The recording loop's first step was its first frame, which only set the encoder
    // reference; steps without a frame were predictions at the due time. Feeding the same
    // calls in the same order to a fresh loop repeats the run bit for bit.
    for (const RunLogRecord& record : log.records) {
        const LoopSnapshot& snapshot = record.frame_missing
                                           ? loop.step_without_frame(record.frame.time)
                                           : loop.step(record.frame);
        on_step(record, snapshot);
    }
}

RefilterResult refilter(const RunLog& log, const RunConfig& new_config,
                        const RefilterProgress& progress) {
    LegoFeupLoop old_loop(resolve(log.config).loop);
    LegoFeupLoop new_loop(resolve(new_config).loop);

    RefilterResult result;
    result.steps.resize(log.records.size());
    // Every step is counted; those with a recorded truth are also scored against it.
    RunMetricsAccumulator old_metrics;
    RunMetricsAccumulator new_metrics;
    const auto add = [](RunMetricsAccumulator& metrics, const RunLogRecord& record,
                        const LoopSnapshot& snapshot) {
        if (record.truth) {
            metrics.add(snapshot, *record.truth);
        } else {
            metrics.add(snapshot);
        }
    };

    const std::size_t total = 2 * log.records.size();
    std::size_t done = 0;
    const auto count_step = [&] {
        if (progress && !progress(++done, total)) {
            throw RefilterCancelled();
        }
    };

    std::size_t index = 0;
    replay_run_log(log, old_loop, [&](const RunLogRecord& record, const LoopSnapshot& snapshot) {
        RefilterStep& step = result.steps[index++];
        step.time = snapshot.time;
        step.frame_missing = record.frame_missing;
        step.truth = record.truth;
        step.old_estimate = snapshot.estimate;
        step.old_covariance = snapshot.covariance;
        result.old_replay_deviation =
            std::max(result.old_replay_deviation, deviation(record, snapshot));
        add(old_metrics, record, snapshot);
        count_step();
    });
    index = 0;
    // Open loop: new_loop's controller computes a command at every step, but the robot
    // drove as recorded, so that command is never used.
    replay_run_log(log, new_loop, [&](const RunLogRecord& record, const LoopSnapshot& snapshot) {
        RefilterStep& step = result.steps[index++];
        step.new_estimate = snapshot.estimate;
        step.new_covariance = snapshot.covariance;
        add(new_metrics, record, snapshot);
        count_step();
    });
    result.old_metrics = old_metrics.result();
    result.new_metrics = new_metrics.result();
    return result;
}

}  // namespace legofeup::lessons
