#pragma once
// A link is where sensor frames come from and where wheel commands go: the in-process
// simulator (lockstep), a simulator over UDP, or the NXT over Bluetooth. The loop never
// knows which; choosing the robot is choosing a link.

#include <optional>

#include "legofeup/core/motion.hpp"
#include "legofeup/core/sensor_frame.hpp"

namespace legofeup {

class RobotLink {
  public:
    virtual ~RobotLink() = default;

    /// The sensor frame of the next control period. Real links block until it arrives;
    /// std::nullopt means none came (closed or timed out) and the caller decides what to do.
    virtual std::optional<SensorFrame> next_frame() = 0;

    /// The wheel speeds (V1, V2) for the coming control period.
    virtual void send_command(const WheelSpeeds& command) = 0;
};

}  // namespace legofeup
