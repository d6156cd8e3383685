#pragma once
// The robot's two driven wheels acting on the Box2D chassis: motors with a first-order
// speed response and saturation, encoders that count wheel rotation, and tyre contacts that
// push the chassis (longitudinal traction) and stop it sliding sideways (lateral grip), both
// limited by friction. Private to sim/.

#include <box2d/box2d.h>

#include <array>
#include <cstdint>

#include "legofeup/core/motion.hpp"
#include "legofeup/sim/robot_spec.hpp"
#include "noise_streams.hpp"

namespace legofeup::sim {

class DriveTrain {
  public:
    explicit DriveTrain(const RobotSpec& spec) { set_spec(spec); }
    void set_spec(const RobotSpec& spec);

    /// Commanded wheel surface speeds (m/s) → motor speed targets with the *nominal* radius.
    void set_command(const WheelSpeeds& command);

    /// Before a world step: advance the motors over dt, count the encoders, and apply the
    /// tyre impulses that make the chassis follow the wheels (within friction).
    void drive(b2Body& chassis, double dt, GaussianStream& slip_right, GaussianStream& slip_left);

    /// What the encoders report: ⌊turns · counts_per_turn⌋ of each wheel, [0] right, [1]
    /// left, as 32-bit counters that wrap (docs/protocol.md).
    std::array<std::int32_t, 2> encoder_counts() const;
    /// Surface speeds ω·r of the wheels, m/s.
    WheelSpeeds surface_speeds() const;

    void stop_motors();

  private:
    RobotSpec spec_;
    std::array<double, 2> radius_{};         // actual wheel radii, m
    std::array<double, 2> target_rate_{};    // rad/s
    std::array<double, 2> rate_{};           // rad/s
    std::array<double, 2> wheel_degrees_{};  // cumulative wheel rotation, degrees
};

}  // namespace legofeup::sim
