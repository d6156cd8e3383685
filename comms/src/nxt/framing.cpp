// The NXT's Bluetooth framing: u16 little-endian length, then the telegram. A byte stream
// splits and joins writes as it likes, so a read takes exactly the 2 length bytes and then
// exactly that many — never "whatever one recv() returned".

#include "legofeup/comms/nxt/framing.hpp"

#include <stdexcept>
#include <string>

#include "../byte_order.hpp"

namespace legofeup::comms::nxt {
namespace {

constexpr std::size_t kLengthSize = 2;

void append_frame(std::vector<std::uint8_t>& out, std::span<const std::uint8_t> telegram) {
    if (telegram.empty() || telegram.size() > kMaxTelegramSize) {
        throw std::invalid_argument("NXT telegram of " + std::to_string(telegram.size())
                                    + " bytes cannot be framed: expected 1..64");
    }
    const auto length = static_cast<std::uint16_t>(telegram.size());
    out.push_back(static_cast<std::uint8_t>(length & 0xFF));
    out.push_back(static_cast<std::uint8_t>(length >> 8));
    out.insert(out.end(), telegram.begin(), telegram.end());
}

}  // namespace

std::vector<std::uint8_t> frame_telegram(std::span<const std::uint8_t> telegram) {
    std::vector<std::uint8_t> frame;
    frame.reserve(kLengthSize + telegram.size());
    append_frame(frame, telegram);
    return frame;
}

void write_telegram(ByteStream& stream, std::span<const std::uint8_t> telegram) {
    stream.write_all(frame_telegram(telegram));
}

void write_telegrams(ByteStream& stream, std::span<const Telegram> telegrams) {
    std::vector<std::uint8_t> frames;
    for (const Telegram& telegram : telegrams) {
        append_frame(frames, telegram);  // all checked before any byte is sent
    }
    if (!frames.empty()) {
        stream.write_all(frames);
    }
}

Telegram read_telegram(ByteStream& stream, ByteStream::Clock::time_point deadline) {
    std::array<std::uint8_t, kLengthSize> prefix{};
    stream.read_exact(prefix, deadline);
    const std::uint16_t length = comms::detail::ByteReader(prefix).u16(0);
    if (length == 0 || length > kMaxTelegramSize) {
        throw FramingError(stream.describe() + ": frame length " + std::to_string(length)
                           + ", expected 1..64 — the stream is out of step, or the other end "
                             "is not an NXT brick");
    }
    Telegram telegram(length);
    stream.read_exact(telegram, deadline);
    return telegram;
}

}  // namespace legofeup::comms::nxt
