// libFuzzer target for the protocol's decoders (docs/protocol.md). One source, built once
// per decoder: LEGOFEUP_FUZZ_PACKET names the packet struct whose decode() is fuzzed.
// Whatever the bytes, decoding must return (no crash, no sanitizer report, no hang), and a
// packet that decodes must encode back to exactly the bytes it came from, apart from the
// fields the decoder is documented to ignore (reserved bytes and the unused arguments of a
// control request).

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>

#include "legofeup/comms/protocol.hpp"

namespace {

using legofeup::comms::DecodeError;

template <typename Packet>
void fuzz_one(std::span<const std::uint8_t> bytes) {
    Packet packet;
    if (legofeup::comms::decode(bytes, packet) != DecodeError::None) {
        return;
    }
    // Round trip: what decoded must encode to a packet that decodes to the same encoding.
    const legofeup::comms::Bytes encoded = legofeup::comms::encode(packet);
    Packet again;
    if (legofeup::comms::decode(encoded, again) != DecodeError::None
        || legofeup::comms::encode(again) != encoded || encoded.size() != bytes.size()) {
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz_one<legofeup::comms::LEGOFEUP_FUZZ_PACKET>(std::span<const std::uint8_t>(data, size));
    return 0;
}
