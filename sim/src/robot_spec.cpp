#include "legofeup/sim/robot_spec.hpp"

#include <cmath>
#include <string>

namespace legofeup::sim {

// Borenstein & Feng: D_R = 2·E_d/(E_d + 1)·D, D_L = 2/(E_d + 1)·D keep the average D.
double RobotSpec::right_wheel_diameter() const {
    return 2.0 * wheel_diameter_ratio / (wheel_diameter_ratio + 1.0) * wheel_diameter;
}

double RobotSpec::left_wheel_diameter() const {
    return 2.0 / (wheel_diameter_ratio + 1.0) * wheel_diameter;
}

std::vector<ConfigIssue> validate(const RobotSpec& robot) {
    std::vector<ConfigIssue> issues;
    ConfigChecker checker(issues);
    const auto check = [&](const char* name, double value, double low, double high) {
        checker.in_range(std::string("simulator.") + name, value, low, high);
    };
    check("wheel_diameter", robot.wheel_diameter, 0.005, 1.0);
    check("wheel_diameter_ratio", robot.wheel_diameter_ratio, 0.5, 2.0);
    check("wheel_base", robot.wheel_base, 0.02, 2.0);
    check("wheel_base_ratio", robot.wheel_base_ratio, 0.5, 2.0);
    check("counts_per_turn", robot.counts_per_turn, 1.0, 1e6);
    check("mass", robot.mass, 0.01, 100.0);
    check("chassis_front", robot.chassis_front, 0.02, 2.0);  // > Box2D's 1 cm polygon skin
    check("chassis_rear", robot.chassis_rear, 0.02, 2.0);
    check("chassis_half_width", robot.chassis_half_width, 0.02, 2.0);
    check("traction", robot.traction, 0.01, 5.0);
    check("wheel_load", robot.wheel_load, 0.05, 1.0);
    check("slip_noise", robot.slip_noise, 0.0, 0.1);
    check("motor_time_constant", robot.motor_time_constant, 0.0, 5.0);
    check("max_motor_rpm", robot.max_motor_rpm, 1.0, 10000.0);
    check("ir_noise", robot.ir_noise, 0.0, 1.0);
    check("ir_noise_distance", robot.ir_noise_distance, 0.01, 1.0);
    check("ir_gain_spread", robot.ir_gain_spread, 0.0, 0.3);
    check("ir_offset_spread", robot.ir_offset_spread, 0.0, 100.0);
    check("ir_period", robot.ir_period, 0.001, 1.0);
    check("ir_ray_length", robot.ir_ray_length, 0.05, 10.0);
    for (auto&& more : {validate(robot.ir_mount, "simulator.ir_mount"),
                        validate(robot.ir_curve, "simulator.ir_curve"),
                        validate(robot.beacon_scanner, "simulator.beacon_scanner"),
                        validate(robot.gyro, "simulator.gyro"),
                        validate(robot.accelerometers, "simulator.accelerometers"),
                        validate(robot.compass, "simulator.compass"),
                        validate(robot.laser_scanner, "simulator.laser_scanner")}) {
        issues.insert(issues.end(), more.begin(), more.end());
    }
    return issues;
}

}  // namespace legofeup::sim
