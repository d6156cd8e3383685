// trace.csv's columns for the further lessons (docs/experiments.md): the original columns
// first and unchanged, then the optional sensors' readings, the speed estimates, the shadow
// filter and the truths, each filled from its LoopSnapshot / GroundTruth field and empty
// where the lesson has no such value.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
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

double value(const std::map<std::string, std::string>& row, const std::string& name) {
    const auto it = row.find(name);
    if (it == row.end()) {
        ADD_FAILURE() << "no column " << name;
        return std::numeric_limits<double>::quiet_NaN();
    }
    return std::stod(it->second);
}

TEST(TraceCsvFurtherLessons, TheOriginalColumnsComeFirstInTheirOrder) {
    const std::string header = trace_csv_header();
    EXPECT_EQ(header.rfind("t,x_true,y_true,th_true,x_est,y_est,th_est,pxx,pxy,pxt,pyy,pyt,ptt,"
                           "x_odo,y_odo,th_odo,ds1,ds2,v1,v2,wall,nis,nees,"
                           "adc1,adc2,association,update,touching_wall,frame_missing,",
                           0),
              0U);
    const std::vector<std::string> names = cells_of(header);
    // + the laser lesson's 16, the loop's 2 checks (odometry_glitch, prediction) and the
    // association gate's 3 and the particle filter's 5 (test_trace_csv_laser.cpp)
    EXPECT_EQ(names.size(), 59U + 16U + 2U + 3U + 5U);
    for (std::size_t i = 0; i < names.size(); ++i) {
        for (std::size_t j = i + 1; j < names.size(); ++j) {
            EXPECT_NE(names[i], names[j]);
        }
    }
}

