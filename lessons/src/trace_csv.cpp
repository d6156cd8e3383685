#include "legofeup/lessons/trace_csv.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "legofeup/core/consistency.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();  // written as an empty cell

// Fixed, locale-independent formatting: the same run gives the same bytes. A non-finite
// value is an empty cell.
void cell(std::ostream& out, double value) {
    if (std::isfinite(value)) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", value);
        out << text;
    }
}

/// A cell and the comma after it.
void number(std::ostream& out, double value) {
    cell(out, value);
    out << ',';
}

/// `value` when `present`, else an empty cell.
void number_if(std::ostream& out, bool present, double value) {
    number(out, present ? value : kNone);
}

/// The further lessons' columns (after frame_missing): what the optional sensors read, the
/// speed estimates of paper 003, the comparison filter and the truths they are judged by.
/// Empty cells where the lesson has no such sensor or estimate.
void further_lesson_cells(std::ostream& out, const LoopSnapshot& s, const GroundTruth& truth) {
    out << to_string(s.localisation) << ',' << to_string(s.filter_kind) << ',';
    const bool scan = !s.frame_missing && s.frame.has_beacon_scan;
    if (scan) {
        int applied = 0;
        for (std::size_t k = 0; k < s.beacons.count && k < s.beacons.updates.size(); ++k) {
            applied += s.beacons.updates[k].status == StepStatus::Applied ? 1 : 0;
        }
        out << static_cast<int>(s.frame.beacons.count) << ',' << applied << ',';
    } else {
        out << ",,";
    }
    const ExtraReadings& r = s.readings;
    number_if(out, r.has_gyro, r.gyro_rate);
    number_if(out, r.has_gyro, r.gyro_heading);
    number_if(out, r.has_compass, r.compass_heading);
    number_if(out, r.has_accelerometers, r.accel_forward[kAccelRightWheel]);
    number_if(out, r.has_accelerometers, r.accel_forward[kAccelLeftWheel]);
    const SpeedEstimates& v = s.speeds;
    number_if(out, v.valid, v.wheel_kf[0]);
    number_if(out, v.valid, v.wheel_kf[1]);
    number_if(out, v.valid, v.wheel_differentiated[0]);
    number_if(out, v.valid, v.wheel_differentiated[1]);
    number_if(out, v.valid, v.body_encoders.v);
    number_if(out, v.valid, v.body_encoders.w);
    number_if(out, v.valid && v.body_kf_valid, v.body_kf.v);
    number_if(out, v.valid && v.body_kf_valid, v.body_kf.w);
    const bool fused = s.localisation == Localisation::GyroFusion;
    number_if(out, fused, s.fused_velocity.v);
    number_if(out, fused, s.fused_velocity.w);
    const ShadowEstimate& shadow = s.shadow;
    out << (shadow.active ? to_string(shadow.kind) : "") << ',';
    for (const double value : {shadow.estimate(kX), shadow.estimate(kY), shadow.estimate(kTheta),
                               shadow.covariance(kX, kX), shadow.covariance(kY, kY),
                               shadow.covariance(kTheta, kTheta)}) {
        number_if(out, shadow.active, value);
    }
    number(out, truth.velocity.v);
    number(out, truth.velocity.w);
    number(out, truth.wheel_surface_speeds.right);
    // (The gyro bias and magnetic disturbance of the truth are not written: the UDP truth
    // stream does not carry them, and a trace must not depend on the link it came over.)
    number(out, truth.wheel_surface_speeds.left);
}

/// The laser lesson's columns (paper 001): whether a scan came, what the ICP match did, the
/// mismatch count and recovery, and the observation with its innovation. Empty cells unless
/// the localisation is laser; the match's cells empty without a scan, the observation's
/// unless the match was used.
void laser_cells(std::ostream& out, const LoopSnapshot& s) {
    const LaserUpdate& laser = s.laser;
    const bool active = s.localisation == Localisation::Laser && !s.frame_missing;
    const bool scan = active && laser.scan_received;
    const auto flag = [&out](bool present, bool value) {
        out << (present ? (value ? "1" : "0") : "") << ',';
    };
    flag(active, laser.scan_received);
    flag(scan, laser.matched);
    out << (scan ? to_string(laser.status) : "") << ',';
    number_if(out, scan, laser.icp.matched_points);
    number_if(out, scan, laser.icp.iterations);
    flag(scan, laser.icp.converged);
    number_if(out, scan, laser.icp.rms_residual);
    number_if(out, active, laser.consecutive_mismatches);
    flag(active, laser.recovery_triggered);
    const bool used = scan && laser.matched;
    for (int i = 0; i < 3; ++i) {
        number_if(out, used, laser.innovation(i));
    }
    number_if(out, used, laser.observed_pose.x);
    number_if(out, used, laser.observed_pose.y);
    number_if(out, used, laser.observed_pose.theta);
    number(out, used && laser.status == StepStatus::Applied ? laser.nis : kNone);
}

