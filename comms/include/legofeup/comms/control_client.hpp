#pragma once
// The control stream's client (docs/protocol.md): status, reset, pause/resume, noise,
// teleport and time scale, each a request that is retried with the same id until a reply
// comes (the server carries out a repeated id once).

#include <chrono>
#include <optional>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/comms/udp_socket.hpp"

namespace legofeup::comms {

class ControlClient {
  public:
    /// `server` is the control port.
    explicit ControlClient(const Endpoint& server,
                           std::chrono::milliseconds reply_timeout = std::chrono::milliseconds(300),
                           int attempts = 3);

    /// Sends `request` (its id and sequence are filled in) and returns the reply, whatever
    /// its result. Throws LinkError if no reply came after all attempts.
    ControlReplyPacket request(ControlRequestPacket request);

    // The same, throwing LinkError with the server's message unless the result is Ok.
    ServerStatus status();
    ServerStatus reset(std::uint64_t seed, const std::optional<Pose2>& start = std::nullopt);
    ServerStatus pause();
    ServerStatus resume();
    ServerStatus set_noise(const NoiseSettings& noise);
    ServerStatus teleport(const Pose2& pose);
    ServerStatus set_time_scale(double time_scale);

  private:
    ServerStatus checked(const ControlRequestPacket& request);

    Endpoint server_;
    UdpSocket socket_;
    std::chrono::milliseconds reply_timeout_;
    int attempts_;
    std::uint32_t next_request_id_ = 1;
    std::uint32_t next_sequence_ = 1;
};

}  // namespace legofeup::comms