TEST(TraceCsvFurtherLessons, EachColumnCarriesItsSnapshotField) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);

    LoopSnapshot s;
    s.step = 1;
    s.time = 0.5;
    s.localisation = Localisation::GyroFusion;
    s.filter_kind = FilterKind::Ukf;
    s.frame.has_beacon_scan = true;
    s.frame.beacons.count = 3;
    s.beacons.count = 3;
    s.beacons.updates[0].status = StepStatus::Applied;
    s.beacons.updates[1].status = StepStatus::Applied;
    s.beacons.updates[2].status = StepStatus::NotAttempted;
    s.readings.has_gyro = true;
    s.readings.gyro_rate = 0.25;
    s.readings.gyro_heading = -1.5;
    s.readings.has_compass = true;
    s.readings.compass_heading = 3.0;
    s.readings.has_accelerometers = true;
    s.readings.accel_forward = {0.125, -0.375};
    s.speeds.valid = true;
    s.speeds.wheel_kf = {0.11, 0.09};
    s.speeds.wheel_differentiated = {0.12, 0.08};
    s.speeds.body_encoders = {0.1, 0.4};
    s.speeds.body_kf_valid = true;
    s.speeds.body_kf = {0.105, 0.41};
    s.fused_velocity = {0.098, 0.39};
    s.shadow.active = true;
    s.shadow.kind = FilterKind::Ekf;
    s.shadow.estimate << 1.5, -0.5, 0.75;
    s.shadow.covariance.diagonal() << 1e-4, 2e-4, 3e-4;
    s.shadow.covariance(0, 1) = 7.0;  // off-diagonals are not written
    GroundTruth truth;
    truth.velocity = {0.1, 0.4};
    truth.wheel_surface_speeds = {0.124, 0.076};
    truth.gyro_bias_rate = 0.0123;
    truth.magnetic_disturbance = -0.2;
    writer.on_step(s, truth);

    // A wall lesson's step: none of the further values exist.
    LoopSnapshot plain;
    plain.step = 2;
    plain.time = 0.55;
    writer.on_step(plain, GroundTruth{});

    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 2U);
    const auto& r = rows[0];
    EXPECT_EQ(r.at("localisation"), "gyro_fusion");
    EXPECT_EQ(r.at("filter"), "ukf");
    EXPECT_EQ(r.at("beacon_sightings"), "3");
    EXPECT_EQ(r.at("beacon_updates"), "2");
    EXPECT_EQ(value(r, "gyro_rate"), 0.25);
    EXPECT_EQ(value(r, "gyro_heading"), -1.5);
    EXPECT_EQ(value(r, "compass_heading"), 3.0);
    EXPECT_EQ(value(r, "accel_right"), 0.125);
    EXPECT_EQ(value(r, "accel_left"), -0.375);
    EXPECT_EQ(value(r, "wheel_kf_right"), 0.11);
    EXPECT_EQ(value(r, "wheel_kf_left"), 0.09);
    EXPECT_EQ(value(r, "wheel_diff_right"), 0.12);
    EXPECT_EQ(value(r, "wheel_diff_left"), 0.08);
    EXPECT_EQ(value(r, "v_enc"), 0.1);
    EXPECT_EQ(value(r, "w_enc"), 0.4);
    EXPECT_EQ(value(r, "v_kf"), 0.105);
    EXPECT_EQ(value(r, "w_kf"), 0.41);
    EXPECT_EQ(value(r, "v_fused"), 0.098);
    EXPECT_EQ(value(r, "w_fused"), 0.39);
    EXPECT_EQ(r.at("shadow_filter"), "ekf");
    EXPECT_EQ(value(r, "shadow_x"), 1.5);
    EXPECT_EQ(value(r, "shadow_y"), -0.5);
    EXPECT_EQ(value(r, "shadow_theta"), 0.75);
    EXPECT_EQ(value(r, "shadow_pxx"), 1e-4);
    EXPECT_EQ(value(r, "shadow_pyy"), 2e-4);
    EXPECT_EQ(value(r, "shadow_ptt"), 3e-4);
    EXPECT_EQ(value(r, "v_true"), 0.1);
    EXPECT_EQ(value(r, "w_true"), 0.4);
    EXPECT_EQ(value(r, "wheel_right_true"), 0.124);
    EXPECT_EQ(value(r, "wheel_left_true"), 0.076);
    EXPECT_EQ(r.count("gyro_bias_true"), 0U);  // not carried by the UDP truth stream

    const auto& p = rows[1];
    EXPECT_EQ(p.at("localisation"), "walls");
    EXPECT_EQ(p.at("filter"), "ekf");
    for (const char* empty : {"beacon_sightings",
                              "beacon_updates",
                              "gyro_rate",
                              "gyro_heading",
                              "compass_heading",
                              "accel_right",
                              "accel_left",
                              "wheel_kf_right",
                              "wheel_kf_left",
                              "wheel_diff_right",
                              "wheel_diff_left",
                              "v_enc",
                              "w_enc",
                              "v_kf",
                              "w_kf",
                              "v_fused",
                              "w_fused",
                              "shadow_filter",
                              "shadow_x",
                              "shadow_y",
                              "shadow_theta",
                              "shadow_pxx",
                              "shadow_pyy",
                              "shadow_ptt"}) {
        EXPECT_EQ(p.at(empty), "") << empty;
    }
    EXPECT_EQ(p.at("wheel_left_true"), "0");
}

TEST(TraceCsvFurtherLessons, SpeedsWithoutAccelerometersLeaveTheKfBodySpeedEmpty) {
    const LoopConfig loop;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, loop);
    LoopSnapshot s;
    s.speeds.valid = true;
    s.speeds.body_kf_valid = false;
    s.speeds.body_kf = {5.0, 5.0};
    s.frame_missing = true;  // and a missing frame has no scan, whatever it holds
    s.frame.has_beacon_scan = true;
    s.frame.beacons.count = 2;
    writer.on_step(s, GroundTruth{});
    const auto rows = rows_of(csv.str());
    ASSERT_EQ(rows.size(), 1U);
    EXPECT_EQ(rows[0].at("v_kf"), "");
    EXPECT_EQ(rows[0].at("w_kf"), "");
    EXPECT_EQ(rows[0].at("v_enc"), "0");
    EXPECT_EQ(rows[0].at("beacon_sightings"), "");
}

}  // namespace
}  // namespace legofeup::lessons
