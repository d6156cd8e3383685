#pragma once
// Splitting and reading the plain-text fields of calibration inputs (CSV lines, "x,y;x,y"
// option values). Private to lessons/.

#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace legofeup::lessons {

inline std::string_view trimmed(std::string_view text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = text.find_last_not_of(" \t\r");
    return text.substr(first, last - first + 1);
}

/// The trimmed pieces of `text` between `separator`s ("a, b" → {"a", "b"}).
inline std::vector<std::string_view> split_fields(std::string_view text, char separator) {
    std::vector<std::string_view> fields;
    std::size_t begin = 0;
    while (true) {
        const std::size_t end = text.find(separator, begin);
        fields.push_back(trimmed(text.substr(begin, end - begin)));
        if (end == std::string_view::npos) {
            return fields;
        }
        begin = end + 1;
    }
}

/// The whole of `text` as a number (nan and inf included; callers check finiteness).
inline std::optional<double> parse_number(std::string_view text) {
    double value = 0.0;
    if (!text.empty() && text.front() == '+') {
        text.remove_prefix(1);
    }
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end) {
        return std::nullopt;
    }
    return value;
}

}  // namespace legofeup::lessons
