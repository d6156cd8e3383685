#pragma once
// Test-side byte writers for the UDP protocol's packets, independent of comms' own byte-order
// code, so that a test builds its packets from the layout in docs/protocol.md and not from
// the encoder it checks.

#include <gtest/gtest.h>

#include <bit>
#include <cstddef>
#include <cstdint>

#include "legofeup/comms/protocol.hpp"

namespace legofeup::comms::test_bytes {

/// Writes the `size` low bytes of `value` at `offset`, least significant first.
inline void put_le(Bytes& bytes, std::size_t offset, std::uint64_t value, std::size_t size) {
    ASSERT_LE(offset + size, bytes.size());
    for (std::size_t i = 0; i < size; ++i) {
        bytes[offset + i] = static_cast<std::uint8_t>((value >> (8 * i)) & 0xFF);
    }
}
inline void put_u16(Bytes& bytes, std::size_t offset, std::uint16_t value) {
    put_le(bytes, offset, value, 2);
}
inline void put_i16(Bytes& bytes, std::size_t offset, std::int16_t value) {
    put_le(bytes, offset, static_cast<std::uint16_t>(value), 2);
}
inline void put_u64(Bytes& bytes, std::size_t offset, std::uint64_t value) {
    put_le(bytes, offset, value, 8);
}
inline void put_f64(Bytes& bytes, std::size_t offset, double value) {
    put_u64(bytes, offset, std::bit_cast<std::uint64_t>(value));
}

}  // namespace legofeup::comms::test_bytes
