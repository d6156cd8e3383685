// FNV-1a 64 of text: the hash the tests pin and compare traces by. For each byte b,
// h ← (h ⊕ b) · 1099511628211 mod 2⁶⁴, from h = 14695981039346656037 (Fowler, Noll, Vo).
#pragma once

#include <cstdint>
#include <string_view>

namespace legofeup::lessons::hash_testing {

inline std::uint64_t fnv1a_64(std::string_view text) {
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
    return hash;
}

}  // namespace legofeup::lessons::hash_testing