/// The wall association's gate and the candidate wall's d² = νᵀS⁻¹ν with the χ²(2) threshold
/// (computed under either gate); empty without a candidate wall.
void association_gate_cells(std::ostream& out, const LoopSnapshot& s) {
    const AssociationResult& a = s.association;
    const bool candidate = a.wall >= 0;
    out << (candidate ? to_string(a.gate) : "") << ',';
    number_if(out, candidate, a.mahalanobis_d2);
    number_if(out, candidate, a.mahalanobis_threshold);
}

/// The particle filter's cloud (particle_summary.hpp): its count, N_eff, the share of the
/// weight within 0.5 m of the mean, whether the step resampled and how many particles the
/// recovery injected. Empty cells with the other filters. The last cells of a row.
void particle_cells(std::ostream& out, const LoopSnapshot& s) {
    const ParticleSummary& p = s.particles;
    const bool cloud = p.count > 0;
    number_if(out, cloud, p.count);
    number_if(out, cloud, p.effective);
    number_if(out, cloud, p.near_mean_share);
    number_if(out, cloud, p.resampled ? 1.0 : 0.0);
    cell(out, cloud ? p.injected : kNone);
    out << '\n';
}

}  // namespace

const char* trace_csv_header() {
    return "t,x_true,y_true,th_true,x_est,y_est,th_est,pxx,pxy,pxt,pyy,pyt,ptt,"
           "x_odo,y_odo,th_odo,ds1,ds2,v1,v2,wall,nis,nees,"
           "adc1,adc2,association,update,touching_wall,frame_missing,"
           // The further lessons (docs/experiments.md, "trace.csv columns").
           "localisation,filter,beacon_sightings,beacon_updates,"
           "gyro_rate,gyro_heading,compass_heading,accel_right,accel_left,"
           "wheel_kf_right,wheel_kf_left,wheel_diff_right,wheel_diff_left,v_enc,w_enc,v_kf,w_kf,"
           "v_fused,w_fused,shadow_filter,shadow_x,shadow_y,shadow_theta,shadow_pxx,shadow_pyy,"
           "shadow_ptt,v_true,w_true,wheel_right_true,wheel_left_true,"
           // The laser lesson (paper 001).
           "laser_scan,laser_matched,laser_update,laser_matched_points,laser_icp_iterations,"
           "laser_icp_converged,laser_icp_rms,laser_mismatches,laser_recovery,"
           "laser_innovation_x,laser_innovation_y,laser_innovation_theta,"
           "laser_observed_x,laser_observed_y,laser_observed_theta,laser_nis,"
           // The loop's own checks of its inputs.
           "odometry_glitch,prediction,"
           // The wall association's gate (docs/loop.md, "Wall association").
           "association_gate,association_d2,association_d2_threshold,"
           // The particle filter (docs/particle_filter.md).
           "pf_particles,pf_neff,pf_near_mean,pf_resampled,pf_injected";
}

TraceCsvWriter::TraceCsvWriter(std::ostream& out, const LoopConfig& loop) : out_(out), loop_(loop) {
    out_ << trace_csv_header() << '\n';
}

void TraceCsvWriter::on_step(const LoopSnapshot& s, const GroundTruth& truth) {
    number(out_, s.time);
    number(out_, truth.pose.x);
    number(out_, truth.pose.y);
    number(out_, truth.pose.theta);
    number(out_, s.estimate(kX));
    number(out_, s.estimate(kY));
    number(out_, s.estimate(kTheta));
    const StateCovariance& P = s.covariance;
    for (const auto& [row, column] :
         {std::pair{kX, kX}, std::pair{kX, kY}, std::pair{kX, kTheta}, std::pair{kY, kY},
          std::pair{kY, kTheta}, std::pair{kTheta, kTheta}}) {
        number(out_, P(row, column));
    }
    number(out_, s.odometry_pose.x);
    number(out_, s.odometry_pose.y);
    number(out_, s.odometry_pose.theta);
    for (const IrSample& ir : s.ir) {
        number(out_, ir.reading.status == IrStatus::Unavailable ? kNone : ir.reading.distance);
    }
    number(out_, s.wheels.right);
    number(out_, s.wheels.left);
    if (s.association.associated()) {
        out_ << loop_.walls.wall(s.association.wall).name;
    }
    out_ << ',';
    number(out_, s.update.status == StepStatus::Applied ? s.update.nis : kNone);
    number(out_, normalized_estimation_error(to_state(truth.pose), s.estimate, s.covariance));
    out_ << s.ir[0].adc << ',' << s.ir[1].adc << ',' << to_string(s.association.outcome) << ','
         << to_string(s.update.status) << ',' << (truth.touching_wall ? 1 : 0) << ','
         << (s.frame_missing ? 1 : 0) << ',';
    further_lesson_cells(out_, s, truth);
    laser_cells(out_, s);
    out_ << (s.odometry_glitch ? 1 : 0) << ',';
    out_ << to_string(s.predict_status) << ',';
    association_gate_cells(out_, s);
    particle_cells(out_, s);  // the last cells, and the end of the row
}

}  // namespace legofeup::lessons
