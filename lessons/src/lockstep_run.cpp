#include "legofeup/lessons/lockstep_run.hpp"

#include <chrono>
#include <utility>

#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

double progress_of(const ResolvedRun& run, const LoopSnapshot& snapshot) {
    const auto* path = std::get_if<FollowPath>(&run.loop.controller);
    if (path != nullptr && path->laps() > 0 && snapshot.controller.segment >= 0) {
        const double sides = static_cast<double>(path->segments().size());
        return (snapshot.controller.lap + snapshot.controller.segment / sides) / path->laps();
    }
    return snapshot.time / run.max_duration;
}

}  // namespace

RunResult run_lockstep(const ResolvedRun& run, RunObserver* observer,
                       const ProgressCallback& progress) {
    const auto started = std::chrono::steady_clock::now();
    sim::WorldSpec world = run.world;
    world.start = run.true_start;  // the simulator puts the robot at its world's start
    sim::Simulator simulator(std::move(world), run.robot, run.config.simulator, run.config.seed);
    sim::LockstepLink link(simulator);
    LegoFeupLoop loop(run.loop);
    RunMetricsAccumulator metrics;
    RunResult result;

    for (std::uint64_t step = 0;; ++step) {
        const SensorFrame frame = *link.next_frame();  // the lockstep link always has one
        const LoopSnapshot& snapshot = loop.step(frame);
        const sim::GroundTruth truth = simulator.ground_truth();
        metrics.add(snapshot, truth.pose);
        if (observer != nullptr) {
            observer->on_step(snapshot, truth);
        }
        result.routine_finished = snapshot.controller.finished;
        if (result.routine_finished || frame.time >= run.max_duration) {
            break;
        }
        link.send_command(snapshot.wheels);
        if (progress && step % 200 == 0) {
            progress(progress_of(run, snapshot), frame.time);
        }
    }
    result.metrics = metrics.result();
    result.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return result;
}

}  // namespace legofeup::lessons
