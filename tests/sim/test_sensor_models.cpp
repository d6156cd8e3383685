// The further lessons' sensor models as pure functions (sim/src/sensor_models.hpp) and the
// magnetic disturbance field, against hand-worked values.

#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/sim/world.hpp"
#include "sensor_models.hpp"

namespace legofeup::sim {
namespace {

TEST(MagneticDisturbance, IsBoundedByItsAmplitudeAndReachesIt) {
    const MagneticDisturbance field{12.0, 3.0};
    double largest = 0.0;
    // One wavelength-periodic cell and more: 0.5 cm grid over 6 m × 6 m.
    for (int i = 0; i <= 1200; ++i) {
        for (int j = 0; j <= 1200; ++j) {
            const Vector2 p(-3.0 + 0.005 * i, -3.0 + 0.005 * j);
            const double d = magnetic_disturbance_deg(field, p);
            ASSERT_LE(std::abs(d), 12.0 + 1e-12) << p.transpose();
            largest = std::max(largest, std::abs(d));
        }
    }
    EXPECT_GT(largest, 0.99 * 12.0);
    // The analytic maximum: k·x = π/2 and k·(x/2 + √3·y/2) = π/2.
    const double k = 2.0 * kPi / 3.0;
    const double x = kPi / 2.0 / k;
    const double y = (kPi / 2.0 / k - 0.5 * x) * 2.0 / std::sqrt(3.0);
    EXPECT_NEAR(magnetic_disturbance_deg(field, {x, y}), 12.0, 1e-12);
}

TEST(MagneticDisturbance, IsSmoothWithBoundedGradient) {
    const MagneticDisturbance field{12.0, 3.0};
    const double bound = 12.0 * 2.0 * kPi / 3.0;  // |∇d| ≤ A·k, °/m
    const double h = 1e-4;
    double steepest = 0.0;
    for (int i = 0; i < 60; ++i) {
        for (int j = 0; j < 60; ++j) {
            const Vector2 p(-1.5 + 0.05 * i, -1.5 + 0.05 * j);
            // Central differences along x and y.
            const double gx = (magnetic_disturbance_deg(field, p + Vector2(h, 0.0))
                               - magnetic_disturbance_deg(field, p - Vector2(h, 0.0)))
                              / (2.0 * h);
            const double gy = (magnetic_disturbance_deg(field, p + Vector2(0.0, h))
                               - magnetic_disturbance_deg(field, p - Vector2(0.0, h)))
                              / (2.0 * h);
            const double gradient = std::hypot(gx, gy);
            ASSERT_LE(gradient, bound * (1.0 + 1e-6));
            steepest = std::max(steepest, gradient);
            // No jumps: a 1 cm step changes it by at most bound·1 cm.
            EXPECT_LE(std::abs(magnetic_disturbance_deg(field, p + Vector2(0.006, 0.008))
                               - magnetic_disturbance_deg(field, p)),
                      bound * 0.01 + 1e-12);
        }
    }
    EXPECT_GT(steepest, 0.3 * bound);  // it does vary across the arena
}

TEST(MagneticDisturbance, NoneIsZeroEverywhere) {
    EXPECT_EQ(magnetic_disturbance_deg(MagneticDisturbance{}, {0.3, -0.7}), 0.0);
    EXPECT_EQ(magnetic_disturbance_deg({0.0, 3.0}, {1.0, 2.0}), 0.0);
}

TEST(SensorModels, GyroAddsOffsetRateAndBiasThenSaturates) {
    const GyroSpec gyro;  // 600 counts, 1 count per °/s, ±360 °/s
    EXPECT_EQ(gyro_raw(gyro, 0.0, 0.0, 0.0), 600);
    EXPECT_EQ(gyro_raw(gyro, degrees_to_radians(90.0), 2.0, 0.4), 692);  // 600 + 90 + 2.4
    EXPECT_EQ(gyro_raw(gyro, degrees_to_radians(-45.0), -0.2, -0.4), 554);
    EXPECT_EQ(gyro_raw(gyro, degrees_to_radians(500.0), 0.0, 0.0), 960);
    EXPECT_EQ(gyro_raw(gyro, degrees_to_radians(-1000.0), 0.0, 0.0), 240);
    GyroSpec fine = gyro;
    fine.counts_per_dps = 4.0;
    EXPECT_EQ(gyro_raw(fine, degrees_to_radians(10.0), 0.0, 0.0), 640);
}

TEST(SensorModels, AccelerometerCountsPerGAndSaturates) {
    const AccelerometerSpec accel;  // 200 counts per g, ±2 g
    EXPECT_EQ(accelerometer_raw(accel, 0.5 * accel.gravity, 0.0, 0.0), 100);
    EXPECT_EQ(accelerometer_raw(accel, -0.5 * accel.gravity, 1.0, -0.6), -100);  // −99.6
    EXPECT_EQ(accelerometer_raw(accel, 3.0 * accel.gravity, 0.0, 0.0), 400);
    EXPECT_EQ(accelerometer_raw(accel, -3.0 * accel.gravity, 0.0, 0.0), -400);
}

TEST(SensorModels, CompassIsWholeDegreesInZeroTo360) {
    EXPECT_EQ(compass_raw(degrees_to_radians(90.0), 0.0, 0.0), 90);
    EXPECT_EQ(compass_raw(degrees_to_radians(90.0), 12.0, -0.7), 101);  // 101.3
    EXPECT_EQ(compass_raw(degrees_to_radians(-90.0), 0.0, 0.0), 270);
    EXPECT_EQ(compass_raw(degrees_to_radians(-0.2), 0.0, 0.0), 0);  // 359.8 rounds to 360 ≡ 0
    EXPECT_EQ(compass_raw(degrees_to_radians(359.4), 0.0, 0.0), 359);
    EXPECT_EQ(compass_raw(degrees_to_radians(0.3), -0.5, 0.0), 0);   // −0.2 → 0
    EXPECT_EQ(compass_raw(degrees_to_radians(725.0), 0.0, 0.0), 5);  // unwrapped headings
    EXPECT_EQ(compass_raw(degrees_to_radians(-725.0), 0.0, 0.0), 355);
}

TEST(SensorModels, MountSpecificForceOnACircleIsCentripetal) {
    // A point moving on a circle of radius r at rate ω: |v| = ω·r, the force points to the
    // centre, i.e. to the left of the direction of travel, magnitude ω²·r.
    const double omega = 0.8;
    const double radius = 0.5;
    const double dt = 0.01;
    const double theta0 = 0.3;
    const double theta1 = theta0 + omega * dt;
    const auto velocity = [&](double theta) -> Vector2 {
        return Vector2(-std::sin(theta), std::cos(theta)) * omega * radius;  // heading θ + π/2
    };
    // The point's heading is the direction of travel, so the robot frame is (travel, left).
    const Vector2 force = mount_specific_force(velocity(theta0), velocity(theta1),
                                               theta0 + kPi / 2.0, theta1 + kPi / 2.0, dt);
    const double chord = 2.0 * std::sin(omega * dt / 2.0) / dt;  // |Δv|/(|v|·dt)
    EXPECT_NEAR(force.x(), 0.0, 1e-12);
    EXPECT_NEAR(force.y(), omega * radius * chord, 1e-12);
    EXPECT_NEAR(force.y(), omega * omega * radius, 1e-5);
    // Speeding up straight ahead along heading 1 rad.
    const Vector2 heading(std::cos(1.0), std::sin(1.0));
    const Vector2 straight = mount_specific_force(0.1 * heading, 0.12 * heading, 1.0, 1.0, dt);
    EXPECT_NEAR(straight.x(), 2.0, 1e-12);
    EXPECT_NEAR(straight.y(), 0.0, 1e-12);
}

}  // namespace
}  // namespace legofeup::sim
