#pragma once
// Reading typed values out of toml++ nodes with the problems they cause. Private to lessons/.

#include <toml++/toml.h>
#include <optional>
#include <sstream>
#include <string>

#include "legofeup/core/state.hpp"

namespace legofeup::lessons {

inline int line_of(const toml::node& node) {
    return static_cast<int>(node.source().begin.line);
}

/// The node as the user wrote it (for messages); strings in double quotes.
inline std::string node_text(const toml::node& node) {
    if (const auto* text = node.as_string()) {
        return "\"" + text->get() + "\"";
    }
    std::ostringstream text;
    node.visit([&](const auto& value) { text << value; });
    return text.str();
}

inline std::optional<double> number_of(const toml::node& node) {
    if (const auto* real = node.as_floating_point()) {
        return real->get();
    }
    if (const auto* integer = node.as_integer()) {
        return static_cast<double>(integer->get());
    }
    return std::nullopt;
}

inline std::optional<Vector2> point_of(const toml::node& node) {
    const auto* array = node.as_array();
    if (array == nullptr || array->size() != 2) {
        return std::nullopt;
    }
    const toml::node* first = array->get(0);
    const toml::node* second = array->get(1);
    if (first == nullptr || second == nullptr) {
        return std::nullopt;
    }
    const auto x = number_of(*first);
    const auto y = number_of(*second);
    if (!x || !y) {
        return std::nullopt;
    }
    return Vector2(*x, *y);
}

/// The closest of `candidates` to `word` (edit distance ≤ 3), or "".
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace legofeup::lessons
