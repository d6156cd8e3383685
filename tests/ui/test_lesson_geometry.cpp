// The further lessons' Qt-free helpers behind the views: where a bearing ray goes and how long
// it is drawn. (Which settings a localisation uses: tests/lessons/test_setting_table.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"

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

}  // namespace
}  // namespace legofeup::ui
