// Addresses of a brick as a user types them: bt:XX:XX:XX:XX:XX:XX, serial:/dev/rfcomm0,
// tcp:HOST:PORT. Every refusal quotes the text, says what is wrong and shows the form
// expected, because this is usually the first thing a student gets wrong.

#include <cctype>
#include <charconv>
#include <stdexcept>
#include <string_view>

#include "legofeup/comms/nxt/transport.hpp"

namespace legofeup::comms::nxt {
namespace {

constexpr std::string_view kBtForm = "bt:XX:XX:XX:XX:XX:XX";
constexpr std::string_view kForms =
    "expected bt:XX:XX:XX:XX:XX:XX, serial:/dev/rfcomm0 or tcp:HOST:PORT";

[[noreturn]] void refuse(const std::string& text, const std::string& problem) {
    throw std::invalid_argument(text + ": " + problem);
}

bool is_hex(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}

/// "00:16:53:01:02:03": six hex pairs separated by colons; returned in upper case.
std::string parse_bluetooth(const std::string& text, std::string_view address) {
    constexpr std::size_t kLength = 17;  // 6 pairs and 5 colons
    for (std::size_t i = 0; i < address.size() && i < kLength; ++i) {
        const char c = address[i];
        const bool colon_here = i % 3 == 2;
        if (colon_here && c != ':') {
            refuse(text, "'" + std::string(1, c) + "' where a ':' belongs; expected "
                             + std::string(kBtForm));
        }
        if (!colon_here && !is_hex(c)) {
            refuse(text, "'" + std::string(1, c) + "' is not a hex digit; expected "
                             + std::string(kBtForm));
        }
    }
    if (address.size() != kLength) {
        refuse(text, "a Bluetooth address has 6 bytes; expected " + std::string(kBtForm)
                         + " (an NXT's starts 00:16:53)");
    }
    std::string upper(address);
    for (char& c : upper) {
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return upper;
}

TransportAddress parse_tcp(const std::string& text, std::string_view rest) {
    const std::size_t colon = rest.rfind(':');
    if (colon == std::string_view::npos) {
        refuse(text, "no port; expected tcp:HOST:PORT, e.g. tcp:127.0.0.1:7000");
    }
    const std::string_view host = rest.substr(0, colon);
    const std::string_view port_text = rest.substr(colon + 1);
    if (host.empty()) {
        refuse(text, "no host; expected tcp:HOST:PORT, e.g. tcp:127.0.0.1:7000");
    }
    unsigned port = 0;
    const auto [end, error] =
        std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
    const bool digits_only = !port_text.empty() && end == port_text.data() + port_text.size()
                             && (error == std::errc{} || error == std::errc::result_out_of_range);
    if (!digits_only) {
        refuse(text,
               "port '" + std::string(port_text) + "' is not a number; expected tcp:HOST:PORT");
    }
    if (error != std::errc{} || port == 0 || port > 65535) {
        refuse(text, "port " + std::string(port_text) + " is not in 1..65535");
    }
    return {TransportKind::Tcp, std::string(host), static_cast<std::uint16_t>(port)};
}

/// Text with no known prefix: which prefix it probably lacks ("" when no guess).
std::string guess_prefix(const std::string& text) {
    if (text.front() == '/') {
        return "; for a device write serial:" + text;
    }
    if (text.size() == 17 && text[2] == ':' && is_hex(text[0]) && is_hex(text[1])) {
        return "; for a Bluetooth address write bt:" + text;
    }
    const std::size_t colon = text.rfind(':');
    const std::string host = text.substr(0, colon == std::string::npos ? 0 : colon);
    const bool looks_like_host = host.find('/') == std::string::npos
                                 && (host == "localhost" || host.find('.') != std::string::npos);
    if (looks_like_host && colon + 1 < text.size()
        && text.find_first_not_of("0123456789", colon + 1) == std::string::npos) {
        return "; for a host and port write tcp:" + text;
    }
    return "";
}

}  // namespace

std::string TransportAddress::to_string() const {
    switch (kind) {
        case TransportKind::Bluetooth:
            return "bt:" + target;
        case TransportKind::Serial:
            return "serial:" + target;
        case TransportKind::Tcp:
            break;
    }
    return "tcp:" + target + ":" + std::to_string(port);
}

TransportAddress parse_transport_address(const std::string& text) {
    if (text.empty()) {
        throw std::invalid_argument("empty brick address; " + std::string(kForms));
    }
    const std::size_t colon = text.find(':');
    const std::string scheme = colon == std::string::npos ? "" : text.substr(0, colon);
    const std::string_view rest =
        colon == std::string::npos ? std::string_view{} : std::string_view(text).substr(colon + 1);
    if (scheme == "bt") {
        return {TransportKind::Bluetooth, parse_bluetooth(text, rest), 0};
    }
    if (scheme == "serial") {
        if (rest.empty()) {
            refuse(text, "no device path; expected serial:/dev/rfcomm0 (or another tty)");
        }
        return {TransportKind::Serial, std::string(rest), 0};
    }
    if (scheme == "tcp") {
        return parse_tcp(text, rest);
    }
    const std::string guess = guess_prefix(text);
    if (colon == std::string::npos || !guess.empty()) {
        refuse(text, "no transport prefix; " + std::string(kForms) + guess);
    }
    refuse(text, "unknown transport '" + scheme + "'; " + std::string(kForms));
}

}  // namespace legofeup::comms::nxt
