#pragma once
// Waiting on a LiveRun's worker in tests: for samples, and for the run's end.

#include <chrono>
#include <thread>
#include <vector>

#include "legofeup/ui/session/live_run.hpp"

namespace legofeup::ui::testing {

/// Collects samples until `done` holds for the collection (or 20 s of wall time pass).
template <class Done>
std::vector<RunSample> collect_until(LiveRun& live, std::vector<RunSample>& samples, Done done) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!done(samples) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        for (RunSample& sample : live.take_samples()) {
            samples.push_back(std::move(sample));
        }
    }
    return samples;
}

/// Waits (up to `limit`) for the run's phase to leave Connecting and Running.
inline LiveRunStatus wait_for_end(const LiveRun& live, std::chrono::seconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        const LiveRunStatus status = live.status();
        if (status.phase != RunPhase::Connecting && status.phase != RunPhase::Running) {
            return status;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return live.status();
}

}  // namespace legofeup::ui::testing
