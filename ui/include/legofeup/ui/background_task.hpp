#pragma once
// One piece of long work (reading a run log, re-filtering it) on a thread of its own, so that
// the GUI thread stays responsive. A value mailbox, as LiveRun's: the GUI thread polls
// `progress()` for its bar and takes the outcome once `finished()`; destroying the task
// cancels it (the work stops at its next progress report) and joins the thread.
//
// The work is a function of a TaskProgress: it reports its share done through it, and
// stops (throwing, e.g. lessons::RefilterCancelled) when the report answers false. Whatever
// it throws becomes the outcome's error message; whatever it returns, the outcome's result.
//
// Qt-free on purpose: dialogs poll it from a timer, tests drive it directly.

#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace legofeup::ui {

/// What the work sees of its task: where to report progress, and whether to go on.
class TaskProgress {
  public:
    /// Records `fraction` (0 … 1) done; returns false once the task is cancelled.
    bool report(double fraction) const {
        progress_.store(fraction, std::memory_order_relaxed);
        return !cancelled_.load(std::memory_order_relaxed);
    }
    bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }

  private:
    template <class Result>
    friend class BackgroundTask;
    TaskProgress(std::atomic<double>& progress, const std::atomic<bool>& cancelled)
        : progress_(progress), cancelled_(cancelled) {}
    std::atomic<double>& progress_;
    const std::atomic<bool>& cancelled_;
};

template <class Result>
class BackgroundTask {
  public:
    /// What a finished task gives: the result, or why there is none (what the work threw).
    struct Outcome {
        std::optional<Result> result;
        std::string error;
    };
    using Work = std::function<Result(const TaskProgress&)>;

    /// Starts `work` on a new thread at once.
    explicit BackgroundTask(Work work)
        : thread_([this, work = std::move(work)] {
              Outcome outcome;
              try {
                  outcome.result = work(TaskProgress(progress_, cancelled_));
              } catch (const std::exception& error) {
                  outcome.error = error.what();
              }
              {
                  const std::lock_guard lock(mutex_);
                  outcome_ = std::move(outcome);
              }
              finished_.store(true, std::memory_order_release);
          }) {}
    /// Cancels and joins.
    ~BackgroundTask() {
        cancel();
        thread_.join();
    }
    BackgroundTask(const BackgroundTask&) = delete;
    BackgroundTask& operator=(const BackgroundTask&) = delete;

    /// The share of the work done, 0 … 1, as it last reported.
    double progress() const { return progress_.load(std::memory_order_relaxed); }
    bool finished() const { return finished_.load(std::memory_order_acquire); }
    /// Asks the work to stop at its next progress report.
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    /// The outcome, once finished() (before, none); taken once.
    std::optional<Outcome> take() {
        if (!finished()) {
            return std::nullopt;
        }
        const std::lock_guard lock(mutex_);
        return std::exchange(outcome_, std::nullopt);
    }

  private:
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancelled_{false};
    std::atomic<bool> finished_{false};
    std::mutex mutex_;
    std::optional<Outcome> outcome_;
    std::thread thread_;  ///< last: it starts when everything it uses exists
};

}  // namespace legofeup::ui
