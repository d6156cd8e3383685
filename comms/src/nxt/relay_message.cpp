#include "legofeup/comms/nxt/relay_message.hpp"

#include <array>
#include <charconv>
#include <string_view>

#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::comms::nxt {
namespace {

constexpr std::array<const char*, 7> kFieldNames = {
    "seq", "right_count", "left_count", "front_raw", "rear_raw", "valid_mask", "battery_mV"};
constexpr std::size_t kMaxRelayText = kMaxMessageSize - 1;

[[noreturn]] void refuse(std::string_view text, const std::string& why) {
    throw ReplyError("relay message '" + std::string(text) + "': " + why, std::nullopt);
}

/// One decimal field in [low, high]: digits with an optional leading '-', nothing else.
std::int64_t field_value(std::string_view text, std::string_view field, std::size_t index,
                         std::int64_t low, std::int64_t high) {
    const std::string name =
        "field " + std::to_string(index + 2) + " (" + kFieldNames.at(index) + ")";
    std::int64_t value = 0;
    const char* end = field.data() + field.size();
    const auto [stop, error] = std::from_chars(field.data(), end, value);
    if (field.empty() || error != std::errc() || stop != end || field.front() == '+') {
        refuse(text, name + " is not a whole number");
    }
    if (value < low || value > high) {
        refuse(text, name + " = " + std::string(field) + " is outside " + std::to_string(low)
                         + " … " + std::to_string(high));
    }
    return value;
}

}  // namespace

std::string format_relay_message(const RelayReading& r) {
    const int mask = (r.front_valid ? 1 : 0) | (r.rear_valid ? 2 : 0);
    return "L1 " + std::to_string(r.sequence) + ' ' + std::to_string(r.right_count) + ' '
           + std::to_string(r.left_count) + ' ' + std::to_string(r.front_raw) + ' '
           + std::to_string(r.rear_raw) + ' ' + std::to_string(mask) + ' '
           + std::to_string(r.battery_millivolts);
}

RelayReading parse_relay_message(std::span<const std::uint8_t> message) {
    std::size_t length = message.size();
    if (length > 0 && message[length - 1] == 0) {
        --length;  // the terminating NUL
    }
    const std::string_view text(reinterpret_cast<const char*>(message.data()), length);
    if (text.size() > kMaxRelayText) {
        refuse(text.substr(0, 20), std::to_string(text.size()) + " characters, at most "
                                       + std::to_string(kMaxRelayText));
    }
    if (text.find('\0') != std::string_view::npos) {
        refuse("", "a NUL inside the text");
    }
    if (!text.starts_with("L1 ")) {
        refuse(text, "does not start with 'L1 ' (is the relay program legofeup.rxe running?)");
    }
    std::array<std::string_view, kFieldNames.size()> fields;
    std::size_t start = 3;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        const std::size_t space = text.find(' ', start);
        const bool last = i + 1 == fields.size();
        if (last != (space == std::string_view::npos)) {
            refuse(text, "expected " + std::to_string(fields.size()) + " fields after 'L1'");
        }
        fields.at(i) = text.substr(start, last ? std::string_view::npos : space - start);
        start = space + 1;
    }
    constexpr std::int64_t kCountLimit = 2147483647;
    RelayReading reading;
    reading.sequence =
        static_cast<std::uint32_t>(field_value(text, fields[0], 0, 0, kRelaySequenceModulus - 1));
    reading.right_count =
        static_cast<std::int32_t>(field_value(text, fields[1], 1, -kCountLimit - 1, kCountLimit));
    reading.left_count =
        static_cast<std::int32_t>(field_value(text, fields[2], 2, -kCountLimit - 1, kCountLimit));
    reading.front_raw = static_cast<std::uint16_t>(field_value(text, fields[3], 3, 0, 1023));
    reading.rear_raw = static_cast<std::uint16_t>(field_value(text, fields[4], 4, 0, 1023));
    const auto mask = field_value(text, fields[5], 5, 0, 3);
    reading.front_valid = (mask & 1) != 0;
    reading.rear_valid = (mask & 2) != 0;
    reading.battery_millivolts =
        static_cast<std::uint16_t>(field_value(text, fields[6], 6, 0, 65535));
    return reading;
}

}  // namespace legofeup::comms::nxt
