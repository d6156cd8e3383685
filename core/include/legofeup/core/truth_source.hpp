#pragma once
// Where the ground truth of a run comes from, for metrics and plots: the in-process
// simulator, or its truth stream over UDP. Never the filter's input (see robot_link.hpp).

#include <optional>

#include "legofeup/core/ground_truth.hpp"

namespace legofeup {

class TruthSource {
  public:
    virtual ~TruthSource() = default;
    /// The truth at `time` (or the newest before it); nullopt if none is known.
    virtual std::optional<GroundTruth> truth_at(double time) = 0;
};

}  // namespace legofeup
