#pragma once

// Whole numbers read from the JSON of shard files (docs/analysis.md), range-checked.
//
// nlohmann's get<int>() of a JSON number converts with a static_cast, and a cast of a
// floating-point value outside the target's range (a shard saying "count": 1e300) is
// undefined behaviour, found by fuzz_shard_file; a negative count read as std::size_t wraps
// round to a huge one. These readers take only JSON integers that fit the field and throw
// std::runtime_error naming the field and its value otherwise, which the shard reader turns
// into "damaged shard file: …".

#include <concepts>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace legofeup::lessons::analysis {

/// `value` as a T, when it is a JSON integer within T's range; `what` names it in the error.
template <std::integral T>
T json_integer(const nlohmann::json& value, const std::string& what) {
    if (value.is_number_unsigned()) {
        const auto number = value.get<std::uint64_t>();
        if (std::in_range<T>(number)) {
            return static_cast<T>(number);
        }
    } else if (value.is_number_integer()) {
        const auto number = value.get<std::int64_t>();
        if (std::in_range<T>(number)) {
            return static_cast<T>(number);
        }
    } else {
        throw std::runtime_error(what + " is " + value.dump() + ", not a whole number");
    }
    throw std::runtime_error(what + " is " + value.dump() + ", out of range");
}

/// The member `key` of `object` as a T (a missing key throws nlohmann's out_of_range).
template <std::integral T>
T json_integer_at(const nlohmann::json& object, const char* key) {
    return json_integer<T>(object.at(key), key);
}

}  // namespace legofeup::lessons::analysis
