#pragma once
// The physical robot the simulator moves: its true geometry (which may differ from what the
// filter assumes), its motors, its contact with the floor, its IR sensors, and every noise
// source. All defaults are the NXT 2.0 robot of the scenario without errors; experiments set
// the errors (docs/simulator.md).

#include <vector>

#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/sim/sensor_specs.hpp"

namespace legofeup::sim {

struct RobotSpec {
    // Geometry as built (nominal) and Borenstein & Feng's systematic errors.
    double wheel_diameter = 0.0432;     ///< nominal (average) wheel diameter, m
    double wheel_diameter_ratio = 1.0;  ///< E_d = D_right / D_left, same average diameter
    double wheel_base = 0.12;           ///< nominal distance between the wheels' contacts, m
    double wheel_base_ratio = 1.0;      ///< E_b = actual / nominal wheel base
    double counts_per_turn = 360.0;     ///< encoder counts a wheel turn (NXT: 360, 1 count = 1°)

    // Body and floor.
    double mass = 0.6;                 ///< kg
    double chassis_front = 0.08;       ///< chassis extent ahead of the axle, m
    double chassis_rear = 0.07;        ///< chassis extent behind the axle, m
    double chassis_half_width = 0.07;  ///< including the wheels, m
    double traction = 0.8;             ///< friction coefficient μ of the tyres on the floor
    double wheel_load = 0.8;           ///< share of the weight on the two driven wheels
    /// Random wheel slip: the ground distance a wheel covers differs from its rolled
    /// distance by Gaussian noise of variance slip_noise² · |distance| (m^½).
    double slip_noise = 0.0;

    // Motors.
    double motor_time_constant = 0.05;  ///< first-order response of the wheel speed, s
    double max_motor_rpm = 170.0;       ///< no-load speed at 9 V

    // IR sensors (Sharp GP2D120 on the right side).
    IrMount ir_mount;
    SharpIrCurve ir_curve;
    double ir_noise = 0.0;       ///< σ of Gaussian noise on each IR distance, m
    double ir_period = 0.038;    ///< a new reading every 38 ms, held in between, s
    double ir_ray_length = 0.8;  ///< beyond this the sensor sees nothing, m

    // The further lessons' sensors (docs/sensors.md), all off by default.
    BeaconScannerSpec beacon_scanner;
    GyroSpec gyro;
    AccelerometerSpec accelerometers;
    CompassSpec compass;
    LaserScannerSpec laser_scanner;

    /// Actual diameters of the right and left wheels from the average and E_d.
    double right_wheel_diameter() const;
    double left_wheel_diameter() const;
};

/// Everything wrong with a robot spec; fields are named "simulator.<name>".
std::vector<ConfigIssue> validate(const RobotSpec& robot);

}  // namespace legofeup::sim
