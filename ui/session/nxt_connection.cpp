#include "legofeup/ui/session/nxt_connection.hpp"

#include <QObject>
#include <exception>
#include <utility>

#include "legofeup/lessons/input_error.hpp"
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

/// Starts an emulated brick with `target`'s wiring and relay program on `config`'s simulated
/// robot, and points `target` at it (and its truth).
std::unique_ptr<EmulatedNxtBrick> start_emulated_brick(lessons::NxtTarget& target,
                                                       const lessons::RunConfig& config) {
    const comms::nxt::NxtWiring& wiring = target.link.wiring;
    nxtemu::EmulatorOptions options;
    options.run = config;  // the simulated robot, world, noise and seed of this run
    options.wiring = {wiring.right_motor, wiring.left_motor, wiring.front_ir, wiring.rear_ir,
                      wiring.reversed_motors};
    options.firmware.relay_program = target.link.relay_program;
    auto emulated = std::make_unique<EmulatedNxtBrick>(std::move(options));
    const std::uint16_t port = emulated->brick.serve_tcp();
    target.link.address = {comms::nxt::TransportKind::Tcp, "127.0.0.1", port};
    target.truth = emulated->brick.truth_endpoint();
    return emulated;
}

}  // namespace

bool nxt_supported() {
    return true;
}

NxtConnection prepare_nxt_connection(const LinkChoice& choice, const lessons::RobotProfile* profile,
                                     const lessons::RunConfig& config) {
    lessons::NxtTarget target;
    target.link.mode =
        choice.relay ? comms::nxt::CycleMode::Relay : comms::nxt::CycleMode::DirectCommands;
    if (profile != nullptr) {
        lessons::apply_robot_profile(*profile, target);  // its wiring and motor constant
    }
    NxtConnection connection;
    if (choice.emulated) {
        try {
            connection.emulated_brick = start_emulated_brick(target, config);
        } catch (const std::exception& error) {
            connection.problem =
                QObject::tr("The emulated brick did not start: %1").arg(error.what());
            return connection;
        }
    } else {
        const std::string typed = normalized_nxt_address(choice.nxt_address).toStdString();
        try {
            target.link.address = lessons::parse_nxt_target(typed, choice.relay, "").link.address;
        } catch (const lessons::InputError& error) {
            connection.problem = QObject::tr("The NXT's address: %1").arg(error.what());
            return connection;
        }
    }
    connection.connect = [target]() { return lessons::connect_nxt(target); };
    return connection;
}

}  // namespace legofeup::ui
