#pragma once
// A kinematic stand-in for the simulator, for core tests only: exact unicycle motion, wheel
// encoders that count whole degrees of wheel rotation, and IR sensors computed by an
// independent ray–segment intersection and the published GP2D120 fit. Nothing here reuses
// the core's geometry code, so tests compare the core against separate calculations.
//
// Slip, as in the simulator (docs/simulator.md, "Errors"): each period a wheel ROLLS
// s = v·dt (what its encoder counts) but its tyre COVERS s + ε on the ground, with
// ε ~ N(0, slip_noise²·|s|), independently per wheel and per period. The pose follows the
// covered distances, the encoders the rolled ones, so slip is odometry error: after rolling
// a distance S the ground distance of each wheel is off by N(0, slip_noise²·S).

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "legofeup/core/legofeup_loop.hpp"

namespace legofeup::testing {

/// The physical robot: its real wheel sizes and base may differ from what the filter assumes
/// (Borenstein's systematic errors E_d and E_b).
struct KinematicRobotParams {
    double right_wheel_diameter = 0.0432;
    double left_wheel_diameter = 0.0432;
    double wheel_base = 0.12;
    double counts_per_turn = 360.0;
    /// Random slip, m^½: the variance of a tyre's ground distance minus its rolled distance
    /// is slip_noise²·|rolled| per period (see the file comment). 0 = none.
    double slip_noise = 0.0;
};

class KinematicRobot {
  public:
    KinematicRobot(const Pose2& start, const KinematicRobotParams& params, unsigned seed = 1);

    /// Holds the wheel speeds (surface speeds ω·r) for `dt` seconds; the encoders count the
    /// rolled distances, the pose follows the exact circular arc of the covered ones.
    void drive(const WheelSpeeds& wheels, double dt);
    /// Unicycle form, for controller tests: V and W held for dt.
    void drive(const VelocityCommand& command, double dt);

    const Pose2& pose() const { return pose_; }
    std::array<std::int32_t, 2> encoder_counts() const;

  private:
    Pose2 pose_;
    KinematicRobotParams params_;
    std::array<double, 2> wheel_degrees_{};  // right, left
    std::mt19937_64 rng_;
};

/// Exact arc motion of a unicycle: V, W held for dt from `pose` (heading not wrapped).
Pose2 integrate_arc(const Pose2& pose, double v, double w, double dt);

/// Distance from a sensor at `origin` looking along `direction` to the nearest wall
/// segment, or +infinity when the ray hits nothing.
double ray_distance(const Vector2& origin, const Vector2& direction,
                    const std::vector<Wall>& walls);

/// IR readings the real sensors would give at `pose` (front, rear): metres.
std::array<double, 2> true_ir_distances(const Pose2& pose, const std::vector<Wall>& walls,
                                        double lateral_offset = 0.06, double front = 0.05,
                                        double rear = -0.05);

/// The published GP2D120 fit R[cm] = 2914/(A + 5) − 1, inverted: distance → 10-bit A/D.
std::uint16_t gp2d120_adc(double distance_m);

/// One step of truth for a closed-loop run.
struct RunRecord {
    Pose2 truth;
    LoopSnapshot snapshot;
};

/// Runs the loop against the kinematic robot for `duration` seconds at `period`, optionally
/// adding Gaussian noise (standard deviation in metres) to each IR distance.
std::vector<RunRecord> run_closed_loop(LegoFeupLoop& loop, KinematicRobot& robot,
                                       const std::vector<Wall>& walls, double duration,
                                       double period = 0.05, double ir_noise_sd = 0.0,
                                       unsigned noise_seed = 7);

}  // namespace legofeup::testing
