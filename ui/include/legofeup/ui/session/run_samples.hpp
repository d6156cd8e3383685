#pragma once
// Turning a step of the loop (and the truth at its time) into what the views draw.

#include <optional>

#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// The sample of one step, with its NEES computed when the truth is known.
RunSample make_run_sample(const LoopSnapshot& snapshot, const std::optional<GroundTruth>& truth);

/// A sample's truth, or for a robot without one (a real NXT) the CLI's unknown truth: the
/// trace's truth and NEES cells stay empty.
GroundTruth truth_or_unknown(const RunSample& sample);

/// The walls, map, intended path, IR mounting and laser scanner of a run, for the views.
ArenaScene scene_of(const lessons::ResolvedRun& run);

/// Collects every step of a run as samples (tests, benchmarks and recorded runs).
class SampleCollector final : public lessons::RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        samples_.push_back(make_run_sample(snapshot, truth));
    }
    std::vector<RunSample> take() { return std::move(samples_); }

  private:
    std::vector<RunSample> samples_;
};

}  // namespace legofeup::ui
