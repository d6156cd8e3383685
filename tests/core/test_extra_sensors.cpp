#include <gtest/gtest.h>

#include <cstdint>

#include "legofeup/core/extra_sensors.hpp"
#include "legofeup/core/lesson_filters_config.hpp"

namespace legofeup {
namespace {

TEST(ExtraSensors, ConvertsRawReadingsToSiUnits) {
    const ExtraSensorCalibration calibration;  // offset 600, 1 count/(°/s), 200 counts/g
    EXPECT_NEAR(gyro_rate_from_raw(690, calibration), kPi / 2.0, 1e-12);  // 90 °/s
    EXPECT_NEAR(gyro_rate_from_raw(555, calibration), -kPi / 4.0, 1e-12);
    ExtraSensorCalibration doubled = calibration;
    doubled.gyro_counts_per_dps = 2.0;
    EXPECT_NEAR(gyro_rate_from_raw(780, doubled), kPi / 2.0, 1e-12);

    EXPECT_NEAR(accel_from_raw(200, calibration), 9.80665, 1e-12);
    EXPECT_NEAR(accel_from_raw(-100, calibration), -4.903325, 1e-12);

    EXPECT_NEAR(compass_heading_from_raw(0), 0.0, 1e-12);
    EXPECT_NEAR(compass_heading_from_raw(90), kPi / 2.0, 1e-12);
    EXPECT_NEAR(compass_heading_from_raw(180), kPi, 1e-12);
    EXPECT_NEAR(compass_heading_from_raw(270), -kPi / 2.0, 1e-12);
    EXPECT_NEAR(compass_heading_from_raw(359), -kPi / 180.0, 1e-12);
}

TEST(ExtraSensors, BodyAccelerationFromTheWheelAccelerometers) {
    // a = (1.0 + 0.5)/2 = 0.75 m/s², α = (1.0 − 0.5)/0.12 = 4.1667 rad/s².
    const VelocityCommand acceleration = body_acceleration(1.0, 0.5, 0.12);
    EXPECT_NEAR(acceleration.v, 0.75, 1e-15);
    EXPECT_NEAR(acceleration.w, 0.5 / 0.12, 1e-12);
}

TEST(LessonFiltersConfig, NamesRoundTrip) {
    for (const Localisation value : {Localisation::Walls, Localisation::Beacons,
                                     Localisation::GyroFusion, Localisation::Compass}) {
        EXPECT_EQ(localisation_from_string(to_string(value)), value);
    }
    EXPECT_STREQ(to_string(Localisation::GyroFusion), "gyro_fusion");
    EXPECT_EQ(localisation_from_string("Beacons"), std::nullopt);
    EXPECT_EQ(filter_kind_from_string("ukf"), FilterKind::Ukf);
    EXPECT_EQ(filter_kind_from_string("ekf"), FilterKind::Ekf);
    EXPECT_STREQ(to_string(FilterKind::Ukf), "ukf");
    EXPECT_EQ(filter_kind_from_string(""), std::nullopt);
}

}  // namespace
}  // namespace legofeup
