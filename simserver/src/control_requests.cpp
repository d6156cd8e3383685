// The control stream's requests (docs/protocol.md): each is checked, carried out on the
// server's thread between two periods, and answered with the status after it.

#include <algorithm>
#include <cmath>
#include <limits>

#include "legofeup/core/config_issue.hpp"
#include "server_state.hpp"

namespace legofeup::simserver {
namespace {

using comms::ControlOp;
using comms::ControlResult;

}  // namespace

std::string SimServer::State::check_pose_in_arena(const Pose2& pose) const {
    // The arena's extent: the bounding box of its walls, less the chassis' reach from the
    // axle (the circle around it, whatever the heading), so the robot lands clear of them.
    const double reach =
        std::hypot(std::max(robot.chassis_front, robot.chassis_rear), robot.chassis_half_width);
    double low_x = std::numeric_limits<double>::infinity();
    double low_y = low_x;
    double high_x = -low_x;
    double high_y = -low_x;
    for (const Wall& wall : simulator.world().walls) {
        for (const Vector2& point : {wall.start, wall.end}) {
            low_x = std::min(low_x, point.x());
            high_x = std::max(high_x, point.x());
            low_y = std::min(low_y, point.y());
            high_y = std::max(high_y, point.y());
        }
    }
    // A map's extent counts as well (a world may be a map alone, like the office).
    if (const auto& map = simulator.world().map; map && !map->empty()) {
        const Vector2 map_low = map->world_min();
        const Vector2 map_high = map->world_max();
        low_x = std::min(low_x, map_low.x());
        low_y = std::min(low_y, map_low.y());
        high_x = std::max(high_x, map_high.x());
        high_y = std::max(high_y, map_high.y());
        const auto cell = map->cell_of(position_of(pose));
        if (cell && map->occupied(*cell)) {
            return "pose (" + format_config_number(pose.x) + ", " + format_config_number(pose.y)
                   + ") m is inside an occupied cell of the map";
        }
    }
    low_x += reach;
    low_y += reach;
    high_x -= reach;
    high_y -= reach;
    if (pose.x >= low_x && pose.x <= high_x && pose.y >= low_y && pose.y <= high_y) {
        return {};
    }
    return "pose (" + format_config_number(pose.x) + ", " + format_config_number(pose.y)
           + ") m is outside the arena, or the chassis would overlap a wall (x "
           + format_config_number(low_x) + " … " + format_config_number(high_x) + ", y "
           + format_config_number(low_y) + " … " + format_config_number(high_y) + ")";
}

comms::ControlReplyPacket SimServer::State::carry_out(const comms::ControlRequestPacket& request,
                                                      Clock::time_point now) {
    comms::ControlReplyPacket reply;
    reply.sequence = ++reply_sequence;
    reply.request_id = request.request_id;
    reply.op = request.op;
    const auto refuse = [&](std::string message) {
        reply.result = ControlResult::Rejected;
        reply.message = std::move(message);
    };

    switch (static_cast<ControlOp>(request.op)) {
        case ControlOp::Status:
            break;
        case ControlOp::Reset: {
            const Pose2 start = request.pose_given ? request.pose : simulator.world().start;
            if (std::string problem = check_pose_in_arena(start); !problem.empty()) {
                refuse("reset: " + problem);
                break;
            }
            // Time 0, encoders 0, motors still, every noise stream reseeded.
            simulator.reset(start, request.seed);
            seed = request.seed;
            steps = 0;
            session.motors_stopped();
            reset_flag = true;
            restart_clock(now);
            send_truth();
            send_frame(now);  // the new time 0 at once, with the reset flag
            break;
        }
        case ControlOp::Pause:
            paused = true;
            break;
        case ControlOp::Resume:
            if (paused) {
                paused = false;
                restart_clock(now);
            }
            break;
        case ControlOp::SetNoise: {
            sim::RobotSpec changed = robot;
            changed.wheel_diameter_ratio = request.noise.wheel_diameter_ratio;
            changed.wheel_base_ratio = request.noise.wheel_base_ratio;
            changed.slip_noise = request.noise.slip_noise;
            changed.ir_noise = request.noise.ir_noise;
            if (const auto issues = sim::validate(changed); !issues.empty()) {
                refuse("set noise: " + join_issue_messages(issues, "; "));
                break;
            }
            simulator.set_robot(changed);
            robot = changed;
            break;
        }
        case ControlOp::Teleport:
            if (std::string problem = check_pose_in_arena(request.pose); !problem.empty()) {
                refuse("teleport: " + problem);
                break;
            }
            simulator.teleport(request.pose);
            break;
        case ControlOp::SetTimeScale: {
            SimServerOptions changed = options;
            changed.time_scale = request.time_scale;
            if (const auto issues = validate(changed); !issues.empty()) {
                refuse("set time scale: " + join_issue_messages(issues, "; "));
                break;
            }
            options = changed;
            restart_clock(now);
            break;
        }
        default:
            reply.result = ControlResult::UnknownOp;
            reply.message = "unknown op " + std::to_string(request.op);
            break;
    }
    reply.time = simulator.time();
    reply.status = current_status();
    return reply;
}

}  // namespace legofeup::simserver
