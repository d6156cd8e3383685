#pragma once
// The observation side of the laser lesson (paper 001 §III-A.2, III-B, III-C, IV-B): one
// measured scan in, at most one pose update of the filter out.
//
//   1. scanner pose Ŝ = X̂ ⊕ M (M: the scanner's mount on the robot)
//   2. ray-cast the expected scan m̂ at Ŝ in the map (Fig. 2), same geometry as the scanner
//   3. both scans → points in the scanner's own frame (the measured ones in the true
//      scanner frame S, the expected ones in Ŝ)
//   4. ICP moves the measured points (source) onto the expected ones (reference):
//      p_Ŝ = T·p_S for the same world point, so S = Ŝ ⊕ T, i.e. T = Ŝ⁻¹ ⊕ S
//   5. matching (§III-B): not converged, or fewer than min_matched_points pairs ⇒ mismatch,
//      prediction only
//   6. otherwise the observed robot pose Z = S ⊕ M⁻¹ = X̂ ⊕ M ⊕ T ⊕ M⁻¹ updates the filter
//      with H = I, R = diag(r_x, r_y, r_θ) (eq. 14–18, LaserPoseMeasurement)
//   7. kidnapping (§IV-B): after recovery_after_mismatches consecutive mismatched scans,
//      P ← factor·P once, and the ICP's correspondence distance is multiplied by
//      recovery_correspondence_factor (stricter) until the next match
//
// Mismatches count scans, not frames. A scan whose beam count differs from the configured
// geometry is skipped and counted apart. The ICP object and the point buffers are kept
// between scans with their capacity, so a scan allocates nothing but the kd-tree rebuild.

#include <cstdint>
#include <memory>
#include <vector>

#include "legofeup/core/icp_2d.hpp"
#include "legofeup/core/laser_scan.hpp"
#include "legofeup/core/lesson_filters_config.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/occupancy_grid.hpp"
#include "legofeup/core/pose_estimator.hpp"

namespace legofeup {

class LaserLocaliser {
  public:
    LaserLocaliser();

    /// New tuning and map (shared, read-only). The mismatch streak and totals are kept.
    void configure(const LaserTuning& tuning, std::shared_ptr<const OccupancyGrid> map);
    /// Forgets the mismatch streak, the recovery and the totals.
    void reset();

    /// Steps 1–7 for one scan against `filter`'s current (predicted) estimate; `report`
    /// receives everything, including the persistent state (describe()).
    void process(PoseEstimator& filter, const LaserScan& scan, LaserUpdate& report);

    /// Writes the state that outlives a scan (streak, recovery, totals) and, as the
    /// correspondence distance, the one the next scan will use.
    void describe(LaserUpdate& report) const;

    /// The ICP correspondence distance the next scan uses, m.
    double correspondence_distance() const;
    int consecutive_mismatches() const { return consecutive_mismatches_; }
    bool recovery_active() const { return recovery_active_; }

  private:
    /// Step 7: one more mismatched scan; inflates P once per streak.
    void count_mismatch(PoseEstimator& filter, LaserUpdate& report);

    LaserTuning tuning_;
    std::shared_ptr<const OccupancyGrid> map_;
    Icp2d icp_;
    std::vector<Vector2> measured_points_;  // source, scanner frame
    std::vector<Vector2> expected_points_;  // reference, predicted scanner frame
    int consecutive_mismatches_ = 0;
    bool recovery_active_ = false;
    std::uint32_t total_scans_ = 0;
    std::uint32_t total_matches_ = 0;
    std::uint32_t total_recoveries_ = 0;
    std::uint32_t total_skipped_ = 0;
};

}  // namespace legofeup
