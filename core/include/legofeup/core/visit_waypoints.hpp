#pragma once
// VisitWaypoints: the "random path" and "piecewise trajectory" of paper 004 — drive to each
// of a list of coordinates in order, optionally standing still at each one for a set time.
//
// Leg k runs from the previous waypoint p_{k−1} (for the first leg: where the robot was when
// the routine started) to the waypoint p_k and is steered like FollowLine: with u the unit
// vector p_{k−1} → p_k and e = u × (x − p_{k−1}) the signed offset (left positive), the
// desired heading is θ_d = atan2(u) − atan(k_e·e), W = k_θ·wrap(θ_d − θ) clipped to ±W_ref,
// V = V_ref·max(0, cos(θ_d − θ)). When the robot must stop at p_k (a pause, or the end) it
// also slows to V ≤ k_ρ·|p_k − x| like GoXYTheta. Facing more than 60° off θ_d it turns on
// the spot (V = 0) until within the heading tolerance, as a piecewise routine does.
// p_k is reached when |p_k − x| ≤ the position tolerance or the robot has passed it along u.

#include <cstdint>
#include <vector>

#include "legofeup/core/motion.hpp"
#include "legofeup/core/path_controllers.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup {

class VisitWaypoints {
  public:
    /// `pause`: seconds standing still (V = W = 0) at each waypoint, ≥ 0. `laps` ≤ 0 repeats
    /// the list for ever (the leg after the last waypoint goes back to the first). With no
    /// waypoints the routine is finished at once (validation reports the empty list).
    explicit VisitWaypoints(std::vector<Vector2> waypoints, double pause = 0.0, int laps = 1);

    /// One control period; `period` (s) is the time this command will be applied for and
    /// is what the pause counts.
    ControlOutput step(const Pose2& estimate, const MotionLimits& limits,
                       const ControllerGains& gains, double period);

    const std::vector<Vector2>& waypoints() const { return waypoints_; }
    double pause() const { return pause_; }
    int laps() const { return laps_; }
    /// The waypoint being driven to (or paused at); the last one once finished.
    int waypoint_index() const { return index_; }
    int completed_laps() const { return completed_laps_; }
    bool paused() const { return phase_ == Phase::Pause; }
    bool finished() const { return phase_ == Phase::Finished; }

  private:
    enum class Phase : std::uint8_t { Start, Turn, Drive, Pause, Finished };

    bool last_waypoint_of_run() const;
    bool stops_at_target() const;
    void arrive();
    void leave_waypoint();
    ControlOutput drive_leg(const Pose2& estimate, const MotionLimits& limits,
                            const ControllerGains& gains);

    std::vector<Vector2> waypoints_;
    double pause_;
    int laps_;
    int index_ = 0;
    int completed_laps_ = 0;
    Phase phase_ = Phase::Start;
    Vector2 leg_start_ = Vector2::Zero();  // p_{k−1}
    double paused_for_ = 0.0;              // s stood still at the current waypoint
};

/// `count` points drawn uniformly in the box [lower, upper], each at least `min_spacing`
/// from the one before (the first one is unconstrained). Deterministic on every platform:
/// std::mt19937_64 (fully specified by the standard) mapped to [0, 1) by its top 53 bits.
/// Throws std::invalid_argument for a negative count, a non-finite or inverted box, a
/// negative spacing, or a spacing the box cannot give (more than half its diagonal).
std::vector<Vector2> random_waypoints(std::uint64_t seed, int count, const Vector2& lower,
                                      const Vector2& upper, double min_spacing);

}  // namespace legofeup
