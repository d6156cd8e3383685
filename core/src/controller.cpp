#include "legofeup/core/controller.hpp"

#include <algorithm>
#include <type_traits>

namespace legofeup {

ControlOutput ManualDrive::step(const Pose2& /*estimate*/, const MotionLimits& limits,
                                const ControllerGains& /*gains*/) const {
    ControlOutput out;
    out.command.v = std::clamp(command_.v, -limits.v_ref, limits.v_ref);
    out.command.w = std::clamp(command_.w, -limits.w_ref, limits.w_ref);
    return out;
}

ControllerKind kind_of(const Controller& controller) {
    struct KindOf {
        ControllerKind operator()(const ManualDrive&) const { return ControllerKind::Manual; }
        ControllerKind operator()(const GoXYTheta&) const { return ControllerKind::GoXYTheta; }
        ControllerKind operator()(const FollowLine&) const { return ControllerKind::FollowLine; }
        ControllerKind operator()(const FollowCircle&) const {
            return ControllerKind::FollowCircle;
        }
        ControllerKind operator()(const FollowPath&) const { return ControllerKind::FollowPath; }
        ControllerKind operator()(const VisitWaypoints&) const {
            return ControllerKind::VisitWaypoints;
        }
    };
    return std::visit(KindOf{}, controller);
}

const char* to_string(ControllerKind kind) {
    switch (kind) {
        case ControllerKind::Manual:
            return "manual";
        case ControllerKind::GoXYTheta:
            return "GoXYTheta";
        case ControllerKind::FollowLine:
            return "FollowLine";
        case ControllerKind::FollowCircle:
            return "FollowCircle";
        case ControllerKind::FollowPath:
            return "FollowPath";
        case ControllerKind::VisitWaypoints:
            return "visit_waypoints";
    }
    return "unknown";
}

ControlOutput run_controller(Controller& controller, const Pose2& estimate,
                             const MotionLimits& limits, const ControllerGains& gains,
                             double period, ControllerStatus& status) {
    const ControlOutput out = std::visit(
        [&](auto& routine) {
            if constexpr (std::is_same_v<std::decay_t<decltype(routine)>, VisitWaypoints>) {
                return routine.step(estimate, limits, gains, period);
            } else {
                return routine.step(estimate, limits, gains);
            }
        },
        controller);
    status.kind = kind_of(controller);
    status.cross_track_error = out.cross_track_error;
    status.heading_error = out.heading_error;
    status.finished = out.finished;
    if (const auto* path = std::get_if<FollowPath>(&controller)) {
        status.segment = path->segment_index();
        status.lap = path->completed_laps();
        status.finished = path->finished();
    } else if (const auto* waypoints = std::get_if<VisitWaypoints>(&controller)) {
        status.segment = waypoints->waypoint_index();
        status.lap = waypoints->completed_laps();
    } else {
        status.segment = -1;
        status.lap = 0;
    }
    return out;
}

}  // namespace legofeup
