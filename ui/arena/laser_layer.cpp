#include "legofeup/ui/arena/laser_layer.hpp"

#include <algorithm>
#include <vector>

#include "arena_drawing.hpp"
#include "arena_text.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::to_point;

/// The scan's points in the world, the scanner at `scanner_pose` (world frame).
QPolygonF world_points(const LaserScan& scan, const ScanGeometry& geometry,
                       const Pose2& scanner_pose) {
    thread_local std::vector<Vector2> points;
    scan_to_points(scan, geometry, scanner_pose, points);
    QPolygonF polygon;
    polygon.reserve(static_cast<qsizetype>(points.size()));
    for (const Vector2& p : points) {
        polygon.append(to_point(p));
    }
    return polygon;
}

}  // namespace

const RunSample* latest_scan_sample(const RunHistory& history, std::size_t look_back) {
    // Within the recent steps, whose samples the history keeps whole.
    const std::size_t size = history.size();
    const std::size_t stop = size > look_back ? size - look_back : 0;
    for (std::size_t i = size; i > stop; --i) {
        const RunSample* sample = history.sample(i - 1);
        if (sample != nullptr && sample->snapshot.laser.scan_received
            && !sample->snapshot.laser.wrong_beam_count) {
            return sample;
        }
    }
    return nullptr;
}

LaserScanPoints laser_scan_points(const RunSample& sample, const LaserScene& scene) {
    LaserScanPoints points;
    const LoopSnapshot& snapshot = sample.snapshot;
    if (!snapshot.laser.scan_received) {
        return points;
    }
    // Measured: where the filter believes the scanner is now, X̂ ⊕ mount.
    const Pose2 estimated_scanner = compose(to_pose(snapshot.estimate), scene.mount);
    points.measured = world_points(snapshot.frame.laser, scene.geometry, estimated_scanner);
    // Expected: cast from the predicted scanner pose (before this scan's update).
    points.expected =
        world_points(snapshot.laser.expected, scene.geometry, snapshot.laser.scanner_pose);
    if (sample.truth) {
        const Pose2 true_scanner = compose(sample.truth->pose, scene.true_mount);
        points.measured_at_truth =
            world_points(snapshot.frame.laser, scene.true_geometry, true_scanner);
    }
    points.matched = snapshot.laser.matched;
    return points;
}

QString laser_status_text(const LoopSnapshot& snapshot, const LaserScene& scene) {
    const LaserUpdate& update = snapshot.laser;
    if (!update.scan_received) {
        return {};
    }
    if (update.wrong_beam_count) {
        return arena_text::tr("scan skipped: %1 beams expected").arg(scene.geometry.beam_count);
    }
    if (snapshot.particles.count > 0) {
        return update.matched ? arena_text::tr("scan weighed · N_eff %L1 of %L2")
                                    .arg(snapshot.particles.effective, 0, 'f', 0)
                                    .arg(snapshot.particles.count)
                              : arena_text::tr("scan not weighed (refused)");
    }
    if (update.recovery_active) {
        return arena_text::tr("recovery: P×%1 · mismatch ×%2")
            .arg(scene.recovery_covariance_factor, 0, 'g', 3)
            .arg(update.consecutive_mismatches);
    }
    if (update.matched) {
        return arena_text::tr("ICP matched %1 pts").arg(update.icp.matched_points);
    }
    return update.icp.converged
               ? arena_text::tr("mismatch ×%1 · %2 pts")
                     .arg(update.consecutive_mismatches)
                     .arg(update.icp.matched_points)
               : arena_text::tr("mismatch ×%1 · not converged").arg(update.consecutive_mismatches);
}

LaserScanPoints latest_laser_scan_points(const RunHistory& history) {
    const ArenaScene& scene = history.scene();
    if (!scene.laser.active) {
        return {};
    }
    const RunSample* sample = latest_scan_sample(history);
    return sample != nullptr ? laser_scan_points(*sample, scene.laser) : LaserScanPoints{};
}

QString latest_laser_status_text(const RunHistory& history) {
    const ArenaScene& scene = history.scene();
    if (!scene.laser.active) {
        return {};
    }
    const RunSample* sample = latest_scan_sample(history);
    return sample != nullptr ? laser_status_text(sample->snapshot, scene.laser) : QString();
}

}  // namespace legofeup::ui
