#pragma once
// The message the on-brick relay program (resources/nxt/legofeup_relay.nxc) leaves in its
// response mailbox every 10 ms, read by the host with one MESSAGEREAD per cycle:
//
//   "L1 <seq> <right_count> <left_count> <front_raw> <rear_raw> <valid_mask> <battery_mV>"
//
// ASCII, single spaces, decimal, NUL-terminated, at most 58 characters. seq counts messages
// modulo 1000000; the counts are the wheel motors' RotationCount (1 count = 1°); the raws
// are the IR sensors' 10-bit A/D values; valid_mask bit 0 = front valid, bit 1 = rear valid.

#include <cstdint>
#include <span>
#include <string>

namespace legofeup::comms::nxt {

struct RelayReading {
    std::uint32_t sequence = 0;  ///< 0 … 999999
    std::int32_t right_count = 0;
    std::int32_t left_count = 0;
    std::uint16_t front_raw = 0;  ///< 0 … 1023
    std::uint16_t rear_raw = 0;
    bool front_valid = false;
    bool rear_valid = false;
    std::uint16_t battery_millivolts = 0;
    bool operator==(const RelayReading&) const = default;
};

inline constexpr std::uint32_t kRelaySequenceModulus = 1'000'000;

/// The message text (without the NUL).
std::string format_relay_message(const RelayReading& reading);

/// Parses a mailbox message (with or without its terminating NUL). Throws ReplyError
/// ("relay message 'L1 4 x …': field 3 (right_count) is not a number") for anything that is
/// not exactly the format above.
RelayReading parse_relay_message(std::span<const std::uint8_t> message);

}  // namespace legofeup::comms::nxt
