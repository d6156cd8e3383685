#pragma once
// A test shim between a client and the simulator server's robot port that loses, duplicates
// and reorders packets on purpose, with a seeded generator, and counts what it did. Faults
// hit sensor frames (server → client) and wheel commands (client → server) only, so the
// handshake stays reliable and every injected fault is one the counters must see.
//
// Reordering holds one packet back and sends it right after the next packet that is sent:
// it arrives late (overtaken by a newer one), which both sides must count as late.

#include <atomic>
#include <cstdint>
#include <mutex>
#include <random>
#include <thread>

#include "legofeup/comms/protocol.hpp"
#include "legofeup/comms/udp_socket.hpp"

namespace legofeup::testing {

struct FaultRates {
    double drop = 0.0;
    double duplicate = 0.0;
    double reorder = 0.0;
};

struct FaultCounts {
    std::uint64_t forwarded = 0;  ///< packets of the faulted type that went through (once)
    std::uint64_t dropped = 0;
    std::uint64_t duplicated = 0;
    std::uint64_t reordered = 0;
};

class LossyRelay {
  public:
    /// Listens on a free loopback port and forwards to `server`.
    LossyRelay(const comms::Endpoint& server, std::uint64_t seed);
    ~LossyRelay();

    /// Where the client should connect.
    comms::Endpoint endpoint() const { return client_side_.local_endpoint(); }

    void set_rates(const FaultRates& to_server, const FaultRates& to_client);
    FaultCounts to_server_counts() const;  ///< wheel commands
    FaultCounts to_client_counts() const;  ///< sensor frames

  private:
    struct Direction {
        FaultRates rates;
        FaultCounts counts;
        comms::Bytes held;
    };
    void run(std::stop_token stop);
    void forward(Direction& direction, bool faulted, std::span<const std::uint8_t> bytes,
                 comms::UdpSocket& out, const comms::Endpoint& to);

    comms::Endpoint server_;
    comms::UdpSocket client_side_;
    comms::UdpSocket server_side_;
    comms::Endpoint client_{0, 0};
    mutable std::mutex mutex_;
    Direction to_server_;
    Direction to_client_;
    std::mt19937_64 random_;
    std::jthread thread_;
};

}  // namespace legofeup::testing
