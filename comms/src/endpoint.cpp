#include "legofeup/comms/endpoint.hpp"

#include <charconv>

#include "legofeup/comms/protocol.hpp"

namespace legofeup::comms {
namespace {

/// A decimal number in [0, max] that is all of `text` (no sign, no spaces, no leading '+').
std::optional<std::uint32_t> parse_number(std::string_view text, std::uint32_t max) {
    if (text.empty() || text.size() > 5) {
        return std::nullopt;
    }
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value > max) {
        return std::nullopt;
    }
    return value;
}

std::optional<std::uint32_t> parse_ipv4(std::string_view text) {
    std::uint32_t address = 0;
    for (int part = 0; part < 4; ++part) {
        const std::size_t dot = text.find('.');
        const bool last = part == 3;
        if (last != (dot == std::string_view::npos)) {
            return std::nullopt;
        }
        const auto octet = parse_number(last ? text : text.substr(0, dot), 255);
        if (!octet) {
            return std::nullopt;
        }
        address = (address << 8) | *octet;
        text = last ? std::string_view{} : text.substr(dot + 1);
    }
    return address;
}

}  // namespace

std::string Endpoint::to_string() const {
    return std::to_string((address >> 24) & 0xFF) + '.' + std::to_string((address >> 16) & 0xFF)
           + '.' + std::to_string((address >> 8) & 0xFF) + '.' + std::to_string(address & 0xFF)
           + ':' + std::to_string(port);
}

std::optional<Endpoint> parse_endpoint(std::string_view text, std::uint16_t default_port) {
    const std::size_t colon = text.find(':');
    const auto address = parse_ipv4(text.substr(0, colon));
    if (!address) {
        return std::nullopt;
    }
    if (colon == std::string_view::npos) {
        return Endpoint{*address, default_port};
    }
    const auto port = parse_number(text.substr(colon + 1), 65535);
    if (!port) {
        return std::nullopt;
    }
    return Endpoint{*address, static_cast<std::uint16_t>(*port)};
}

std::optional<Endpoint> parse_udp_url(std::string_view url) {
    constexpr std::string_view kScheme = "udp://";
    if (!url.starts_with(kScheme)) {
        return std::nullopt;
    }
    return parse_endpoint(url.substr(kScheme.size()), kDefaultRobotPort);
}

}  // namespace legofeup::comms
