#pragma once
// trace.csv: one row per control step. Angles in radians, SI units throughout; empty cells
// where a value does not exist (no update: no NIS). Columns are documented in
// docs/experiments.md and by trace_csv_header().

#include <ostream>

#include "legofeup/core/loop_config.hpp"
#include "legofeup/lessons/lockstep_run.hpp"

namespace legofeup::lessons {

const char* trace_csv_header();

class TraceCsvWriter final : public RunObserver {
  public:
    /// Writes the header at once. `loop` names the walls.
    TraceCsvWriter(std::ostream& out, const LoopConfig& loop);
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override;

  private:
    std::ostream& out_;
    const LoopConfig& loop_;
};

}  // namespace legofeup::lessons
