#include "legofeup/ui/refilter/refilter_job.hpp"

#include <exception>
#include <utility>

namespace legofeup::ui {

RefilterJob::RefilterJob(std::shared_ptr<const lessons::RunLog> log, lessons::RunConfig new_config)
    : thread_([this, log = std::move(log), config = std::move(new_config)] {
          Outcome outcome;
          try {
              outcome.result =
                  lessons::refilter(*log, config, [this](std::size_t done, std::size_t total) {
                      progress_.store(static_cast<double>(done) / static_cast<double>(total),
                                      std::memory_order_relaxed);
                      return !cancelled_.load(std::memory_order_relaxed);
                  });
          } catch (const std::exception& error) {  // InputError, RefilterCancelled
              outcome.error = error.what();
          }
          {
              const std::lock_guard lock(mutex_);
              outcome_ = std::move(outcome);
          }
          finished_.store(true, std::memory_order_release);
      }) {}

RefilterJob::~RefilterJob() {
    cancel();
    thread_.join();
}

std::optional<RefilterJob::Outcome> RefilterJob::take() {
    if (!finished()) {
        return std::nullopt;
    }
    const std::lock_guard lock(mutex_);
    return std::exchange(outcome_, std::nullopt);
}

}  // namespace legofeup::ui
