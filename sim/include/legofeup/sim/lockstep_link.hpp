#pragma once
// The in-process link: the simulator advances exactly one control period per frame asked
// for, so a run is deterministic and as fast as the machine allows.

#include "legofeup/core/robot_link.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::sim {

class LockstepLink final : public RobotLink {
  public:
    explicit LockstepLink(Simulator& simulator) : simulator_(simulator) {}

    /// The first call returns the frame at the current time; every later call first runs
    /// the simulator for one control period with the last command.
    std::optional<SensorFrame> next_frame() override;
    void send_command(const WheelSpeeds& command) override;

    /// Forget that a frame was delivered (after the simulator was reset).
    void restart() { started_ = false; }

  private:
    Simulator& simulator_;
    bool started_ = false;
};

}  // namespace legofeup::sim
