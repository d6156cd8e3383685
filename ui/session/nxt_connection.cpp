#include "legofeup/ui/session/nxt_connection.hpp"

#include <QObject>
#include <exception>
#include <string>
#include <utility>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/links/link_registry.hpp"
#include "legofeup/lessons/nxt_run.hpp"
#include "legofeup/nxtemu/emulated_nxt.hpp"
#include "legofeup/ui/session/nxt_address.hpp"
#include "legofeup/ui/session/session.hpp"

namespace legofeup::ui {
namespace {

class EmulatedNxtBrick final : public EmulatedBrick {
  public:
    explicit EmulatedNxtBrick(nxtemu::EmulatorOptions options) : brick(std::move(options)) {}
    nxtemu::EmulatedNxt brick;
};

/// Starts an emulated brick with the wiring and relay program of `profile` (null: the
/// nominal robot's) on `config`'s simulated robot, and returns it with the link to it: its
/// loopback TCP port, and its simulator's truth.
std::unique_ptr<EmulatedNxtBrick> start_emulated_brick(const lessons::RobotProfile* profile,
                                                       const lessons::RunConfig& config,
                                                       lessons::LinkRequest& request) {
    lessons::NxtTarget target;
    if (profile != nullptr) {
        lessons::apply_robot_profile(*profile, target);
    }
    const comms::nxt::NxtWiring& wiring = target.link.wiring;
    nxtemu::EmulatorOptions options;
    options.run = config;  // the simulated robot, world, noise and seed of this run
    options.wiring = {wiring.right_motor, wiring.left_motor, wiring.front_ir, wiring.rear_ir,
                      wiring.reversed_motors};
    options.firmware.relay_program = target.link.relay_program;
    auto emulated = std::make_unique<EmulatedNxtBrick>(std::move(options));
    const std::uint16_t port = emulated->brick.serve_tcp();
    request.address = "tcp:127.0.0.1:" + std::to_string(port);
    request.truth_url = "udp://" + emulated->brick.truth_endpoint().to_string();
    return emulated;
}

}  // namespace

bool nxt_supported() {
    return true;
}

NxtConnection prepare_nxt_connection(const LinkChoice& choice, const lessons::RobotProfile* profile,
                                     const lessons::RunConfig& config) {
    lessons::LinkRequest request;
    request.relay = choice.relay;
    NxtConnection connection;
    if (choice.emulated) {
        try {
            connection.emulated_brick = start_emulated_brick(profile, config, request);
        } catch (const std::exception& error) {
            connection.problem =
                QObject::tr("The emulated brick did not start: %1").arg(error.what());
            return connection;
        }
    } else {
        request.address = normalized_nxt_address(choice.nxt_address).toStdString();
        if (!lessons::is_nxt_link(request.address)) {  // the registry would take a simulator's
            connection.problem =
                QObject::tr("The NXT's address: %1 names no NXT (bt:…, serial:… or tcp:…)")
                    .arg(QString::fromStdString(request.address));
            return connection;
        }
    }
    try {
        connection.plan = lessons::plan_link(request);  // the registry's nxt entry
    } catch (const lessons::InputError& error) {
        connection.problem = QObject::tr("The NXT's address: %1").arg(error.what());
        connection.emulated_brick.reset();
        return connection;
    }
    if (profile != nullptr) {
        connection.plan->apply_profile(*profile);  // its wiring, motor constant, relay program
    }
    return connection;
}

}  // namespace legofeup::ui
