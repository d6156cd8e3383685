#pragma once
// Little-endian reading and writing at fixed offsets, independent of the host's byte order.
// The protocol's layouts are offsets into a buffer whose size was checked before any read.

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace legofeup::comms::detail {

/// The longest prefix of `text` of at most `max_bytes` bytes that does not end inside a UTF-8
/// character: the cut moves back over continuation bytes (0b10xxxxxx), which never start a
/// character, to the first byte of the character that would not fit. A character has at most
/// three continuation bytes, so the cut moves back at most three (text that is not UTF-8 is
/// cut there whatever it holds).
inline std::string_view utf8_prefix(std::string_view text, std::size_t max_bytes) {
    if (text.size() <= max_bytes) {
        return text;
    }
    const auto continues_a_character = [&](std::size_t i) {
        return (static_cast<unsigned char>(text[i]) & 0xC0U) == 0x80U;
    };
    std::size_t cut = max_bytes;
    while (cut > 0 && max_bytes - cut < 3 && continues_a_character(cut)) {
        --cut;
    }
    return text.substr(0, cut);
}

class ByteWriter {
  public:
    explicit ByteWriter(std::size_t size) : bytes_(size, 0) {}

    void u8(std::size_t offset, std::uint8_t value) { bytes_.at(offset) = value; }
    void u16(std::size_t offset, std::uint16_t value) { unsigned_le(offset, value, 2); }
    void u32(std::size_t offset, std::uint32_t value) { unsigned_le(offset, value, 4); }
    void u64(std::size_t offset, std::uint64_t value) { unsigned_le(offset, value, 8); }
    void i16(std::size_t offset, std::int16_t value) {
        u16(offset, std::bit_cast<std::uint16_t>(value));
    }
    void i32(std::size_t offset, std::int32_t value) {
        u32(offset, std::bit_cast<std::uint32_t>(value));
    }
    void f64(std::size_t offset, double value) { u64(offset, std::bit_cast<std::uint64_t>(value)); }
    /// Bytes of `text` followed by NULs up to `size`. A text longer than size − 1 bytes is
    /// cut at the last UTF-8 character boundary that fits, so a multi-byte character is
    /// either sent whole or not at all (docs/protocol.md, "Encoding").
    void text(std::size_t offset, std::string_view text, std::size_t size) {
        const std::string_view fitting = utf8_prefix(text, size - 1);
        std::memcpy(bytes_.data() + offset, fitting.data(), fitting.size());
    }

    std::vector<std::uint8_t> take() { return std::move(bytes_); }

  private:
    void unsigned_le(std::size_t offset, std::uint64_t value, int size) {
        for (int i = 0; i < size; ++i) {
            bytes_.at(offset + static_cast<std::size_t>(i)) =
                static_cast<std::uint8_t>(value >> (8 * i));
        }
    }

    std::vector<std::uint8_t> bytes_;
};

class ByteReader {
  public:
    explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

    std::uint8_t u8(std::size_t offset) const { return bytes_[offset]; }
    std::uint16_t u16(std::size_t offset) const {
        return static_cast<std::uint16_t>(unsigned_le(offset, 2));
    }
    std::uint32_t u32(std::size_t offset) const {
        return static_cast<std::uint32_t>(unsigned_le(offset, 4));
    }
    std::uint64_t u64(std::size_t offset) const { return unsigned_le(offset, 8); }
    std::int16_t i16(std::size_t offset) const { return std::bit_cast<std::int16_t>(u16(offset)); }
    std::int32_t i32(std::size_t offset) const { return std::bit_cast<std::int32_t>(u32(offset)); }
    double f64(std::size_t offset) const { return std::bit_cast<double>(u64(offset)); }
    /// The bytes up to the first NUL within `size`.
    std::string text(std::size_t offset, std::size_t size) const {
        const auto* begin = reinterpret_cast<const char*>(bytes_.data() + offset);
        return std::string(begin, strnlen(begin, size));
    }

  private:
    std::uint64_t unsigned_le(std::size_t offset, int size) const {
        std::uint64_t value = 0;
        for (int i = size - 1; i >= 0; --i) {
            value = (value << 8) | bytes_[offset + static_cast<std::size_t>(i)];
        }
        return value;
    }

    std::span<const std::uint8_t> bytes_;
};

}  // namespace legofeup::comms::detail
