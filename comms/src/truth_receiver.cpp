#include "legofeup/comms/truth_receiver.hpp"

namespace legofeup::comms {
namespace {

constexpr std::size_t kKeep = 64;
/// Subscriptions lapse after 5 s; renewing every second survives a few lost renewals.
constexpr std::chrono::seconds kRenewEvery{1};

}  // namespace

TruthReceiver::TruthReceiver(const Endpoint& server)
    : server_(server), socket_(client_endpoint_for(server)) {
    subscribe();
}

TruthReceiver::~TruthReceiver() {
    socket_.send_to(encode(BarePacket{PacketType::TruthUnsubscribe, next_sequence_++, 0.0}),
                    server_);
}

void TruthReceiver::subscribe() {
    socket_.send_to(encode(BarePacket{PacketType::TruthSubscribe, next_sequence_++, 0.0}), server_);
    renew_at_ = std::chrono::steady_clock::now() + kRenewEvery;
}

void TruthReceiver::poll(std::chrono::microseconds timeout) {
    if (std::chrono::steady_clock::now() >= renew_at_) {
        subscribe();
    }
    for (auto datagram = socket_.receive(timeout); datagram;
         datagram = socket_.receive(std::chrono::microseconds(0))) {
        TruthPacket packet;
        if (datagram->from != server_ || decode(datagram->bytes, packet) != DecodeError::None) {
            ++malformed_;
            continue;
        }
        if (window_.classify(packet.sequence) != Arrival::New) {
            continue;
        }
        recent_.push_back(packet.truth);
        if (recent_.size() > kKeep) {
            recent_.pop_front();
        }
    }
}

std::optional<GroundTruth> TruthReceiver::truth_at(double time) {
    poll();
    const std::uint64_t wanted = to_microseconds(time);
    // Newest first. Since the last reset the times only go up (equal times: the newer packet
    // wins, as after a reset at time 0 or a subscription's first packet); a time that goes up
    // walking back belongs to the run before a reset, whose times may repeat this run's.
    std::optional<std::uint64_t> newer;
    for (auto it = recent_.rbegin(); it != recent_.rend(); ++it) {
        const std::uint64_t t = to_microseconds(it->time);
        if (newer && t > *newer) {
            break;
        }
        if (t <= wanted) {
            return *it;
        }
        newer = t;
    }
    return std::nullopt;
}

std::optional<GroundTruth> TruthReceiver::latest() const {
    if (recent_.empty()) {
        return std::nullopt;
    }
    return recent_.back();
}

}  // namespace legofeup::comms
