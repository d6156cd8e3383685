#include "legofeup/core/laser_localiser.hpp"

#include <utility>

#include "legofeup/core/laser_pose_measurement.hpp"

namespace legofeup {

LaserLocaliser::LaserLocaliser() {
    measured_points_.reserve(kMaxScanBeams);
    expected_points_.reserve(kMaxScanBeams);
    icp_.set_params(tuning_.icp);
}

void LaserLocaliser::configure(const LaserTuning& tuning,
                               std::shared_ptr<const OccupancyGrid> map) {
    tuning_ = tuning;
    map_ = std::move(map);
}

void LaserLocaliser::reset() {
    consecutive_mismatches_ = 0;
    recovery_active_ = false;
    total_scans_ = 0;
    total_matches_ = 0;
    total_recoveries_ = 0;
    total_skipped_ = 0;
}

double LaserLocaliser::correspondence_distance() const {
    const double normal = tuning_.icp.max_correspondence_distance;
    return recovery_active_ ? normal * tuning_.recovery_correspondence_factor : normal;
}

void LaserLocaliser::describe(LaserUpdate& report) const {
    report.consecutive_mismatches = consecutive_mismatches_;
    report.recovery_active = recovery_active_;
    report.correspondence_distance = correspondence_distance();
    report.total_scans = total_scans_;
    report.total_matches = total_matches_;
    report.total_recoveries = total_recoveries_;
    report.total_skipped = total_skipped_;
}

void LaserLocaliser::process(PoseEstimator& filter, const LaserScan& scan, LaserUpdate& report) {
    if (map_ == nullptr || map_->empty()) {
        describe(report);
        return;  // validation requires a map with this localisation; nothing to match against
    }
    report.scan_received = true;
    const ScanGeometry& geometry = tuning_.geometry;
    if (scan.beam_count != geometry.beam_count) {
        report.wrong_beam_count = true;
        ++total_skipped_;
        describe(report);
        return;
    }
    ++total_scans_;
    const double threshold = correspondence_distance();  // this scan's, before any change

    // 1–2. The expected scan at the predicted scanner pose Ŝ = X̂ ⊕ M.
    const Pose2 predicted = to_pose(filter.state());
    const Pose2 scanner = compose(predicted, tuning_.mount);
    report.scanner_pose = scanner;
    expected_scan(*map_, scanner, geometry, report.expected);

    // 3. Both clouds in their scanner's own frame (identity frame pose).
    scan_to_points(scan, geometry, Pose2{}, measured_points_);
    scan_to_points(report.expected, geometry, Pose2{}, expected_points_);
    report.measured_points = static_cast<int>(measured_points_.size());
    report.expected_points = static_cast<int>(expected_points_.size());

    // 4. T = Ŝ⁻¹ ⊕ S: the measured cloud moved onto the expected one.
    IcpParams params = tuning_.icp;
    params.max_correspondence_distance = threshold;
    icp_.set_params(params);
    icp_.set_reference(expected_points_);
    report.icp = icp_.align(measured_points_, Pose2{});

    // 5. Matching (§III-B).
    report.matched =
        report.icp.converged && report.icp.matched_points >= tuning_.min_matched_points;
    if (report.matched) {
        // 6. Z = Ŝ ⊕ T ⊕ M⁻¹, then the H = I update (eq. 14–18).
        report.observed_pose =
            compose(compose(scanner, report.icp.transform), inverse(tuning_.mount));
        const LaserPoseMeasurement measurement(
            report.observed_pose, StateVector(tuning_.r_x, tuning_.r_y, tuning_.r_theta));
        const auto update = filter.update(measurement);
        report.status = update.status;
        report.innovation = update.innovation;
        report.nis = update.nis;
        // A match the filter refused (non-finite) was not used: it counts as a mismatch.
        report.matched = update.status == StepStatus::Applied;
    }
    if (report.matched) {
        ++total_matches_;
        consecutive_mismatches_ = 0;
        recovery_active_ = false;  // back to the normal correspondence distance
    } else {
        count_mismatch(filter, report);
    }
    describe(report);
    report.correspondence_distance = threshold;
}

void LaserLocaliser::count_mismatch(PoseEstimator& filter, LaserUpdate& report) {
    ++consecutive_mismatches_;
    if (!tuning_.kidnap_recovery || recovery_active_
        || consecutive_mismatches_ < tuning_.recovery_after_mismatches) {
        return;
    }
    // §IV-B: let the filter "search" a larger area. reset() conditions the inflated P
    // (symmetric, within the covariance limits), so any factor keeps it finite and PD.
    const StateCovariance inflated = tuning_.recovery_covariance_factor * filter.covariance();
    filter.reset(filter.state(), inflated);
    recovery_active_ = true;
    report.recovery_triggered = true;
    ++total_recoveries_;
}

}  // namespace legofeup
