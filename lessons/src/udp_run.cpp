#include "legofeup/lessons/udp_run.hpp"

#include <cmath>

#include "legofeup/comms/control_client.hpp"
#include "legofeup/comms/link_error.hpp"
#include "legofeup/comms/truth_receiver.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons {
namespace {

using namespace std::chrono_literals;

comms::NoiseSettings noise_of(const sim::RobotSpec& robot) {
    return {robot.wheel_diameter_ratio, robot.wheel_base_ratio, robot.slip_noise, robot.ir_noise};
}

}  // namespace

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
    comms::ControlClient control(target.control);
    const comms::ServerStatus status = control.status();
    const double period = run.config.simulator.control_period;
    if (std::abs(status.control_period - period) > 1e-9) {
        throw comms::LinkError("the simulator at " + target.robot.to_string() + " runs "
                               + format_config_number(status.control_period)
                               + " s control periods, the run " + format_config_number(period)
                               + " s: start legofeup-sim with --control-period "
                               + format_config_number(period));
    }
    // Subscribe before the reset so the truth of time 0 is not missed; the status request
    // above and the noise request below are answered only after the subscription arrived.
    comms::TruthReceiver truth(target.truth);
    control.set_noise(noise_of(run.robot));

    comms::UdpLinkOptions options;
    options.server = target.robot;
    comms::UdpSimulatorLink link(options);
    link.connect();
    control.reset(run.config.seed, run.true_start);
    if (!link.await_reset(2s)) {
        throw comms::LinkError("the simulator at " + target.robot.to_string()
                               + " sent no frame after the reset");
    }

    UdpRunReport report;
    report.result = run_with_link(run, link, truth, observer, progress);
    link.disconnect();
    report.server = control.status();
    report.link = link.counters();
    return report;
}

}  // namespace legofeup::lessons
