#include "legofeup/ui/session/run_samples.hpp"

#include <variant>

#include "legofeup/core/consistency.hpp"

namespace legofeup::ui {

RunSample make_run_sample(const LoopSnapshot& snapshot, const std::optional<GroundTruth>& truth) {
    RunSample sample{snapshot, truth, std::numeric_limits<double>::quiet_NaN()};
    if (truth) {
        const StateVector true_state = to_state(truth->pose);
        sample.nees =
            normalized_estimation_error(true_state, snapshot.estimate, snapshot.covariance);
    }
    return sample;
}

ArenaScene scene_of(const lessons::ResolvedRun& run) {
    ArenaScene scene;
    scene.walls = run.world.walls;
    if (const auto* path = std::get_if<FollowPath>(&run.loop.controller)) {
        scene.path = path->segments();
    }
    scene.ir_mount = run.loop.ir_mount;
    scene.ir_max_range = run.loop.ir_curve.max_range;
    scene.control_period = run.config.simulator.control_period;
    // The beacons only where the filter uses them: the standard arena has them too, and
    // the wall lesson keeps the paper's look.
    if (run.loop.lesson.localisation == Localisation::Beacons) {
        scene.beacons = run.world.beacons;
    }
    return scene;
}

}  // namespace legofeup::ui
