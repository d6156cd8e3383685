// The control stream's requests (docs/protocol.md): each is checked, carried out on the
// server's thread between two periods, and answered with the status after it.

#include <string>
#include <string_view>
#include <vector>

#include "legofeup/core/config_issue.hpp"
#include "placement.hpp"
#include "server_state.hpp"

namespace legofeup::simserver {
namespace {

using comms::ControlOp;
using comms::ControlResult;

/// "<request>: <field> = <value>: <reason>" for the first issue, and how many more there are,
/// short enough for the reply's message field (at most 87 bytes for the noise and time-scale
/// checks): the field without its section ("slip_noise", not "simulator.slip_noise"), since a
/// protocol client sets it by its place in the request, not by a configuration key.
std::string first_issue(std::string_view request, const std::vector<ConfigIssue>& issues) {
    const ConfigIssue& issue = issues.front();
    const std::string field = issue.field.substr(issue.field.rfind('.') + 1);
    std::string message =
        std::string(request) + ": " + field + " = " + issue.value + ": " + issue.reason;
    if (issues.size() > 1) {
        message += " (and " + std::to_string(issues.size() - 1) + " more)";
    }
    return message;
}

}  // namespace

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
            if (std::string problem = placement_problem(simulator.world(), robot, start, "reset");
                !problem.empty()) {
                refuse(std::move(problem));
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
                refuse(first_issue("set noise", issues));
                break;
            }
            simulator.set_robot(changed);
            robot = changed;
            break;
        }
        case ControlOp::Teleport:
            if (std::string problem =
                    placement_problem(simulator.world(), robot, request.pose, "teleport");
                !problem.empty()) {
                refuse(std::move(problem));
                break;
            }
            simulator.teleport(request.pose);
            break;
        case ControlOp::SetTimeScale: {
            SimServerOptions changed = options;
            changed.time_scale = request.time_scale;
            if (const auto issues = validate(changed); !issues.empty()) {
                refuse(first_issue("set time scale", issues));
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
