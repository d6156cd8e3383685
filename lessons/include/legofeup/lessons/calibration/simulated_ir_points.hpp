#pragma once
// Calibration measurements taken on the simulated robot, as a student takes them on a real
// one (docs/calibration.md): a flat target square to the sensors at known distances, the mean
// of several readings at each. With the realistic IR model each sensor has its own curve,
// which these points reveal; with the ideal model they lie on the filter's own curve.

#include <cstdint>
#include <span>
#include <vector>

#include "legofeup/lessons/calibration/ir_calibration.hpp"
#include "legofeup/sim/robot_spec.hpp"

namespace legofeup::lessons {

/// The distances docs/calibration.md advises: every 1 cm from 4 to 10 cm, every 2 cm from
/// 12 to 30 cm (17 distances), metres.
std::vector<double> advised_ir_calibration_distances();

/// For each distance (metres, from the sensors' front face): the robot of `robot`, run with
/// `seed`, stands still facing a wall at that distance for `readings` control periods; each
/// sensor gives one point (the mean of its A/D values, the distance). Front sensor's points
/// first, then the rear's (each point says its sensor), each in the order of `distances`. Throws
/// std::invalid_argument when `robot` does not validate, `readings` < 1 or a distance is not in (0,
/// 0.8] m.
std::vector<IrCalibrationPoint> measure_simulated_ir_points(const sim::RobotSpec& robot,
                                                            std::uint64_t seed,
                                                            std::span<const double> distances,
                                                            int readings);

}  // namespace legofeup::lessons
