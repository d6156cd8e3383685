// trace.csv's columns for the laser lesson (paper 001; docs/experiments.md): after every
// earlier column, whether a scan came, what the ICP match did, the mismatch count and the
// recovery, and the pose observation with its innovation — each from its LaserUpdate field,
// empty where it does not exist (another localisation, no scan, a match not used).

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "csv_test_support.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/lessons/trace_csv.hpp"

namespace legofeup::lessons {
namespace {

using csv_testing::cells_of;
using csv_testing::rows_of;

const std::vector<std::string> kLaserColumns = {
    "laser_scan",           "laser_matched",       "laser_update",         "laser_matched_points",
    "laser_icp_iterations", "laser_icp_converged", "laser_icp_rms",        "laser_mismatches",
    "laser_recovery",       "laser_innovation_x",  "laser_innovation_y",   "laser_innovation_theta",
    "laser_observed_x",     "laser_observed_y",    "laser_observed_theta", "laser_nis"};

// The columns after the laser lesson's: the loop's glitch flag and how it predicted, the
// association gate's, then the particle filter's.
const std::vector<std::string> kLastColumns = {"odometry_glitch",
                                               "prediction",
                                               "association_gate",
                                               "association_d2",
                                               "association_d2_threshold",
                                               "pf_particles",
                                               "pf_neff",
                                               "pf_near_mean",
                                               "pf_resampled",
                                               "pf_injected"};

TEST(TraceCsvLaser, TheLaserColumnsComeAfterTheFurtherLessonsAndBeforeTheLoopsOwn) {
    const std::vector<std::string> names = cells_of(trace_csv_header());
    const auto last = static_cast<std::ptrdiff_t>(kLastColumns.size());
    const auto laser_count = static_cast<std::ptrdiff_t>(kLaserColumns.size());
    ASSERT_GE(names.size(), kLaserColumns.size() + kLastColumns.size() + 1);
    EXPECT_EQ(std::vector<std::string>(names.end() - last, names.end()), kLastColumns);
    const std::vector<std::string> laser(names.end() - last - laser_count, names.end() - last);
    EXPECT_EQ(laser, kLaserColumns);
    EXPECT_EQ(*(names.end() - last - laser_count - 1), "wheel_left_true");
}

LoopSnapshot laser_step(std::uint64_t step) {
    LoopSnapshot s;
    s.step = step;
    s.time = 0.05 * static_cast<double>(step);
    s.localisation = Localisation::Laser;
    return s;
}

TEST(TraceCsvLaser, EachColumnCarriesItsLaserUpdateField) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);

    // A match used: every cell.
    LoopSnapshot used = laser_step(1);
    used.frame.has_laser_scan = true;
    used.laser.scan_received = true;
    used.laser.matched = true;
    used.laser.status = StepStatus::Applied;
    used.laser.icp.matched_points = 512;
    used.laser.icp.iterations = 7;
    used.laser.icp.converged = true;
    used.laser.icp.rms_residual = 0.0125;
    used.laser.innovation << 0.01, -0.02, 0.005;
    used.laser.observed_pose = {1.25, 0.75, -0.5};
    used.laser.nis = 2.5;
    writer.on_step(used, GroundTruth{});

    // A mismatch that starts the recovery: the match's cells but no observation.
    LoopSnapshot mismatch = laser_step(2);
    mismatch.laser.scan_received = true;
    mismatch.laser.matched = false;
    mismatch.laser.icp.matched_points = 40;
    mismatch.laser.icp.iterations = 50;
    mismatch.laser.icp.converged = false;
    mismatch.laser.icp.rms_residual = 0.25;
    mismatch.laser.consecutive_mismatches = 100;
    mismatch.laser.recovery_triggered = true;
    mismatch.laser.observed_pose = {9.0, 9.0, 9.0};  // not written: the match was not used
    mismatch.laser.nis = 99.0;
    writer.on_step(mismatch, GroundTruth{});

    // A period without a scan (the scanner is half as fast as the loop).
    LoopSnapshot no_scan = laser_step(3);
    no_scan.laser.consecutive_mismatches = 3;
    writer.on_step(no_scan, GroundTruth{});

