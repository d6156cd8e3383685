#include "legofeup/lessons/calibration/simulated_ir_points.hpp"

#include <stdexcept>
#include <string>

#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

// A long wall along the x axis; the robot heads +x above it, so its right-side sensors look
// straight down at it.
sim::WorldSpec calibration_bench() {
    sim::WorldSpec world;
    world.name = "IR calibration bench";
    world.walls.push_back({"target", {-2.0, 0.0}, {2.0, 0.0}});
    world.start = {0.0, 0.5, 0.0};
    return world;
}

}  // namespace

std::vector<double> advised_ir_calibration_distances() {
    std::vector<double> distances;
    for (int cm = 4; cm <= 10; ++cm) {
        distances.push_back(cm / 100.0);
    }
    for (int cm = 12; cm <= 30; cm += 2) {
        distances.push_back(cm / 100.0);
    }
    return distances;
}

std::vector<IrCalibrationPoint> measure_simulated_ir_points(const sim::RobotSpec& robot,
                                                            std::uint64_t seed,
                                                            std::span<const double> distances,
                                                            int readings) {
    if (readings < 1) {
        throw std::invalid_argument("readings per distance must be at least 1, not "
                                    + std::to_string(readings));
    }
    for (const double distance : distances) {
        if (!(distance > 0.0 && distance <= robot.ir_ray_length)) {
            throw std::invalid_argument("calibration distance " + std::to_string(distance)
                                        + " m is not in (0, ir_ray_length]");
        }
    }
    sim::Simulator simulator(calibration_bench(), robot, sim::SimulatorSettings{}, seed);
    simulator.set_wheel_command({0.0, 0.0});
    std::vector<IrCalibrationPoint> front;
    std::vector<IrCalibrationPoint> rear;
    for (const double distance : distances) {
        // The sensors sit lateral_offset to the right of the centre line.
        simulator.teleport({0.0, distance + robot.ir_mount.lateral_offset, 0.0});
        double sum[2] = {0.0, 0.0};
        for (int i = 0; i < readings; ++i) {
            // With the default ir_period (38 ms < 50 ms) each period brings a fresh sample.
            simulator.step_control_period();
            const SensorFrame frame = simulator.sensor_frame();
            sum[0] += frame.ir_adc[0];
            sum[1] += frame.ir_adc[1];
        }
        front.push_back({sum[0] / readings, distance, kFrontSensor});
        rear.push_back({sum[1] / readings, distance, kRearSensor});
    }
    front.insert(front.end(), rear.begin(), rear.end());
    return front;
}

}  // namespace legofeup::lessons
