#include "legofeup/core/extra_sensors.hpp"

#include "legofeup/core/angles.hpp"

namespace legofeup {

double gyro_rate_from_raw(std::int16_t raw, const ExtraSensorCalibration& calibration) {
    const double rate_dps =
        (static_cast<double>(raw) - calibration.gyro_offset) / calibration.gyro_counts_per_dps;
    return degrees_to_radians(rate_dps);
}

double accel_from_raw(std::int16_t raw, const ExtraSensorCalibration& calibration) {
    return static_cast<double>(raw) / calibration.accel_counts_per_g * calibration.gravity;
}

double compass_heading_from_raw(std::int16_t degrees) {
    return wrap_angle(degrees_to_radians(static_cast<double>(degrees)));
}

VelocityCommand body_acceleration(double a_right, double a_left, double wheel_base) {
    return {0.5 * (a_right + a_left), (a_right - a_left) / wheel_base};
}

}  // namespace legofeup