    // Another localisation, and a missing frame: all empty.
    LoopSnapshot walls;
    walls.step = 4;
    walls.laser.scan_received = true;
    writer.on_step(walls, GroundTruth{});
    LoopSnapshot missing = laser_step(5);
    missing.frame_missing = true;
    writer.on_step(missing, GroundTruth{});

    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 5U);
    const auto& u = rows[0];
    EXPECT_EQ(u.at("laser_scan"), "1");
    EXPECT_EQ(u.at("laser_matched"), "1");
    EXPECT_EQ(u.at("laser_update"), to_string(StepStatus::Applied));
    EXPECT_EQ(u.at("laser_matched_points"), "512");
    EXPECT_EQ(u.at("laser_icp_iterations"), "7");
    EXPECT_EQ(u.at("laser_icp_converged"), "1");
    EXPECT_EQ(u.at("laser_icp_rms"), "0.0125");
    EXPECT_EQ(u.at("laser_mismatches"), "0");
    EXPECT_EQ(u.at("laser_recovery"), "0");
    EXPECT_EQ(u.at("laser_innovation_x"), "0.01");
    EXPECT_EQ(u.at("laser_innovation_y"), "-0.02");
    EXPECT_EQ(u.at("laser_innovation_theta"), "0.005");
    EXPECT_EQ(u.at("laser_observed_x"), "1.25");
    EXPECT_EQ(u.at("laser_observed_y"), "0.75");
    EXPECT_EQ(u.at("laser_observed_theta"), "-0.5");
    EXPECT_EQ(u.at("laser_nis"), "2.5");

    const auto& m = rows[1];
    EXPECT_EQ(m.at("laser_scan"), "1");
    EXPECT_EQ(m.at("laser_matched"), "0");
    EXPECT_EQ(m.at("laser_update"), to_string(StepStatus::NotAttempted));
    EXPECT_EQ(m.at("laser_matched_points"), "40");
    EXPECT_EQ(m.at("laser_icp_iterations"), "50");
    EXPECT_EQ(m.at("laser_icp_converged"), "0");
    EXPECT_EQ(m.at("laser_icp_rms"), "0.25");
    EXPECT_EQ(m.at("laser_mismatches"), "100");
    EXPECT_EQ(m.at("laser_recovery"), "1");
    for (const char* empty :
         {"laser_innovation_x", "laser_innovation_y", "laser_innovation_theta", "laser_observed_x",
          "laser_observed_y", "laser_observed_theta", "laser_nis"}) {
        EXPECT_EQ(m.at(empty), "") << empty;
    }

    const auto& n = rows[2];
    EXPECT_EQ(n.at("laser_scan"), "0");
    EXPECT_EQ(n.at("laser_mismatches"), "3");
    EXPECT_EQ(n.at("laser_recovery"), "0");
    for (const char* empty : {"laser_matched", "laser_update", "laser_matched_points",
                              "laser_icp_iterations", "laser_icp_converged", "laser_icp_rms",
                              "laser_innovation_x", "laser_observed_x", "laser_nis"}) {
        EXPECT_EQ(n.at(empty), "") << empty;
    }

    for (const std::size_t row : {3U, 4U}) {
        for (const std::string& column : kLaserColumns) {
            EXPECT_EQ(rows[row].at(column), "") << row << ": " << column;
        }
    }
    EXPECT_EQ(rows[3].at("localisation"), "walls");
}

TEST(TraceCsvLaser, AnUpdateRejectedByTheFilterHasNoNis) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);
    LoopSnapshot s = laser_step(1);
    s.laser.scan_received = true;
    s.laser.matched = true;
    s.laser.status = StepStatus::RejectedByGate;
    s.laser.nis = 40.0;
    s.laser.observed_pose = {1.0, 2.0, 0.0};
    writer.on_step(s, GroundTruth{});
    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 1U);
    EXPECT_EQ(rows[0].at("laser_update"), to_string(StepStatus::RejectedByGate));
    EXPECT_EQ(rows[0].at("laser_observed_y"), "2");
    EXPECT_EQ(rows[0].at("laser_nis"), "");
}

TEST(TraceCsvLaser, TheAssociationGateColumnsCarryTheCandidatesD2AndThreshold) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);
    LoopSnapshot s = laser_step(1);
    writer.on_step(s, GroundTruth{});  // no candidate wall: empty cells
    s.association.outcome = AssociationOutcome::MahalanobisMismatch;
    s.association.gate = AssociationGate::Mahalanobis;
    s.association.wall = 0;
    s.association.mahalanobis_d2 = 136.25;
    s.association.mahalanobis_threshold = 9.21034037;
    writer.on_step(s, GroundTruth{});
    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0].at("association_gate"), "");
    EXPECT_EQ(rows[0].at("association_d2"), "");
    EXPECT_EQ(rows[0].at("association_d2_threshold"), "");
    EXPECT_EQ(rows[1].at("association"), "Mahalanobis distance above the gate");
    EXPECT_EQ(rows[1].at("association_gate"), "mahalanobis");
    EXPECT_EQ(rows[1].at("association_d2"), "136.25");
    EXPECT_EQ(rows[1].at("association_d2_threshold"), "9.21034037");
}

TEST(TraceCsvLaser, TheGlitchFlagMarksTheStepsWhoseCountsWereNotUsed) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);
    LoopSnapshot s = laser_step(1);
    writer.on_step(s, GroundTruth{});
    s.odometry_glitch = true;
    writer.on_step(s, GroundTruth{});
    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0].at("odometry_glitch"), "0");
    EXPECT_EQ(rows[1].at("odometry_glitch"), "1");
}

TEST(TraceCsvLaser, ThePredictionColumnSaysHowTheStepPredicted) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);
    LoopSnapshot s = laser_step(1);
    s.predict_status = StepStatus::Applied;
    writer.on_step(s, GroundTruth{});
    s.predict_status = StepStatus::AppliedLinearised;
    writer.on_step(s, GroundTruth{});
    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 2U);
    EXPECT_EQ(rows[0].at("prediction"), to_string(StepStatus::Applied));
    EXPECT_EQ(rows[1].at("prediction"), to_string(StepStatus::AppliedLinearised));
    EXPECT_NE(rows[0].at("prediction"), rows[1].at("prediction"));
}

}  // namespace
}  // namespace legofeup::lessons
