#include "support/lossy_relay.hpp"

#include <array>

#include "legofeup/comms/protocol.hpp"

namespace legofeup::testing {

using namespace std::chrono_literals;

LossyRelay::LossyRelay(const comms::Endpoint& server, std::uint64_t seed)
    : server_(server),
      client_side_(comms::Endpoint{0x7F000001, 0}),
      server_side_(comms::Endpoint{0x7F000001, 0}),
      random_(seed),
      thread_([this](std::stop_token stop) { run(std::move(stop)); }) {}

LossyRelay::~LossyRelay() {
    thread_.request_stop();
    thread_.join();
}

void LossyRelay::set_rates(const FaultRates& to_server, const FaultRates& to_client) {
    const std::scoped_lock lock(mutex_);
    to_server_.rates = to_server;
    to_client_.rates = to_client;
}

FaultCounts LossyRelay::to_server_counts() const {
    const std::scoped_lock lock(mutex_);
    return to_server_.counts;
}

FaultCounts LossyRelay::to_client_counts() const {
    const std::scoped_lock lock(mutex_);
    return to_client_.counts;
}

void LossyRelay::forward(Direction& direction, bool faulted, std::span<const std::uint8_t> bytes,
                         comms::UdpSocket& out, const comms::Endpoint& to) {
    if (!faulted) {
        out.send_to(bytes, to);
        return;
    }
    // One draw decides the packet's fate: drop | hold back | duplicate | pass.
    const FaultRates& rates = direction.rates;
    const double draw = std::uniform_real_distribution<double>(0.0, 1.0)(random_);
    if (draw < rates.drop) {
        ++direction.counts.dropped;
        return;
    }
    const bool reorder = draw < rates.drop + rates.reorder;
    if (reorder && direction.held.empty()) {
        direction.held.assign(bytes.begin(), bytes.end());  // goes out after the next one
        return;
    }
    out.send_to(bytes, to);
    ++direction.counts.forwarded;
    if (!reorder && draw < rates.drop + rates.reorder + rates.duplicate) {
        out.send_to(bytes, to);
        ++direction.counts.duplicated;
    }
    if (!direction.held.empty()) {
        out.send_to(direction.held, to);
        direction.held.clear();
        ++direction.counts.forwarded;
        ++direction.counts.reordered;
    }
}

void LossyRelay::run(std::stop_token stop) {
    const std::array<comms::UdpSocket*, 2> sockets{&client_side_, &server_side_};
    while (!stop.stop_requested()) {
        const std::vector<bool> readable = comms::wait_readable(sockets, 20ms);
        const std::scoped_lock lock(mutex_);
        while (readable[0]) {
            const auto datagram = client_side_.receive(0us);
            if (!datagram) {
                break;
            }
            // Only the first client's packets, and below only the server's: with tests in
            // parallel a port can be reused while another test's program still sends to it,
            // and a stray command relayed on would fill one of the injected gaps.
            if (client_.port == 0) {
                client_ = datagram->from;
            } else if (!(datagram->from == client_)) {
                continue;
            }
            comms::PacketHeader header;
            const bool command = decode_header(datagram->bytes, header) == comms::DecodeError::None
                                 && header.type == comms::PacketType::WheelCommand;
            forward(to_server_, command, datagram->bytes, server_side_, server_);
        }
        while (readable[1]) {
            const auto datagram = server_side_.receive(0us);
            if (!datagram) {
                break;
            }
            if (!(datagram->from == server_)) {
                continue;
            }
            comms::PacketHeader header;
            const bool frame = decode_header(datagram->bytes, header) == comms::DecodeError::None
                               && header.type == comms::PacketType::SensorFrame;
            forward(to_client_, frame, datagram->bytes, client_side_, client_);
        }
    }
}

}  // namespace legofeup::testing
