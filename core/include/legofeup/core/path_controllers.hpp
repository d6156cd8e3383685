#pragma once
// The control module's routines (paper §IV.A): GoXYTheta, FollowLine, FollowCircle.
// Each takes the estimated pose, V_ref and W_ref, and returns (V, W).
//
// Steering law shared by the line and circle routines: with e the signed offset from the
// reference (left of a line / outside a circle positive) and φ the reference's heading,
// the robot aims at θ_d = φ ∓ atan(k_e·e) (back towards the reference, never more than 90°
// off it), turns with W = W_ff + k_θ·wrap(θ_d − θ) clipped to ±W_ref, and drives with
// V = V_ref·max(0, cos(θ_d − θ)), so it turns on the spot when facing away.
// For a line ė = V·sin(θ − φ) → −V·k_e·e/√(1 + k_e²e²): the offset decays monotonically.

#include <cstdint>

#include "legofeup/core/motion.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

struct ControlOutput {
    VelocityCommand command;
    bool finished = false;           ///< the routine's goal is reached (see each routine)
    double cross_track_error = 0.0;  ///< signed offset from the reference, m
    double heading_error = 0.0;      ///< desired − estimated heading, rad
};

/// Drives to (x, y), then turns on the spot to θ. Finished (and stopped) when both are
/// within the gains' tolerances.
class GoXYTheta {
  public:
    explicit GoXYTheta(const Pose2& target) : target_(target) {}
    const Pose2& target() const { return target_; }
    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains);

  private:
    enum class Phase : std::uint8_t { Approach, Align, Arrived };
    Pose2 target_;
    Phase phase_ = Phase::Approach;
};

/// Follows the line through `from` and `to`, in that direction. Finished once the robot has
/// passed `to` (measured along the line); it keeps following the line afterwards.
class FollowLine {
  public:
    FollowLine(const Vector2& from, const Vector2& to);
    const Vector2& from() const { return from_; }
    const Vector2& to() const { return to_; }
    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains) const;

  private:
    Vector2 from_;
    Vector2 to_;
    Vector2 direction_;  // unit vector from → to
    double length_;
};

/// Follows a circle counter-clockwise (or clockwise). With a finite `sweep` (radians,
/// positive) it is finished once the robot has travelled that angle around the centre.
class FollowCircle {
  public:
    FollowCircle(const Vector2& centre, double radius, bool counter_clockwise, double sweep = 0.0);
    const Vector2& centre() const { return centre_; }
    double radius() const { return radius_; }
    bool counter_clockwise() const { return counter_clockwise_; }
    double sweep() const { return sweep_; }
    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains);

  private:
    Vector2 centre_;
    double radius_;
    bool counter_clockwise_;
    double sweep_;  // 0: never finished
    bool started_ = false;
    double last_bearing_ = 0.0;
    double swept_ = 0.0;  // angle travelled in the commanded direction
};

}  // namespace legofeup
