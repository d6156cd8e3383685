#pragma once
// One re-filtering (lessons::refilter) on a thread of its own, so that the Re-filter dialog
// stays responsive while a long log is replayed (a laser log runs one ICP per scan, twice:
// seconds, not milliseconds). A value mailbox, as LiveRun's: the GUI thread polls
// `progress()` for its bar and takes the outcome once `finished()`; destroying the job
// cancels it (the replay stops at its next step) and joins the thread.
//
// Qt-free on purpose: the dialog polls it from a timer, tests drive it directly.

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::ui {

class RefilterJob {
  public:
    /// What a finished job gives: the result, or why there is none (the reader's or
    /// resolve()'s message; "re-filtering cancelled" after cancel()).
    struct Outcome {
        std::optional<lessons::RefilterResult> result;
        std::string error;
    };

    /// Starts replaying `log` (shared, not copied: a log can be large) with `new_config`.
    RefilterJob(std::shared_ptr<const lessons::RunLog> log, lessons::RunConfig new_config);
    /// Cancels and joins.
    ~RefilterJob();
    RefilterJob(const RefilterJob&) = delete;
    RefilterJob& operator=(const RefilterJob&) = delete;

    /// The share of the replay done, 0 … 1.
    double progress() const { return progress_.load(std::memory_order_relaxed); }
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    /// Asks the replay to stop at its next step; it finishes with an error.
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    /// The outcome, once finished() (before, none); taken once.
    std::optional<Outcome> take();

  private:
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancelled_{false};
    std::atomic<bool> finished_{false};
    std::mutex mutex_;
    std::optional<Outcome> outcome_;
    std::thread thread_;  ///< last: it starts when everything it uses exists
};

}  // namespace legofeup::ui
