#include "legofeup/comms/udp_link.hpp"

#include <cmath>
#include <utility>

#include "legofeup/comms/link_error.hpp"

namespace legofeup::comms {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kConnectRetry{200};
/// Lockstep servers advance after 100 ms without an answer (docs/protocol.md).
constexpr std::chrono::microseconds kLockstepFrameTimeout{150'000};

std::chrono::microseconds default_frame_timeout(double control_period, double time_scale) {
    if (time_scale <= 0.0) {
        return kLockstepFrameTimeout;
    }
    const double seconds = 1.5 * control_period / time_scale;
    return std::chrono::microseconds(std::llround(seconds * 1e6));
}

}  // namespace

UdpSimulatorLink::UdpSimulatorLink(UdpLinkOptions options)
    : options_(options), socket_(client_endpoint_for(options.server)) {}

UdpSimulatorLink::~UdpSimulatorLink() {
    if (connected_) {
        disconnect();
    }
}

void UdpSimulatorLink::send_bare(PacketType type) {
    socket_.send_to(encode(BarePacket{type, next_session_sequence_++, last_frame_time_}),
                    options_.server);
}

void UdpSimulatorLink::connect() {
    const auto give_up = Clock::now() + options_.connect_timeout;
    while (Clock::now() < give_up) {
        send_bare(PacketType::Connect);
        const auto retry_at = std::min(Clock::now() + kConnectRetry, give_up);
        while (Clock::now() < retry_at) {
            const auto wait =
                std::chrono::duration_cast<std::chrono::microseconds>(retry_at - Clock::now());
            const auto datagram = socket_.receive(wait);
            if (!datagram || datagram->from != options_.server) {
                continue;
            }
            ConnectReplyPacket reply;
            if (decode(datagram->bytes, reply) != DecodeError::None) {
                continue;  // e.g. a frame that overtook the reply: frames come once we are in
            }
            if (reply.result == ConnectResult::Busy) {
                throw LinkError("the simulator at " + options_.server.to_string()
                                + " is driven by another client (" + reply.holder.to_string()
                                + "); stop it, or wait 3 s after it stopped");
            }
            connected_ = true;
            control_period_ = reply.control_period;
            time_scale_ = reply.time_scale;
            frame_timeout_ = options_.frame_timeout.value_or(
                default_frame_timeout(control_period_, time_scale_));
            frame_window_.restart();
            return;
        }
    }
    throw LinkError("no simulator answered at " + options_.server.to_string() + " within "
                    + std::to_string(options_.connect_timeout.count())
                    + " ms: is legofeup-sim running there?");
}

void UdpSimulatorLink::disconnect() {
    send_command(WheelSpeeds{});
    send_bare(PacketType::Disconnect);
    connected_ = false;
}

std::optional<FramePacket> UdpSimulatorLink::receive_frame(Clock::time_point deadline) {
    for (;;) {
        const auto left =
            std::chrono::duration_cast<std::chrono::microseconds>(deadline - Clock::now());
        const auto datagram = socket_.receive(std::max(left, std::chrono::microseconds(0)));
        if (!datagram) {
            return std::nullopt;
        }
        if (datagram->from != options_.server) {
            ++counters_.unexpected_peer;
            continue;
        }
        // A datagram cut to the buffer is longer than any packet: it decodes as oversized.
        FramePacket packet;
        if (decode(datagram->bytes, packet) != DecodeError::None) {
            ConnectReplyPacket late_reply;  // a repeated connect's reply is not malformed
            if (decode(datagram->bytes, late_reply) != DecodeError::None) {
                ++counters_.malformed;
            }
            continue;
        }
        if (frame_window_.classify(packet.frame.sequence) == Arrival::New) {
            return packet;
        }
        // Duplicate or late: counted in the window, never handed over.
    }
}

bool UdpSimulatorLink::await_reset(std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (const auto packet = receive_frame(deadline)) {
        if (packet->flags.reset) {
            pending_ = packet;
            return true;
        }
    }
    return false;
}

std::optional<SensorFrame> UdpSimulatorLink::next_frame() {
    std::optional<FramePacket> packet = std::exchange(pending_, std::nullopt);
    if (!packet) {
        packet = receive_frame(Clock::now() + frame_timeout_);
    }
    if (!packet) {
        ++counters_.timeouts;
        return std::nullopt;
    }
    last_flags_ = packet->flags;
    last_frame_time_ = packet->frame.time;
    return packet->frame;
}

void UdpSimulatorLink::send_command(const WheelSpeeds& command) {
    socket_.send_to(encode(CommandPacket{next_command_sequence_++, last_frame_time_, command}),
                    options_.server);
    ++counters_.commands_sent;
}

}  // namespace legofeup::comms
