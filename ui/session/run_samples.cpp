#include "legofeup/ui/session/run_samples.hpp"

#include <memory>
#include <variant>

#include "legofeup/core/consistency.hpp"

namespace legofeup::ui {

namespace {

/// Whether two maps hold the same cells at the same place (a map loaded twice is one map).
bool same_map(const OccupancyGrid& a, const OccupancyGrid& b) {
    return a.width() == b.width() && a.height() == b.height() && a.resolution() == b.resolution()
           && a.origin().x == b.origin().x && a.origin().y == b.origin().y
           && a.origin().theta == b.origin().theta && a.cells() == b.cells();
}

}  // namespace

RunSample make_run_sample(const LoopSnapshot& snapshot, const std::optional<GroundTruth>& truth) {
    RunSample sample{snapshot, truth, std::numeric_limits<double>::quiet_NaN(), nullptr};
    if (truth) {
        const StateVector true_state = to_state(truth->pose);
        sample.nees =
            normalized_estimation_error(true_state, snapshot.estimate, snapshot.covariance);
    }
    return sample;
}

GroundTruth truth_or_unknown(const RunSample& sample) {
    if (sample.truth) {
        return *sample.truth;
    }
    return *lessons::UnknownTruth().truth_at(sample.snapshot.time);
}

ArenaScene scene_of(const lessons::ResolvedRun& run) {
    ArenaScene scene;
    scene.walls = run.world.walls;
    scene.loop = std::make_shared<const LoopConfig>(run.loop);
    if (const auto* path = std::get_if<FollowPath>(&run.loop.controller)) {
        scene.path = path->segments();
    }
    scene.ir_mount = run.loop.ir_mount;
    scene.ir_max_range = run.loop.ir_curve.max_range;
    scene.association = run.loop.association;
    scene.control_period = run.config.simulator.control_period;
    // The beacons only where the filter uses them: the standard arena has them too, and
    // the wall lesson keeps the paper's look.
    if (run.loop.lesson.localisation == Localisation::Beacons) {
        scene.beacons = run.world.beacons;
    }
    // The map students compare scans with is the one the robot was given (as surveyed), not
    // the world as built, which differs by centimetres that would not show.
    scene.map = run.world.surveyed_map ? run.world.surveyed_map : run.world.map;
    if (run.loop.lesson.localisation == Localisation::Laser) {
        const LaserTuning& laser = run.loop.lesson.laser;
        scene.laser.active = true;
        scene.laser.geometry = laser.geometry;
        scene.laser.mount = laser.mount;
        scene.laser.true_geometry = run.robot.laser_scanner.geometry;
        scene.laser.true_mount = run.robot.laser_scanner.mount;
        scene.laser.min_matched_points = laser.min_matched_points;
        scene.laser.recovery_after_mismatches = laser.recovery_after_mismatches;
        scene.laser.kidnap_recovery = laser.kidnap_recovery;
        scene.laser.recovery_covariance_factor = laser.recovery_covariance_factor;
        if (run.loop.map && run.loop.map != scene.map
            && (!scene.map || !same_map(*run.loop.map, *scene.map))) {
            scene.filter_map = run.loop.map;
        }
    }
    return scene;
}

}  // namespace legofeup::ui
