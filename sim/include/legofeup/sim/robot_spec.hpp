#pragma once
// The physical robot the simulator moves: its true geometry (which may differ from what the
// filter assumes), its motors, its contact with the floor, its IR sensors, and every noise
// source. All defaults are the NXT 2.0 robot of the scenario without errors; experiments set
// the errors (docs/simulator.md).

#include <vector>

#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/sim/ir_sensor_model.hpp"
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
    /// Ideal: both sensors follow ir_curve exactly and ir_noise is added to the distance.
    /// Realistic: each sensor is its own unit (gain and offset drawn from the seed, below) and
    /// the noise is on its output, of the size that gives ir_noise at ir_noise_distance.
    IrSensorModel ir_model = IrSensorModel::Ideal;
    double ir_noise =
        0.0;  ///< σ of the noise on each IR distance, m (realistic: at ir_noise_distance)
    /// Realistic model: where the output noise amounts to ir_noise of distance, m. The
    /// arena's walls are about 15 cm from the sensors.
    double ir_noise_distance = 0.15;
    /// Realistic model: σ of each unit's gain g (A_true = g·A + o). The GP2D120 data sheet
    /// allows 1.95–2.55 V (typ. 2.25) of output change from 30 to 4 cm, ±13 %; taken as ±3σ.
    double ir_gain_spread = 0.044;
    /// Realistic model: σ of each unit's offset o, A/D counts. The data sheet allows 0.25–0.55 V
    /// (typ. 0.4) at 30 cm, ±0.15 V = ±3σ of 0.05 V, of which the gain explains 0.4 V·0.044;
    /// the rest, √(0.05² − 0.0176²) = 0.047 V, is 9.6 counts of the 10-bit 0–5 V converter.
    double ir_offset_spread = 9.6;
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
