#include "legofeup/lessons/analysis/batch_run.hpp"

#include <algorithm>
#include <charconv>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

/// A finished run waiting for its turn to be consumed.
struct Finished {
    RunResult result;
    std::unique_ptr<RunObserver> observer;
};

/// What the workers and the calling thread share. Workers take the next index, run it and
/// leave the result in `finished`; the calling thread consumes `finished` in index order.
/// A worker does not start run k before run k − window has been consumed, so at most
/// `window` results (and their observers' data) are held at once however slow one run is.
class Batch {
  public:
    Batch(const std::vector<ResolvedRun>& runs, std::size_t window, const ObserverFactory& make)
        : runs_(runs), window_(window), make_(make) {}

    void work() {
        for (;;) {
            std::size_t index = 0;
            {
                std::unique_lock lock(mutex_);
                worker_wakeup_.wait(lock, [&] {
                    return stopping_ || next_ >= runs_.size() || next_ < consumed_ + window_;
                });
                if (stopping_ || next_ >= runs_.size()) {
                    return;
                }
                index = next_++;
            }
            try {
                std::unique_ptr<RunObserver> observer = make_ ? make_(index) : nullptr;
                RunResult result = run_lockstep(runs_[index], observer.get());
                const std::lock_guard lock(mutex_);
                finished_.emplace(index, Finished{std::move(result), std::move(observer)});
                ++finished_count_;
            } catch (...) {
                const std::lock_guard lock(mutex_);
                // The lowest failing index wins, so the error reported does not depend on timing.
                if (!failure_ || index < failure_index_) {
                    failure_ = std::current_exception();
                    failure_index_ = index;
                }
                stopping_ = true;
                worker_wakeup_.notify_all();
            }
            consumer_wakeup_.notify_one();
        }
    }

    /// On the calling thread: hands results to `consume` in index order until all are done
    /// or something failed. Returns normally in both cases; rethrow() reports a failure.
    void consume_in_order(const OrderedConsumer& consume, const BatchProgress& progress) {
        std::size_t reported = 0;
        for (;;) {
            std::map<std::size_t, Finished> ready;  // the next indices in a row
            std::size_t finished = 0;
            {
                std::unique_lock lock(mutex_);
                consumer_wakeup_.wait(lock, [&] {
                    return stopping_ || finished_count_ > reported || finished_.count(consumed_) > 0
                           || consumed_ == runs_.size();
                });
                if (stopping_ || consumed_ == runs_.size()) {
                    return;
                }
                for (;;) {
                    auto next = finished_.extract(consumed_ + ready.size());
                    if (next.empty()) {
                        break;
                    }
                    ready.insert(std::move(next));
                }
                finished = finished_count_;
            }
            if (finished > reported) {
                reported = finished;
                if (progress) {
                    progress(finished, runs_.size());
                }
            }
            for (auto& [index, run] : ready) {
                if (consume) {
                    consume(index, run.result, std::move(run.observer));
                }
            }
            if (!ready.empty()) {
                const std::lock_guard lock(mutex_);
                consumed_ += ready.size();
                worker_wakeup_.notify_all();
            }
        }
    }

    /// Stops the workers after their current run (a failure in the consumer).
    void stop() {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        worker_wakeup_.notify_all();
    }

    void rethrow_failure() const {
        if (failure_) {
            std::rethrow_exception(failure_);
        }
    }

  private:
    const std::vector<ResolvedRun>& runs_;
    const std::size_t window_;
    const ObserverFactory& make_;

    std::mutex mutex_;
    std::condition_variable worker_wakeup_;
    std::condition_variable consumer_wakeup_;
    std::size_t next_ = 0;      ///< the next index a worker takes
    std::size_t consumed_ = 0;  ///< indices below this have been consumed
    std::size_t finished_count_ = 0;
    std::map<std::size_t, Finished> finished_;  ///< finished, not yet consumed
    bool stopping_ = false;
    std::exception_ptr failure_;
    std::size_t failure_index_ = 0;
};

}  // namespace

int available_jobs() {
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void run_batch(const std::vector<ResolvedRun>& runs, int jobs, const ObserverFactory& observers,
               const OrderedConsumer& consume, const BatchProgress& progress) {
    if (runs.empty()) {
        return;
    }
    const auto threads =
        std::min(static_cast<std::size_t>(jobs > 0 ? jobs : available_jobs()), runs.size());
    Batch batch(runs, 2 * threads + 2, observers);
    std::vector<std::jthread> workers;
    workers.reserve(threads);
    for (std::size_t k = 0; k < threads; ++k) {
        workers.emplace_back([&batch] { batch.work(); });
    }
    std::exception_ptr consumer_failure;
    try {
        batch.consume_in_order(consume, progress);
    } catch (...) {
        consumer_failure = std::current_exception();
        batch.stop();
    }
    workers.clear();  // joins
    if (consumer_failure) {
        std::rethrow_exception(consumer_failure);
    }
    batch.rethrow_failure();
}

std::vector<RunResult> run_batch(const std::vector<ResolvedRun>& runs, int jobs,
                                 const BatchProgress& progress) {
    std::vector<RunResult> results;
    results.reserve(runs.size());
    run_batch(
        runs, jobs, {},
        [&](std::size_t /*index*/, const RunResult& result, std::unique_ptr<RunObserver>) {
            results.push_back(result);
        },
        progress);
    return results;
}

Shard parse_shard(const std::string& text) {
    const auto fail = [&](const std::string& reason) {
        return InputError({{"", 0, "--shard", text, reason}});
    };
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) {
        throw fail("expected i/n, e.g. 2/4 for the second of four shards");
    }
    const auto number = [&](std::string_view part) {
        int value = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || error != std::errc() || end != part.data() + part.size()) {
            throw fail("expected i/n with whole numbers, e.g. 2/4");
        }
        return value;
    };
    const std::string_view all(text);
    Shard shard{number(all.substr(0, slash)), number(all.substr(slash + 1))};
    if (shard.count < 1) {
        throw fail("the number of shards n must be at least 1");
    }
    if (shard.index < 1 || shard.index > shard.count) {
        throw fail("the shard i must be between 1 and n = " + std::to_string(shard.count));
    }
    return shard;
}

}  // namespace legofeup::lessons::analysis
