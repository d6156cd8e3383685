#include "legofeup/sim/lockstep_link.hpp"

namespace legofeup::sim {

std::optional<SensorFrame> LockstepLink::next_frame() {
    if (started_) {
        simulator_.step_control_period();
    }
    started_ = true;
    return simulator_.sensor_frame();
}

void LockstepLink::send_command(const WheelSpeeds& command) {
    simulator_.set_wheel_command(command);
}

}  // namespace legofeup::sim
