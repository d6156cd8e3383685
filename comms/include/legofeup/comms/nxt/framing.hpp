#pragma once
// NXT Bluetooth framing: every telegram is preceded by its length as u16 little-endian (not
// counting the two length bytes). Reads take exactly 2 bytes, then exactly `length`.

#include "legofeup/comms/nxt/byte_stream.hpp"
#include "legofeup/comms/nxt/telegram.hpp"

namespace legofeup::comms::nxt {

/// The length prefix followed by the telegram. Throws std::invalid_argument when the
/// telegram is empty or longer than kMaxTelegramSize.
std::vector<std::uint8_t> frame_telegram(std::span<const std::uint8_t> telegram);

/// A length of 0 or above kMaxTelegramSize: the stream is out of step (or not an NXT).
class FramingError : public LinkError {
  public:
    using LinkError::LinkError;
};

void write_telegram(ByteStream& stream, std::span<const std::uint8_t> telegram);
/// Writes several telegrams in one write (one Bluetooth direction change for all of them).
void write_telegrams(ByteStream& stream, std::span<const Telegram> telegrams);
/// Reads one framed telegram. Throws FramingError, StreamTimeout or StreamClosed.
Telegram read_telegram(ByteStream& stream, ByteStream::Clock::time_point deadline);

}  // namespace legofeup::comms::nxt
