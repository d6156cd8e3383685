#pragma once
// An IPv4 address and UDP port, as plain values (no socket headers leak out of comms).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace legofeup::comms {

/// 127.0.0.1 in host order: where every server of the project listens unless told otherwise.
inline constexpr std::uint32_t kLoopbackAddress = 0x7F000001;

struct Endpoint {
    std::uint32_t address = kLoopbackAddress;  ///< IPv4 in host order
    std::uint16_t port = 0;

    bool is_loopback() const { return (address >> 24) == 127; }
    std::string to_string() const;  ///< "127.0.0.1:5600"
    Endpoint with_port(std::uint16_t other_port) const { return {address, other_port}; }

    friend bool operator==(const Endpoint&, const Endpoint&) = default;
};

/// Where a client binds to reach `server`: a free port on loopback for a loopback server,
/// else on every interface.
inline Endpoint client_endpoint_for(const Endpoint& server) {
    return {server.is_loopback() ? server.address : 0, 0};
}

/// Parses "a.b.c.d:port" (port 0 … 65535) or, for the port alone, "a.b.c.d" with
/// `default_port`. Returns nullopt for anything else; names are not resolved.
std::optional<Endpoint> parse_endpoint(std::string_view text, std::uint16_t default_port);

/// Parses "udp://a.b.c.d:port" (the port defaults to the robot port 5600).
std::optional<Endpoint> parse_udp_url(std::string_view url);

}  // namespace legofeup::comms
