// The further lessons' Qt-free helpers behind the views: where a bearing ray goes, how long
// it is drawn, and which settings a localisation uses.

#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/panels/setting_relevance.hpp"

namespace legofeup::ui {
namespace {

TEST(BearingRay, GoesAlongHeadingPlusBearing) {
    // Facing +y (θ = 90°), a beacon 30° to the left is at 120° in the world.
    const Pose2 pose{1.0, -0.5, kPi / 2.0};
    const BearingRay ray = bearing_ray(pose, degrees_to_radians(30.0), 2.0);
    EXPECT_DOUBLE_EQ(ray.from.x(), 1.0);
    EXPECT_DOUBLE_EQ(ray.from.y(), -0.5);
    EXPECT_NEAR(ray.to.x(), 1.0 + 2.0 * std::cos(degrees_to_radians(120.0)), 1e-12);  // 0.0
    EXPECT_NEAR(ray.to.y(), -0.5 + 2.0 * std::sin(degrees_to_radians(120.0)), 1e-12);
    EXPECT_NEAR(ray.to.x(), 0.0, 1e-12);
    // A negative bearing is to the right (clockwise).
    const BearingRay right = bearing_ray({0.0, 0.0, 0.0}, -kPi / 2.0, 1.0);
    EXPECT_NEAR(right.to.x(), 0.0, 1e-12);
    EXPECT_NEAR(right.to.y(), -1.0, 1e-12);
}

TEST(BearingRay, TheExpectedBearingHitsTheBeacon) {
    // h(X̂) = atan2(by − y, bx − x) − θ: its ray, drawn to the beacon's distance, ends on it.
    const Pose2 pose{-0.3, 0.4, 2.5};
    const Beacon beacon{7, Vector2(1.1, -0.9)};
    const double h = wrap_angle(
        std::atan2(beacon.position.y() - pose.y, beacon.position.x() - pose.x) - pose.theta);
    const double distance = std::hypot(1.4, -1.3);
    const BearingRay ray = bearing_ray(pose, h, distance);
    EXPECT_NEAR(ray.to.x(), beacon.position.x(), 1e-12);
    EXPECT_NEAR(ray.to.y(), beacon.position.y(), 1e-12);
    EXPECT_NEAR(beacon_ray_length(pose, beacon), 1.15 * distance, 1e-12);
    // Sitting on the beacon: still a visible stub.
    EXPECT_DOUBLE_EQ(beacon_ray_length({1.1, -0.9, 0.0}, beacon), 0.1);
}

TEST(SettingRelevance, EachLocalisationGreysTheOthersFilters) {
    EXPECT_TRUE(setting_relevant("filter.r11", Localisation::Walls));
    EXPECT_FALSE(setting_relevant("filter.r11", Localisation::Beacons));
    EXPECT_FALSE(setting_relevant("ir_curve.max_range", Localisation::Compass));
    EXPECT_FALSE(setting_relevant("association.max_incidence_deg", Localisation::GyroFusion));
    EXPECT_TRUE(setting_relevant("beacons.r_bearing", Localisation::Beacons));
    EXPECT_FALSE(setting_relevant("beacons.r_bearing", Localisation::Walls));
    EXPECT_TRUE(setting_relevant("compass.r_compass", Localisation::Compass));
    EXPECT_FALSE(setting_relevant("compass.r_compass", Localisation::Beacons));
    EXPECT_TRUE(setting_relevant("gyro_fusion.r_w_gyro", Localisation::GyroFusion));
    // EKF or UKF: every pose filter but the 5-state fusion, which is an EKF only.
    for (const char* key : {"filter.kind", "filter.compare_kinds", "filter.ukf_kappa"}) {
        EXPECT_TRUE(setting_relevant(key, Localisation::Walls)) << key;
        EXPECT_TRUE(setting_relevant(key, Localisation::Beacons)) << key;
        EXPECT_TRUE(setting_relevant(key, Localisation::Compass)) << key;
        EXPECT_FALSE(setting_relevant(key, Localisation::GyroFusion)) << key;
    }
    // Shared settings and unknown keys stay.
    for (const char* key : {"filter.q11", "control.v_ref", "seed", "gyro.noise", "no.such"}) {
        for (const Localisation l : {Localisation::Walls, Localisation::Beacons,
                                     Localisation::GyroFusion, Localisation::Compass}) {
            EXPECT_TRUE(setting_relevant(key, l)) << key;
        }
    }
    // The laser lesson (paper 001): its scan matching only there; its Q is its own (eq. 13),
    // so the odometry's Q11, Q22 are the other lessons'; the simulated scanner is always
    // there (a simulator sensor) and "laser." is not "laser_scanner.".
    for (const char* key : {"laser.r_x", "laser.min_matched_points", "laser.icp_metric",
                            "laser.recovery_covariance_factor", "laser.map"}) {
        EXPECT_TRUE(setting_relevant(key, Localisation::Laser)) << key;
        for (const Localisation l : {Localisation::Walls, Localisation::Beacons,
                                     Localisation::GyroFusion, Localisation::Compass}) {
            EXPECT_FALSE(setting_relevant(key, l)) << key;
        }
    }
    for (const char* key : {"filter.q11", "filter.q22", "filter.r11", "ir_curve.a",
                            "beacons.r_bearing", "compass.k_d"}) {
        EXPECT_FALSE(setting_relevant(key, Localisation::Laser)) << key;
    }
    for (const char* key :
         {"filter.kind", "laser_scanner.enabled", "kidnap.time", "control.v_ref"}) {
        EXPECT_TRUE(setting_relevant(key, Localisation::Laser)) << key;
        EXPECT_TRUE(setting_relevant(key, Localisation::Walls)) << key;
    }
    EXPECT_EQ(setting_lesson("laser.r_x"), "the laser lesson (scan matching in a map)");
    EXPECT_EQ(setting_lesson("laser_scanner.enabled"), "");
    EXPECT_EQ(setting_lesson("filter.r11"), "the wall lesson (IR sensors)");
    EXPECT_EQ(setting_lesson("control.v_ref"), "");
}

TEST(SettingRelevance, EveryRuleNamesARealSetting) {
    // A rule that matches no key of the settings table is a typo (or a renamed section).
    for (const char* key : {"filter.r11", "filter.r22", "filter.wall_updates", "filter.gate",
                            "filter.kind", "filter.compare_kinds", "filter.ukf_kappa", "ir_curve.a",
                            "association.range_margin", "beacons.r_bearing", "gyro_fusion.q_v",
                            "compass.k_d", "filter.q11", "filter.q22", "laser.r_x"}) {
        EXPECT_NE(lessons::find_setting_by_key(key), nullptr) << key;
    }
}

}  // namespace
}  // namespace legofeup::ui
