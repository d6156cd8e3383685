#include "legofeup/comms/control_client.hpp"

#include "legofeup/comms/link_error.hpp"

namespace legofeup::comms {
namespace {

using Clock = std::chrono::steady_clock;

ControlRequestPacket make(ControlOp op) {
    ControlRequestPacket request;
    request.op = static_cast<std::uint8_t>(op);
    return request;
}

}  // namespace

ControlClient::ControlClient(const Endpoint& server, std::chrono::milliseconds reply_timeout,
                             int attempts)
    : server_(server),
      socket_(client_endpoint_for(server)),
      reply_timeout_(reply_timeout),
      attempts_(attempts) {}

ControlReplyPacket ControlClient::request(ControlRequestPacket request) {
    request.request_id = next_request_id_++;
    for (int attempt = 0; attempt < attempts_; ++attempt) {
        request.sequence = next_sequence_++;
        socket_.send_to(encode(request), server_);
        const auto give_up = Clock::now() + reply_timeout_;
        while (Clock::now() < give_up) {
            const auto wait =
                std::chrono::duration_cast<std::chrono::microseconds>(give_up - Clock::now());
            const auto datagram = socket_.receive(wait);
            ControlReplyPacket reply;
            if (datagram && datagram->from == server_
                && decode(datagram->bytes, reply) == DecodeError::None
                && reply.request_id == request.request_id) {
                return reply;
            }
        }
    }
    throw LinkError("no reply from the simulator at " + server_.to_string() + " after "
                    + std::to_string(attempts_) + " attempts: is legofeup-sim running there?");
}

ServerStatus ControlClient::checked(const ControlRequestPacket& request) {
    ControlReplyPacket reply = this->request(request);
    if (reply.result != ControlResult::Ok) {
        throw LinkError(
            "the simulator refused '" + std::string(to_string(static_cast<ControlOp>(request.op)))
            + "': "
            + (reply.message.empty() ? std::string(to_string(reply.result)) : reply.message));
    }
    return reply.status;
}

ServerStatus ControlClient::status() {
    return checked(make(ControlOp::Status));
}

ServerStatus ControlClient::reset(std::uint64_t seed, const std::optional<Pose2>& start) {
    ControlRequestPacket request = make(ControlOp::Reset);
    request.seed = seed;
    request.pose_given = start.has_value();
    request.pose = start.value_or(Pose2{});
    return checked(request);
}

ServerStatus ControlClient::pause() {
    return checked(make(ControlOp::Pause));
}

ServerStatus ControlClient::resume() {
    return checked(make(ControlOp::Resume));
}

ServerStatus ControlClient::set_noise(const NoiseSettings& noise) {
    ControlRequestPacket request = make(ControlOp::SetNoise);
    request.noise = noise;
    return checked(request);
}

ServerStatus ControlClient::teleport(const Pose2& pose) {
    ControlRequestPacket request = make(ControlOp::Teleport);
    request.pose = pose;
    return checked(request);
}

ServerStatus ControlClient::set_time_scale(double time_scale) {
    ControlRequestPacket request = make(ControlOp::SetTimeScale);
    request.time_scale = time_scale;
    return checked(request);
}

}  // namespace legofeup::comms
