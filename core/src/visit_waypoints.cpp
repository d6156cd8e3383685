#include "legofeup/core/visit_waypoints.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>

namespace legofeup {
namespace {

// Facing further than this off the desired heading, the robot turns on the spot first.
const double kTurnInPlaceAbove = degrees_to_radians(60.0);
// Slack on the pause clock so that, e.g., 20 × 0.05 s counts as the full 1 s.
constexpr double kPauseClockSlack = 1e-9;
// A leg shorter than this has no direction of its own; aim straight at the waypoint.
constexpr double kMinLegLength = 1e-9;

struct LegGeometry {
    Vector2 direction;  // u
    double length;      // |p_k − p_{k−1}|
    double distance;    // |p_k − x|
};

LegGeometry leg_geometry(const Vector2& from, const Vector2& target, const Vector2& position) {
    const Vector2 leg = target - from;
    const Vector2 to_target = target - position;
    LegGeometry g{Vector2::UnitX(), leg.norm(), to_target.norm()};
    if (g.length > kMinLegLength) {
        g.direction = leg / g.length;
    } else if (g.distance > 0.0) {
        g.direction = to_target / g.distance;
    }
    return g;
}

ControlOutput standing_still(bool finished) {
    ControlOutput out;
    out.finished = finished;
    return out;
}

}  // namespace

VisitWaypoints::VisitWaypoints(std::vector<Vector2> waypoints, double pause, int laps)
    : waypoints_(std::move(waypoints)), pause_(pause), laps_(laps) {
    if (waypoints_.empty()) {
        phase_ = Phase::Finished;
    }
}

bool VisitWaypoints::last_waypoint_of_run() const {
    const bool last_in_list = index_ + 1 == static_cast<int>(waypoints_.size());
    return last_in_list && laps_ > 0 && completed_laps_ + 1 >= laps_;
}

bool VisitWaypoints::stops_at_target() const {
    return pause_ > 0.0 || last_waypoint_of_run();
}

void VisitWaypoints::arrive() {
    const bool finishes_run = last_waypoint_of_run();
    if (index_ + 1 == static_cast<int>(waypoints_.size())) {
        ++completed_laps_;
    }
    paused_for_ = 0.0;
    if (finishes_run) {
        phase_ = Phase::Finished;
    } else if (pause_ > 0.0) {
        phase_ = Phase::Pause;
    } else {
        leave_waypoint();
    }
}

void VisitWaypoints::leave_waypoint() {
    leg_start_ = waypoints_[static_cast<std::size_t>(index_)];
    index_ = (index_ + 1) % static_cast<int>(waypoints_.size());
    phase_ = Phase::Drive;
}

ControlOutput VisitWaypoints::step(const Pose2& estimate, const MotionLimits& limits,
                                   const ControllerGains& gains, double period) {
    switch (phase_) {
        case Phase::Finished:
            return standing_still(true);
        case Phase::Start:
            leg_start_ = position_of(estimate);  // the first leg starts where the robot is
            phase_ = Phase::Drive;
            break;
        case Phase::Pause:
            if (std::isfinite(period) && period > 0.0) {
                paused_for_ += period;
            }
            if (paused_for_ + kPauseClockSlack < pause_) {
                return standing_still(false);
            }
            leave_waypoint();
            break;
        case Phase::Turn:
        case Phase::Drive:
            break;
    }
    return drive_leg(estimate, limits, gains);
}

ControlOutput VisitWaypoints::drive_leg(const Pose2& estimate, const MotionLimits& limits,
                                        const ControllerGains& gains) {
    const Vector2 position = position_of(estimate);
    const auto current_leg = [&] {
        return leg_geometry(leg_start_, waypoints_[static_cast<std::size_t>(index_)], position);
    };
    LegGeometry g = current_leg();
    const bool passed = g.direction.dot(position - leg_start_) >= g.length;
    if (g.distance <= gains.position_tolerance || passed) {
        arrive();
        if (phase_ != Phase::Drive) {
            return standing_still(finished());
        }
        g = current_leg();  // passing through: steer along the next leg at once
    }

    // FollowLine's law on the leg p_{k−1} → p_k.
    const double offset = cross(g.direction, position - leg_start_);  // e, left positive
    const double desired =
        std::atan2(g.direction.y(), g.direction.x()) - std::atan(gains.cross_track_gain * offset);
    const double error = wrap_angle(desired - estimate.theta);  // θ_d − θ
    if (phase_ == Phase::Drive && std::abs(error) > kTurnInPlaceAbove) {
        phase_ = Phase::Turn;
    } else if (phase_ == Phase::Turn && std::abs(error) <= gains.heading_tolerance) {
        phase_ = Phase::Drive;
    }

    ControlOutput out;
    out.cross_track_error = offset;
    out.heading_error = error;
    out.command.w = std::clamp(gains.heading_gain * error, -limits.w_ref, limits.w_ref);
    if (phase_ == Phase::Drive) {
        out.command.v = limits.v_ref * std::max(0.0, std::cos(error));
        if (stops_at_target()) {
            out.command.v = std::min(out.command.v, gains.distance_gain * g.distance);
        }
    }
    return out;
}

std::vector<Vector2> random_waypoints(std::uint64_t seed, int count, const Vector2& lower,
                                      const Vector2& upper, double min_spacing) {
    if (count < 0) {
        throw std::invalid_argument("random_waypoints: negative count");
    }
    if (!lower.allFinite() || !upper.allFinite() || (upper - lower).minCoeff() < 0.0) {
        throw std::invalid_argument("random_waypoints: the box must be finite, lower ≤ upper");
    }
    const Vector2 size = upper - lower;
    if (!std::isfinite(min_spacing) || min_spacing < 0.0 || min_spacing > 0.5 * size.norm()) {
        throw std::invalid_argument(
            "random_waypoints: spacing must be between 0 and half the box diagonal");
    }

    std::mt19937_64 engine(seed);
    // u = (top 53 bits) · 2⁻⁵³ ∈ [0, 1): the same on every standard library.
    const auto uniform = [&engine] { return static_cast<double>(engine() >> 11) * 0x1.0p-53; };
    const auto draw = [&] {
        const double ux = uniform();
        const double uy = uniform();
        return Vector2(lower.x() + ux * size.x(), lower.y() + uy * size.y());
    };

    constexpr int kMaxDraws = 1000;
    std::vector<Vector2> points;
    points.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        Vector2 point = draw();
        if (!points.empty()) {
            const Vector2& previous = points.back();
            int draws = 1;
            while ((point - previous).norm() < min_spacing && draws < kMaxDraws) {
                point = draw();
                ++draws;
            }
            if ((point - previous).norm() < min_spacing) {
                // Rejection keeps failing (a spacing near half the diagonal): the box corner
                // farthest from the previous point is at least half the diagonal away.
                point = Vector2(previous.x() < lower.x() + 0.5 * size.x() ? upper.x() : lower.x(),
                                previous.y() < lower.y() + 0.5 * size.y() ? upper.y() : lower.y());
            }
        }
        points.push_back(point);
    }
    return points;
}

}  // namespace legofeup
