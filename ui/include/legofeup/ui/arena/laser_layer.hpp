#pragma once
// What the arena draws of the laser lesson (paper 001) at the latest scan, in world
// coordinates: the measured scan placed where the filter believes the scanner is
// (X̂ ⊕ mount, so a wrong estimate shows as a scan that does not lie on the map), the scan
// the filter expected there (ray-cast in its map at the predicted scanner pose, Fig. 2), and
// the measured scan at the true scanner pose (it lies on the map's walls up to the noise).

#include <QPolygonF>
#include <QString>
#include <cstddef>

#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

struct LaserScanPoints {
    QPolygonF measured;           ///< at the estimate ⊕ the filter's mount
    QPolygonF expected;           ///< ray-cast at LaserUpdate::scanner_pose
    QPolygonF measured_at_truth;  ///< at the truth ⊕ the simulated mount; empty without truth
    bool matched = false;         ///< the ICP match was used (§III-B)
};

/// The latest sample whose frame carried a scan the filter processed, among the last
/// `look_back` samples (a scan comes every other control period); nullptr when none.
const RunSample* latest_scan_sample(const RunHistory& history, std::size_t look_back = 20);

/// The scan of `sample` (one with LaserUpdate::scan_received) as world points.
LaserScanPoints laser_scan_points(const RunSample& sample, const LaserScene& scene);

/// The scan update's state in a few words: "ICP matched 512 pts", "mismatch ×37 · 41 pts",
/// "recovery: P×10 · mismatch ×104"; for the particle filter, which weighs the scan's end
/// points instead of matching them (no ICP), "scan weighed · N_eff 6,320 of 10,000"; empty
/// when the snapshot has no scan.
QString laser_status_text(const LoopSnapshot& snapshot, const LaserScene& scene);

/// The latest scan of `history` as the arena draws it; empty outside the laser lesson or
/// before its first scan.
LaserScanPoints latest_laser_scan_points(const RunHistory& history);
/// That scan's status (laser_status_text); empty outside the laser lesson or before its
/// first scan.
QString latest_laser_status_text(const RunHistory& history);

}  // namespace legofeup::ui
