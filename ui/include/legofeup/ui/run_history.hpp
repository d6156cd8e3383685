#pragma once
// What the views draw: every step of the current run, kept in full on the GUI thread.
//
// The session's worker thread produces RunSamples; the session moves them here in one batch
// per repaint (docs/gui.md) and tells the views which ones are new. Views read this history
// only on the GUI thread, so it needs no lock.

#include <cstdint>
#include <iterator>
#include <limits>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/follow_path.hpp"
#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/walls.hpp"

namespace legofeup::ui {

/// One control period of a run: what the loop computed and what really happened.
struct RunSample {
    LoopSnapshot snapshot;
    /// The simulator's truth at the step's time (none over a link without truth, e.g. NXT).
    std::optional<GroundTruth> truth;
    /// NEES x̃ᵀ P⁻¹ x̃ of the pose error x̃ = x̂ − x (pose_error.hpp); NaN without truth.
    double nees = std::numeric_limits<double>::quiet_NaN();
};

/// The laser lesson's (paper 001) scanner and thresholds, for the arena's scan layer and the
/// plots' reference lines.
struct LaserScene {
    bool active = false;                ///< the run localises with the laser (Localisation::Laser)
    ScanGeometry geometry;              ///< the beams as the filter believes them
    Pose2 mount;                        ///< the scanner on the robot as the filter believes it
    ScanGeometry true_geometry;         ///< the simulated scanner's beams
    Pose2 true_mount;                   ///< the simulated scanner on the robot
    int min_matched_points = 0;         ///< fewer matched points is a mismatch (§III-B)
    int recovery_after_mismatches = 0;  ///< consecutive mismatches before P is inflated
    bool kidnap_recovery = false;       ///< the recovery is on
    double recovery_covariance_factor = 1.0;  ///< P is multiplied by it
};

/// What stays fixed during a run: the world and the path drawn behind the robot.
struct ArenaScene {
    std::vector<Wall> walls;        ///< the walls of the world (and of the filter's map)
    std::vector<PathSegment> path;  ///< the intended path; empty when driving by hand
    IrMount ir_mount;               ///< where the IR sensors sit, to draw their rays
    double ir_max_range = 0.8;      ///< m: the trusted IR range
    AssociationParams association;  ///< the wall association's gate and its limits
    double control_period = 0.05;   ///< s
    /// The world's bearing-only beacons (paper 002) when the run localises with them.
    BeaconMap beacons;
    /// The world's occupancy-grid map (paper 001), drawn under everything; null: none.
    std::shared_ptr<const OccupancyGrid> map;
    /// The laser filter's map when it is not the world's (an outdated map); null otherwise.
    std::shared_ptr<const OccupancyGrid> filter_map;
    LaserScene laser;
};

class RunHistory {
  public:
    /// Starts a new run: drops every sample and bumps epoch().
    void restart(ArenaScene scene) {
        scene_ = std::move(scene);
        samples_.clear();
        ++epoch_;
    }
    /// Takes the scene of a run reconfigured while it goes (its thresholds may change);
    /// keeps the samples and the epoch.
    void update_scene(ArenaScene scene) { scene_ = std::move(scene); }
    void append(std::vector<RunSample>&& batch) {
        samples_.insert(samples_.end(), std::make_move_iterator(batch.begin()),
                        std::make_move_iterator(batch.end()));
    }

    const std::vector<RunSample>& samples() const { return samples_; }
    bool empty() const { return samples_.empty(); }
    const RunSample& latest() const { return samples_.back(); }
    const ArenaScene& scene() const { return scene_; }
    /// Changes whenever the history starts over, so views know to drop what they cached.
    std::uint64_t epoch() const { return epoch_; }

  private:
    ArenaScene scene_;
    std::vector<RunSample> samples_;
    std::uint64_t epoch_ = 0;
};

}  // namespace legofeup::ui
