#pragma once
// The loop's side of the robot stream (docs/protocol.md): connects to a simulator server,
// hands the loop one sensor frame per control period and sends its wheel commands back. To
// the loop it is a RobotLink like the in-process one.
//
// Frames arrive in order, each once: duplicates and reordered (late) frames are dropped and
// counted, malformed datagrams and datagrams from other addresses too. next_frame() waits
// for a frame at most frame_timeout and then returns nullopt: the caller predicts without it.

#include <chrono>
#include <optional>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/comms/sequence_window.hpp"
#include "legofeup/comms/udp_socket.hpp"
#include "legofeup/core/robot_link.hpp"

namespace legofeup::comms {

struct UdpLinkOptions {
    Endpoint server{kLoopbackAddress, kDefaultRobotPort};  ///< the robot port
    std::chrono::milliseconds connect_timeout{3000};
    /// How long next_frame() waits; unset: 1.5 control periods at the server's time scale,
    /// or 150 ms in lockstep (the server advances after 100 ms without an answer).
    std::optional<std::chrono::microseconds> frame_timeout;
};

struct LinkCounters {
    SequenceCounts frames;              ///< accepted, duplicate, late, missing
    std::uint64_t timeouts = 0;         ///< next_frame() calls that returned nothing
    std::uint64_t malformed = 0;        ///< datagrams that did not decode as a frame
    std::uint64_t unexpected_peer = 0;  ///< datagrams from an address other than the server
    std::uint64_t commands_sent = 0;
};

class UdpSimulatorLink final : public RobotLink {
  public:
    explicit UdpSimulatorLink(UdpLinkOptions options);
    ~UdpSimulatorLink() override;

    /// Asks for the robot until the server accepts (retrying every 200 ms). Throws LinkError
    /// if no server answers within connect_timeout or another client holds the robot.
    void connect();
    /// Stops the motors and releases the robot (best effort: one datagram each).
    void disconnect();
    bool connected() const { return connected_; }

    /// After asking the server for a reset: drops older frames until the one with the reset
    /// flag, which next_frame() then returns first. False if none came within `timeout`.
    bool await_reset(std::chrono::milliseconds timeout);

    std::optional<SensorFrame> next_frame() override;
    void send_command(const WheelSpeeds& command) override;

    /// The flags of the frame last returned (reset, paused, watchdog).
    const FrameFlags& last_flags() const { return last_flags_; }
    double control_period() const { return control_period_; }
    double time_scale() const { return time_scale_; }
    LinkCounters counters() const {
        LinkCounters counters = counters_;
        counters.frames = frame_window_.counts();
        return counters;
    }
    Endpoint local_endpoint() const { return socket_.local_endpoint(); }

  private:
    void send_bare(PacketType type);
    /// The next new frame before `deadline`, or nullopt.
    std::optional<FramePacket> receive_frame(std::chrono::steady_clock::time_point deadline);

    UdpLinkOptions options_;
    UdpSocket socket_;
    bool connected_ = false;
    double control_period_ = 0.0;
    double time_scale_ = 1.0;
    std::chrono::microseconds frame_timeout_{150'000};
    SequenceWindow frame_window_;
    FrameFlags last_flags_;
    std::optional<FramePacket> pending_;  ///< the reset frame await_reset() found
    double last_frame_time_ = 0.0;
    // Commands are numbered on their own, so the server's window sees no gaps where a
    // Connect or Disconnect went out (docs/protocol.md: sequences count packets of a type).
    std::uint32_t next_command_sequence_ = 1;
    std::uint32_t next_session_sequence_ = 1;
    LinkCounters counters_;
};

}  // namespace legofeup::comms
