#include "legofeup/lessons/udp_run.hpp"

#include <cmath>

#include "legofeup/comms/link_error.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {
namespace {

using namespace std::chrono_literals;

/// The run's control period must be the server's: the loop's noise model is per period.
void check_control_period(comms::ControlClient& control, const ResolvedRun& run,
                          const UdpTarget& target) {
    const comms::ServerStatus status = control.status();
    const double period = run.config.simulator.control_period;
    if (std::abs(status.control_period - period) > 1e-9) {
        throw comms::LinkError("the simulator at " + target.robot.to_string() + " runs "
                               + format_config_number(status.control_period)
                               + " s control periods, the run " + format_config_number(period)
                               + " s: start legofeup-sim with --control-period "
                               + format_config_number(period));
    }
}

comms::UdpLinkOptions link_options(const UdpTarget& target) {
    comms::UdpLinkOptions options;
    options.server = target.robot;
    return options;
}

}  // namespace

comms::NoiseSettings noise_settings_of(const RobotNoise& noise) {
    return {noise.wheel_diameter_ratio, noise.wheel_base_ratio, noise.slip_noise, noise.ir_noise};
}

// The truth receiver subscribes in its constructor, before the reset below, so the truth of
// time 0 is not missed.
UdpRobotConnection::UdpRobotConnection(const ResolvedRun& run, const UdpTarget& target)
    : target_(target),
      robot_(target.robot),
      control_(target.control),
      truth_(target.truth),
      link_(link_options(target)) {
    check_control_period(control_, run, target);
    control_.set_noise(noise_settings_of(robot_noise(run.robot)));
    link_.connect();
    control_.reset(run.config.seed, run.true_start);
    if (!link_.await_reset(2s)) {
        throw comms::LinkError("the simulator at " + target.robot.to_string()
                               + " sent no frame after the reset");
    }
}

UdpRobotConnection::~UdpRobotConnection() {
    close();
}

void UdpRobotConnection::set_noise(const RobotNoise& noise) {
    control_.set_noise(noise_settings_of(noise));
}

void UdpRobotConnection::set_paused(bool paused) {
    if (paused) {
        control_.pause();
    } else {
        control_.resume();
    }
}

void UdpRobotConnection::close() {
    if (link_.connected()) {
        link_.disconnect();
    }
}

LinkHealth UdpRobotConnection::health() const {
    const comms::LinkCounters counters = link_.counters();
    LinkHealth health;
    health.state = link_.connected() ? LinkState::Connected : LinkState::Disconnected;
    health.address = describe();
    health.frames = counters.frames.accepted;
    health.frames_lost = counters.frames.missing;
    health.timeouts = counters.timeouts;
    health.rejected_replies = counters.malformed;
    return health;
}

nlohmann::json UdpRobotConnection::summary() {
    const comms::LinkCounters counters = link_.counters();
    nlohmann::json json = {
        {"kind", "udp"},
        {"robot", target_.robot.to_string()},
        {"truth", target_.truth.to_string()},
        {"control", target_.control.to_string()},
        {"frames_received", counters.frames.accepted},
        {"frames_duplicate", counters.frames.duplicate},
        {"frames_late", counters.frames.late},
        {"frame_timeouts", counters.timeouts},
    };
    try {
        const comms::ServerStatus server = control_.status();
        json.update({
            {"server_time_scale", server.time_scale},
            {"server_commands_accepted", server.counters.commands_accepted},
            {"server_commands_missing", server.counters.commands_missing},
            {"server_overruns", server.counters.overruns},
        });
    } catch (const comms::LinkError& silent) {  // a server that stopped keeps its counters
        json["server_status"] = std::string("no answer: ") + silent.what();
    }
    return json;
}

UdpTarget parse_udp_target(const std::string& url, int truth_port, int control_port) {
    const auto robot = comms::parse_udp_url(url);
    if (!robot || robot->port == 0 || (truth_port == 0 && robot->port > 65533)) {
        throw InputError({{"", 0, "--link", url,
                           "expected lockstep or udp://a.b.c.d:port (an IPv4 address "
                           "and the simulator's robot port, e.g. "
                           "udp://127.0.0.1:5600)"}});
    }
    const auto port_or = [](int given, int fallback) {
        return static_cast<std::uint16_t>(given != 0 ? given : fallback);
    };
    return {*robot, robot->with_port(port_or(truth_port, robot->port + 1)),
            robot->with_port(port_or(control_port, robot->port + 2))};
}

UdpRunReport run_over_udp(const ResolvedRun& run, const UdpTarget& target, RunObserver* observer,
                          const ProgressCallback& progress) {
    UdpRobotConnection connection(run, target);
    UdpRunReport report;
    report.result = run_with_link(run, connection.link(), connection.truth(), observer, progress);
    connection.close();
    report.server = connection.control().status();
    report.link = connection.link().counters();
    return report;
}

}  // namespace legofeup::lessons
