#pragma once
// The ground-truth stream (docs/protocol.md): subscribes to a simulator server's truth port
// and keeps what it hears, for displays and metrics. The filter never sees it.

#include <chrono>
#include <deque>
#include <optional>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/comms/sequence_window.hpp"
#include "legofeup/comms/udp_socket.hpp"
#include "legofeup/core/truth_source.hpp"

namespace legofeup::comms {

class TruthReceiver final : public TruthSource {
  public:
    /// `server` is the truth port. Subscribes at once; poll() renews the subscription.
    explicit TruthReceiver(const Endpoint& server);
    ~TruthReceiver() override;
    TruthReceiver(const TruthReceiver&) = delete;
    TruthReceiver& operator=(const TruthReceiver&) = delete;

    /// Reads what has arrived, waiting at most `timeout` for the first packet.
    void poll(std::chrono::microseconds timeout = std::chrono::microseconds(0));

    /// The truth at exactly `time` (to the microsecond) if it arrived, else the newest one
    /// before it; nullopt if none did. Only packets since the last reset count (times restart
    /// at 0 there). Polls first.
    std::optional<GroundTruth> truth_at(double time) override;
    std::optional<GroundTruth> latest() const;

    const SequenceCounts& counts() const { return window_.counts(); }
    std::uint64_t malformed() const { return malformed_; }

  private:
    void subscribe();

    Endpoint server_;
    UdpSocket socket_;
    SequenceWindow window_;
    std::deque<GroundTruth> recent_;  ///< the last kKeep, oldest first
    std::uint64_t malformed_ = 0;
    std::uint32_t next_sequence_ = 1;
    std::chrono::steady_clock::time_point renew_at_;
};

}  // namespace legofeup::comms
