#include "legofeup/lessons/lockstep_run.hpp"

#include <utility>

#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

/// The in-process simulator's truth is always the truth of the frame just taken.
class SimulatorTruth final : public TruthSource {
  public:
    explicit SimulatorTruth(const sim::Simulator& simulator) : simulator_(simulator) {}
    std::optional<GroundTruth> truth_at(double /*time*/) override {
        return simulator_.ground_truth();
    }

  private:
    const sim::Simulator& simulator_;
};

}  // namespace

RunResult run_lockstep(const ResolvedRun& run, RunObserver* observer,
                       const ProgressCallback& progress) {
    sim::WorldSpec world = run.world;
    world.start = run.true_start;  // the simulator puts the robot at its world's start
    sim::Simulator simulator(std::move(world), run.robot, run.config.simulator, run.config.seed);
    sim::LockstepLink link(simulator);
    SimulatorTruth truth(simulator);
    return run_with_link(run, link, truth, observer, progress);
}

}  // namespace legofeup::lessons
