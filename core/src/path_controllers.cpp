#include "legofeup/core/path_controllers.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup {
namespace {

// Turn towards `desired_heading` (plus a feed-forward turn rate) and drive at V_ref scaled
// by how well the robot already faces it.
ControlOutput steer(double desired_heading, double heading, double feedforward_per_metre,
                    const MotionLimits& limits, const ControllerGains& gains) {
    ControlOutput out;
    out.heading_error = wrap_angle(desired_heading - heading);
    out.command.v = limits.v_ref * std::max(0.0, std::cos(out.heading_error));
    const double w = feedforward_per_metre * out.command.v + gains.heading_gain * out.heading_error;
    out.command.w = std::clamp(w, -limits.w_ref, limits.w_ref);
    return out;
}

double heading_of(const Vector2& v) {
    return std::atan2(v.y(), v.x());
}

}  // namespace

ControlOutput GoXYTheta::step(const Pose2& estimate, const MotionLimits& limits,
                              const ControllerGains& gains) {
    const Vector2 to_target = position_of(target_) - position_of(estimate);
    const double distance = to_target.norm();
    const double final_error = wrap_angle(target_.theta - estimate.theta);

    // Phases with hysteresis (twice the tolerance to leave), so noise cannot make it dither.
    if (distance > 2.0 * gains.position_tolerance) {
        phase_ = Phase::Approach;
    } else if (phase_ == Phase::Approach && distance <= gains.position_tolerance) {
        phase_ = Phase::Align;
    } else if (phase_ == Phase::Arrived && std::abs(final_error) > 2.0 * gains.heading_tolerance) {
        phase_ = Phase::Align;
    }
    if (phase_ == Phase::Align && std::abs(final_error) <= gains.heading_tolerance) {
        phase_ = Phase::Arrived;
    }

    ControlOutput out;
    out.cross_track_error = distance;
    switch (phase_) {
        case Phase::Approach: {
            out = steer(heading_of(to_target), estimate.theta, 0.0, limits, gains);
            out.command.v = std::min(out.command.v, gains.distance_gain * distance);
            out.cross_track_error = distance;
            break;
        }
        case Phase::Align:
            out.heading_error = final_error;
            out.command.w =
                std::clamp(gains.heading_gain * final_error, -limits.w_ref, limits.w_ref);
            break;
        case Phase::Arrived:
            out.heading_error = final_error;
            out.finished = true;
            break;
    }
    return out;
}

FollowLine::FollowLine(const Vector2& from, const Vector2& to)
    : from_(from), to_(to), direction_(Vector2::UnitX()), length_((to - from).norm()) {
    if (length_ > 0.0) {
        direction_ = (to - from) / length_;
    }
}

ControlOutput FollowLine::step(const Pose2& estimate, const MotionLimits& limits,
                               const ControllerGains& gains) const {
    const Vector2 relative = position_of(estimate) - from_;
    const double offset = cross(direction_, relative);  // left of the line positive
    const double desired = heading_of(direction_) - std::atan(gains.cross_track_gain * offset);
    ControlOutput out = steer(desired, estimate.theta, 0.0, limits, gains);
    out.cross_track_error = offset;
    out.finished = direction_.dot(relative) >= length_;
    return out;
}

FollowCircle::FollowCircle(const Vector2& centre, double radius, bool counter_clockwise,
                           double sweep)
    : centre_(centre), radius_(radius), counter_clockwise_(counter_clockwise), sweep_(sweep) {}

ControlOutput FollowCircle::step(const Pose2& estimate, const MotionLimits& limits,
                                 const ControllerGains& gains) {
    const double sense = counter_clockwise_ ? 1.0 : -1.0;
    const Vector2 relative = position_of(estimate) - centre_;
    const double bearing = heading_of(relative);
    const double offset = relative.norm() - radius_;  // outside positive
    const double tangent = bearing + sense * 0.5 * kPi;
    // Outside a CCW circle the centre is to the left: aim left of the tangent (and mirrored).
    const double desired = tangent + sense * std::atan(gains.cross_track_gain * offset);
    ControlOutput out = steer(desired, estimate.theta, sense / radius_, limits, gains);
    out.cross_track_error = offset;

    if (started_) {
        swept_ += sense * wrap_angle(bearing - last_bearing_);
    }
    started_ = true;
    last_bearing_ = bearing;
    out.finished = sweep_ > 0.0 && swept_ >= sweep_;
    return out;
}

}  // namespace legofeup
