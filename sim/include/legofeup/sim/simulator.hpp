#pragma once
// The arena simulator: a LEGO NXT differential-drive robot in a top-down Box2D world.
//
// It owns time. One call of step_control_period() advances the physics by a whole control
// period (fixed physics steps of 1/physics_rate s) with the last wheel command, and then
// sensor_frame() is what the robot's brick would report: cumulative encoder counts from wheel
// rotation and the IR sensors' held 10-bit A/D values. ground_truth() is the separate channel.
// Deterministic: the same world, robot, settings and seed give bit-identical frames.

#include <array>
#include <cstdint>
#include <memory>

#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/sim/robot_spec.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::sim {

struct SimulatorSettings {
    double physics_rate = 100.0;   ///< Hz; the physics step is 1/physics_rate
    double control_period = 0.05;  ///< s; a whole number of physics steps

    /// A sudden change of the robot's position (paper 002's kidnapping): at the start of the
    /// first control period whose end time is ≥ `time`, the robot is moved by (dx, dy) m and
    /// turned by dtheta rad in world coordinates, at rest (teleport); the encoders do not see
    /// it. Once per run (again after a reset).
    struct DisplacementEvent {
        bool enabled = false;
        double time = 0.0;    ///< s
        double dx = 0.0;      ///< m
        double dy = 0.0;      ///< m
        double dtheta = 0.0;  ///< rad
    } displacement;

    /// A kidnapping to a known place (paper 001 §IV-B): at the start of the first control
    /// period whose end time is ≥ `time`, the robot is lifted to `pose` (world frame), at
    /// rest; the encoders do not see it. Once per run (again after a reset).
    struct KidnapEvent {
        bool enabled = false;
        double time = 0.0;  ///< s
        Pose2 pose;         ///< where the robot is put down
    } kidnap;
};

/// Everything wrong with the settings; fields are named "simulator.<name>".
std::vector<ConfigIssue> validate(const SimulatorSettings& settings);
/// Everything wrong with the robot and the settings together: validate(robot),
/// validate(settings), and what depends on both (an enabled laser scanner's scan period must
/// be a whole number of control periods, "simulator.laser_scanner.scan_period"). The
/// simulator's constructor and set_robot check this.
std::vector<ConfigIssue> validate(const RobotSpec& robot, const SimulatorSettings& settings);

class Simulator {
  public:
    /// Throws std::invalid_argument if the world, robot spec or settings do not validate.
    Simulator(WorldSpec world, RobotSpec robot, SimulatorSettings settings, std::uint64_t seed);
    ~Simulator();
    Simulator(const Simulator&) = delete;
    Simulator& operator=(const Simulator&) = delete;

    /// Back to time 0 at `start` with all noise streams reseeded.
    void reset(const Pose2& start, std::uint64_t seed);
    /// Moves the robot instantly (a kidnapping), at rest; time and encoders go on.
    /// GroundTruth::teleports counts it.
    void teleport(const Pose2& pose);

    /// Wheel speeds for the motors, m/s. Like the NXT firmware, the motors turn them into
    /// wheel rotation with the nominal diameter; the real wheels then roll their own.
    void set_wheel_command(const WheelSpeeds& command);
    /// Changes noise and error parameters while running (e.g. from the GUI). The geometry
    /// of the body (mass, chassis, wheel base) is fixed at construction and reset. Throws
    /// std::invalid_argument if validate(robot, settings()) finds anything.
    void set_robot(const RobotSpec& robot);

    void step_physics();
    void step_control_period();

    SensorFrame sensor_frame() const;
    GroundTruth ground_truth() const;
    /// The IR sensors' units (front, rear) the realistic model uses this run: truth, for
    /// tests and teaching; the ideal model ignores them.
    std::array<IrUnit, 2> ir_units() const;
    double time() const;
    const WorldSpec& world() const;
    const RobotSpec& robot() const;
    const SimulatorSettings& settings() const;

  private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace legofeup::sim
