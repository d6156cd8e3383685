// The sensor frame's optional extension block (docs/protocol.md, "SensorFrame extension"):
// the layout worked out by hand, round trips of every field at its extremes (the laser scan
// included), the plain 36-byte frame unchanged, and every malformed extension rejected with
// its error and reason.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "legofeup/comms/protocol.hpp"
#include "protocol_bytes_test_support.hpp"

namespace legofeup::comms {
namespace {

using namespace test_bytes;

/// Bit-for-bit equality of every field of two frames (−0.0 and NaN payloads included).
void expect_same_frame(const SensorFrame& actual, const SensorFrame& expected) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(actual.time),
              std::bit_cast<std::uint64_t>(expected.time));
    EXPECT_EQ(actual.sequence, expected.sequence);
    EXPECT_EQ(actual.encoder_counts, expected.encoder_counts);
    EXPECT_EQ(actual.ir_adc, expected.ir_adc);
    EXPECT_EQ(actual.ir_valid, expected.ir_valid);
    EXPECT_EQ(actual.has_gyro, expected.has_gyro);
    EXPECT_EQ(actual.gyro_raw, expected.gyro_raw);
    EXPECT_EQ(actual.has_accelerometers, expected.has_accelerometers);
    EXPECT_EQ(actual.accel_raw, expected.accel_raw);
    EXPECT_EQ(actual.has_compass, expected.has_compass);
    EXPECT_EQ(actual.compass_deg, expected.compass_deg);
    EXPECT_EQ(actual.has_beacon_scan, expected.has_beacon_scan);
    EXPECT_EQ(actual.has_laser_scan, expected.has_laser_scan);
    EXPECT_EQ(actual.laser, expected.laser);  // beam count and all kMaxScanBeams entries
    ASSERT_EQ(actual.beacons.count, expected.beacons.count);
    for (std::size_t k = 0; k < kMaxBeaconSightings; ++k) {
        EXPECT_EQ(actual.beacons.sightings[k].id, expected.beacons.sightings[k].id) << k;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(actual.beacons.sightings[k].bearing),
                  std::bit_cast<std::uint64_t>(expected.beacons.sightings[k].bearing))
            << "sighting " << k;
    }
}

SensorFrame plain_frame() {
    SensorFrame frame;
    frame.time = 1.25;
    frame.sequence = 0x01020304;
    frame.encoder_counts = {360, -1};
    frame.ir_adc = {512, 1023};
    frame.ir_valid = {true, false};
    return frame;
}

/// Every optional sensor, at the extremes of its type, with all eight sightings.
SensorFrame full_frame() {
    SensorFrame frame = plain_frame();
    frame.has_gyro = true;
    frame.gyro_raw = std::numeric_limits<std::int16_t>::min();
    frame.has_accelerometers = true;
    frame.accel_raw = {{{std::numeric_limits<std::int16_t>::max(), -1}, {0, -200}}};
    frame.has_compass = true;
    frame.compass_deg = 359;
    frame.has_beacon_scan = true;
    frame.beacons.count = kMaxBeaconSightings;
    const std::array<double, kMaxBeaconSightings> bearings{
        std::numbers::pi,
        -std::numbers::pi,
        -0.0,
        0.0,
        std::numeric_limits<double>::denorm_min(),
        0.1,
        -1.2345678901234567,
        std::nextafter(std::numbers::pi, 0.0)};
    for (std::size_t k = 0; k < kMaxBeaconSightings; ++k) {
        frame.beacons.sightings[k] = {static_cast<std::uint8_t>(k == 0 ? 255 : k), bearings[k]};
    }
    return frame;
}

/// A scan of `beams` beams whose ranges run through every kind of value: the error codes,
/// other values below 20, the shortest distance, everyday ones and the largest u16.
LaserScan laser_scan(std::uint16_t beams) {
    LaserScan scan;
    scan.beam_count = beams;
    for (std::size_t i = 0; i < beams; ++i) {
        scan.range_mm[i] = static_cast<std::uint16_t>(i < 22 ? i : 20 + 97 * i);
    }
    scan.range_mm[beams - 1] = 0xFFFF;
    return scan;
}

FramePacket decoded_or_fail(const Bytes& bytes) {
    FramePacket packet;
    std::string reason;
    EXPECT_EQ(decode(bytes, packet, reason), DecodeError::None) << reason;
    EXPECT_TRUE(reason.empty()) << reason;
    return packet;
}

TEST(ProtocolFrameExtension, SizesFollowTheBeaconCount) {
    EXPECT_EQ(frame_size(plain_frame()), 36U);
    SensorFrame frame = plain_frame();
    frame.has_compass = true;
    EXPECT_EQ(frame_size(frame), 52U);
    frame.has_beacon_scan = true;
    frame.beacons.count = 3;
    EXPECT_EQ(frame_size(frame), 52U + 27U);
    frame.beacons.count = 200;  // more than a frame can hold: only the first eight travel
    EXPECT_EQ(frame_size(frame), 124U);
    frame.has_laser_scan = true;
    frame.laser.beam_count = 682;
    EXPECT_EQ(frame_size(frame), 124U + 1364U);
    frame.laser.beam_count = 5000;  // more than a scan holds: only the first 1024 travel
    EXPECT_EQ(frame_size(frame), 124U + 2048U);
    EXPECT_EQ(frame_size(frame), kMaxPacketSize);
    EXPECT_EQ(kMaxPacketSize, 2172U);
    frame.has_beacon_scan = false;  // the beacon count no longer counts
    frame.laser.beam_count = 682;
    EXPECT_EQ(frame_size(frame), 52U + 1364U);

    // Every 52 + 9n + 2m, listed the long way.
    std::set<std::size_t> valid{36};
    for (std::size_t n = 0; n <= 8; ++n) {
        for (std::size_t m = 0; m <= 1024; ++m) {
            valid.insert(52 + 9 * n + 2 * m);
        }
    }
    for (std::size_t length = 0; length <= kMaxPacketSize + 10; ++length) {
        EXPECT_EQ(is_valid_length(PacketType::SensorFrame, length), valid.count(length) == 1)
            << length;
        EXPECT_EQ(is_valid_length(PacketType::WheelCommand, length), length == 36) << length;
    }
}

TEST(ProtocolFrameExtension, AFrameWithoutExtrasIsThePlainThirtySixBytes) {
    // Values in the fields of absent sensors do not travel: the bytes are those of the frame
    // without them, 36 long, the extension never started.
    FramePacket bare{plain_frame(), {true, false, true}};
    FramePacket with_junk = bare;
    with_junk.frame.gyro_raw = 77;
    with_junk.frame.accel_raw = {{{1, 2}, {3, 4}}};
    with_junk.frame.compass_deg = 90;
    with_junk.frame.beacons.count = 2;
    with_junk.frame.beacons.sightings[0] = {4, 1.0};
    with_junk.frame.laser.beam_count = 682;
    with_junk.frame.laser.range_mm[0] = 1234;
    const Bytes bytes = encode(with_junk);
    ASSERT_EQ(bytes.size(), 36U);
    EXPECT_EQ(bytes, encode(bare));
    EXPECT_EQ(bytes[6], 36);  // the length field

    const FramePacket decoded = decoded_or_fail(bytes);
    expect_same_frame(decoded.frame, bare.frame);
    EXPECT_FALSE(decoded.frame.has_gyro || decoded.frame.has_accelerometers
                 || decoded.frame.has_compass || decoded.frame.has_beacon_scan
                 || decoded.frame.has_laser_scan);
}

TEST(ProtocolFrameExtension, AFrameWithoutALaserScanIsByteIdenticalToBefore) {
    // The documented extended example (written before the laser existed), with a stale scan
    // in the frame that does not travel: the same 70 bytes, offset 50 still 0.
    FramePacket packet;
    packet.frame.time = 22.45;
    packet.frame.sequence = 452;
    packet.frame.encoder_counts = {5417, 5199};
    packet.frame.ir_adc = {177, 31};
    packet.frame.ir_valid = {true, true};
    packet.frame.has_gyro = true;
    packet.frame.gyro_raw = 597;
    packet.frame.has_compass = true;
    packet.frame.compass_deg = 271;
    packet.frame.has_beacon_scan = true;
    packet.frame.beacons.count = 2;
    packet.frame.beacons.sightings[0] = {1, 0.75};
    packet.frame.beacons.sightings[1] = {4, -2.5};
    packet.frame.laser.beam_count = 3;
    packet.frame.laser.range_mm = {100, 200, 300};
    const Bytes bytes = encode(packet);
    ASSERT_EQ(bytes.size(), 70U);
    EXPECT_EQ(bytes[36], 0x0D);
    EXPECT_EQ(bytes[50], 0);
    EXPECT_EQ(bytes[51], 0);
    EXPECT_FALSE(decoded_or_fail(bytes).frame.has_laser_scan);
    EXPECT_EQ(decoded_or_fail(bytes).frame.laser, LaserScan{});
}

TEST(ProtocolFrameExtension, LayoutWorkedOutByHand) {
    SensorFrame frame = plain_frame();
    frame.has_gyro = true;
    frame.gyro_raw = -5;
    frame.has_accelerometers = true;
    frame.accel_raw = {{{200, -3}, {-32768, 32767}}};
    frame.has_compass = true;
    frame.compass_deg = 359;
    frame.has_beacon_scan = true;
    frame.beacons.count = 2;
    frame.beacons.sightings[0] = {3, -std::numbers::pi};
    frame.beacons.sightings[1] = {200, 1.5};
    const FramePacket packet{frame, {}};

    // The plain frame with the new length, then the block of docs/protocol.md.
    Bytes expected = encode(FramePacket{plain_frame(), {}});
    ASSERT_EQ(expected.size(), 36U);
    expected.resize(52 + 2 * 9, 0);
    put_le(expected, 6, 70, 2);  // length
    expected[36] = 0x0F;         // gyro | accelerometers | compass | beacon scan
    expected[37] = 2;            // beacon count
    const std::vector<std::uint8_t> fixed{
        0xFB, 0xFF,  // gyro −5
        0xC8, 0x00,  // accel right forward 200
        0xFD, 0xFF,  // accel right left −3
        0x00, 0x80,  // accel left forward −32768
        0xFF, 0x7F,  // accel left left 32767
        0x67, 0x01,  // compass 359
        0x00, 0x00,  // reserved
    };
    std::copy(fixed.begin(), fixed.end(), expected.begin() + 38);
    expected[52] = 3;
    // −π = 0xC00921FB54442D18
    const std::vector<std::uint8_t> minus_pi{0x18, 0x2D, 0x44, 0x54, 0xFB, 0x21, 0x09, 0xC0};
    std::copy(minus_pi.begin(), minus_pi.end(), expected.begin() + 53);
    expected[61] = 200;
    put_f64(expected, 62, 1.5);
    EXPECT_EQ(expected[62 + 7], 0x3F);  // 1.5 = 0x3FF8000000000000
    EXPECT_EQ(expected[62 + 6], 0xF8);

    EXPECT_EQ(encode(packet), expected);
    expect_same_frame(decoded_or_fail(expected).frame, frame);
}

TEST(ProtocolFrameExtension, TheDocumentedExtendedExampleIsWhatTheEncoderWrites) {
    // docs/protocol.md, "Example datagrams": the second sensor frame, copied from there.
    const Bytes documented{0x4c, 0x46, 0x55, 0x50, 0x01, 0x01, 0x46, 0x00, 0xc4, 0x01, 0x00, 0x00,
                           0x50, 0x8f, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00, 0x29, 0x15, 0x00, 0x00,
                           0x4f, 0x14, 0x00, 0x00, 0xb1, 0x00, 0x1f, 0x00, 0x03, 0x00, 0x00, 0x00,
                           0x0d, 0x02, 0x55, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                           0x0f, 0x01, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xe8,
                           0x3f, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0xc0};
    FramePacket packet;
    packet.frame.time = 22.45;
    packet.frame.sequence = 452;
    packet.frame.encoder_counts = {5417, 5199};
    packet.frame.ir_adc = {177, 31};
    packet.frame.ir_valid = {true, true};
    packet.frame.has_gyro = true;
    packet.frame.gyro_raw = 597;
    packet.frame.has_compass = true;
    packet.frame.compass_deg = 271;
    packet.frame.has_beacon_scan = true;
    packet.frame.beacons.count = 2;
    packet.frame.beacons.sightings[0] = {1, 0.75};
    packet.frame.beacons.sightings[1] = {4, -2.5};
    EXPECT_EQ(encode(packet), documented);
    expect_same_frame(decoded_or_fail(documented).frame, packet.frame);
}

TEST(ProtocolFrameExtension, EveryFieldRoundTripsAtItsExtremes) {
    const SensorFrame full = full_frame();
    const Bytes bytes = encode(FramePacket{full, {false, true, false}});
    ASSERT_EQ(bytes.size(), 124U);
    const FramePacket decoded = decoded_or_fail(bytes);
    expect_same_frame(decoded.frame, full);
    EXPECT_TRUE(decoded.flags.paused);
    EXPECT_FALSE(decoded.flags.watchdog_stopped);
}

TEST(ProtocolFrameExtension, EachSensorAloneRoundTripsAndLeavesTheOthersZero) {
    const SensorFrame full = full_frame();
    const LaserScan scan = laser_scan(682);
    for (int which = 0; which < 5; ++which) {
        SensorFrame frame = plain_frame();
        frame.has_gyro = which == 0;
        frame.has_accelerometers = which == 1;
        frame.has_compass = which == 2;
        frame.has_beacon_scan = which == 3;
        frame.has_laser_scan = which == 4;
        frame.gyro_raw = full.gyro_raw;
        frame.accel_raw = full.accel_raw;
        frame.compass_deg = full.compass_deg;
        frame.beacons = full.beacons;
        frame.laser = scan;
        const Bytes bytes = encode(FramePacket{frame, {}});
        EXPECT_EQ(bytes[36], 1U << which) << which;
        EXPECT_EQ(bytes.size(), which == 3 ? 124U : (which == 4 ? 52U + 1364U : 52U)) << which;

        SensorFrame expected = plain_frame();  // absent sensors come back as zeros
        expected.has_gyro = frame.has_gyro;
        expected.has_accelerometers = frame.has_accelerometers;
        expected.has_compass = frame.has_compass;
        expected.has_beacon_scan = frame.has_beacon_scan;
        expected.has_laser_scan = frame.has_laser_scan;
        if (which == 0) {
            expected.gyro_raw = full.gyro_raw;
        } else if (which == 1) {
            expected.accel_raw = full.accel_raw;
        } else if (which == 2) {
            expected.compass_deg = full.compass_deg;
        } else if (which == 3) {
            expected.beacons = full.beacons;
        } else {
            expected.laser = scan;
        }
        expect_same_frame(decoded_or_fail(bytes).frame, expected);
    }
}

TEST(ProtocolFrameExtension, AnEmptyScanIsNotTheSameAsNoScan) {
    SensorFrame frame = plain_frame();
    frame.has_beacon_scan = true;  // scanned, saw nothing
    const Bytes bytes = encode(FramePacket{frame, {}});
    ASSERT_EQ(bytes.size(), 52U);
    EXPECT_EQ(bytes[36], 0x08);
    EXPECT_EQ(bytes[37], 0);
    const FramePacket decoded = decoded_or_fail(bytes);
    EXPECT_TRUE(decoded.frame.has_beacon_scan);
    EXPECT_EQ(decoded.frame.beacons.count, 0);
}

TEST(ProtocolFrameExtension, TheDocumentedPlainExampleStillDecodes) {
    // docs/protocol.md, "Example datagrams": a frame written before the extension existed.
    const Bytes old{0x4c, 0x46, 0x55, 0x50, 0x01, 0x01, 0x24, 0x00, 0xc4, 0x01, 0x00, 0x00,
                    0x50, 0x8f, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00, 0x29, 0x15, 0x00, 0x00,
                    0x4f, 0x14, 0x00, 0x00, 0xb1, 0x00, 0x1f, 0x00, 0x03, 0x00, 0x00, 0x00};
    FramePacket packet;
    packet.frame.has_gyro = true;  // stale state from an earlier frame must be cleared
    packet.frame.has_beacon_scan = true;
    packet.frame.beacons.count = 4;
    std::string reason = "stale";
    ASSERT_EQ(decode(old, packet, reason), DecodeError::None);
    EXPECT_TRUE(reason.empty());
    EXPECT_EQ(packet.frame.sequence, 452U);
    EXPECT_EQ(packet.frame.encoder_counts, (std::array<std::int32_t, 2>{5417, 5199}));
    EXPECT_EQ(packet.frame.ir_adc, (std::array<std::uint16_t, 2>{177, 31}));
    EXPECT_FALSE(packet.frame.has_gyro);
    EXPECT_FALSE(packet.frame.has_beacon_scan);
    EXPECT_EQ(packet.frame.beacons.count, 0);
    EXPECT_EQ(encode(packet), old);
}

// --- Malformed extensions ---------------------------------------------------------------------

struct Rejection {
    DecodeError error;
    std::string reason;
};

Rejection rejected(const Bytes& bytes) {
    FramePacket packet;
    packet.frame.sequence = 99;  // a failed decode leaves the packet alone
    std::string reason;
    const DecodeError error = decode(bytes, packet, reason);
    EXPECT_EQ(packet.frame.sequence, 99U);
    FramePacket again;
    EXPECT_EQ(decode(bytes, again), error);  // the short form agrees
    return {error, reason};
}

Bytes full_bytes() {
    return encode(FramePacket{full_frame(), {}});
}

TEST(ProtocolFrameExtension, ACountBeyondEightIsRejected) {
    Bytes bytes = full_bytes();  // 124 bytes, the longest valid frame
    bytes[37] = 9;
    const Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason, "beacon count 9 exceeds 8");
    bytes[37] = 255;
    EXPECT_EQ(rejected(bytes).reason, "beacon count 255 exceeds 8");
}

TEST(ProtocolFrameExtension, ACountThatDisagreesWithTheLengthIsRejected) {
    SensorFrame frame = full_frame();
    frame.beacons.count = 1;
    Bytes bytes = encode(FramePacket{frame, {}});
    ASSERT_EQ(bytes.size(), 61U);
    bytes[37] = 3;
    Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason, "beacon count 3 needs length 79, the length field says 61");
    bytes[37] = 0;
    EXPECT_EQ(rejected(bytes).reason, "beacon count 0 needs length 52, the length field says 61");
}

TEST(ProtocolFrameExtension, SightingsWithoutTheScanFlagAreRejected) {
    Bytes bytes = full_bytes();
    bytes[36] = 0x07;  // beacon-scan bit cleared, count still 8
    const Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason, "beacon count 8 without the beacon-scan flag (bit 3)");
}

TEST(ProtocolFrameExtension, ANonFiniteBearingIsRejectedWithItsSighting) {
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()}) {
        Bytes bytes = full_bytes();
        put_f64(bytes, 52 + 9 * 5 + 1, bad);
        const Rejection r = rejected(bytes);
        EXPECT_EQ(r.error, DecodeError::NonFinite);
        EXPECT_EQ(r.reason, "beacon sighting 5 (offset 98): bearing is not finite");
    }
}

TEST(ProtocolFrameExtension, LengthsBetweenTheValidOnesAreRejected) {
    // 52 + 9n + 2m misses 53, 55, 57 and 59 (odd needs n ≥ 1), odd lengths beyond
    // 52 + 63 + 2048 = 2163 and even ones beyond 2172; 2173 and more are beyond the maximum.
    for (const std::size_t length :
         {37U, 40U, 51U, 53U, 55U, 57U, 59U, 2165U, 2171U, 2173U, 2174U, 4000U, 65535U}) {
        Bytes bytes = full_bytes();
        bytes.resize(std::min<std::size_t>(length, kMaxPacketSize), 0);
        put_le(bytes, 6, length, 2);
        const Rejection r = rejected(bytes);
        EXPECT_EQ(r.error, DecodeError::BadLength) << length;
        EXPECT_EQ(r.reason, "bad length: sensor frame length " + std::to_string(length)
                                + " is neither 36 nor 52 + 9n + 2m (n = 0 … 8 beacon sightings, "
                                  "m = 0 … 1024 laser beams)")
            << length;
    }
}

TEST(ProtocolFrameExtension, AnExtensionCutShortIsTruncated) {
    const Bytes bytes = full_bytes();
    for (const std::size_t size : {36U, 52U, 115U, 123U}) {
        const Bytes cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
        const Rejection r = rejected(cut);
        EXPECT_EQ(r.error, DecodeError::Truncated) << size;
        EXPECT_EQ(r.reason, "truncated") << size;
    }
}

TEST(ProtocolFrameExtension, AnExtensionWithoutAnySensorIsRejected) {
    // The frame it would describe is the plain 36-byte one: one encoding per frame.
    SensorFrame frame = plain_frame();
    frame.has_compass = true;
    Bytes bytes = encode(FramePacket{frame, {}});
    ASSERT_EQ(bytes.size(), 52U);
    for (const int extras : {0x00, 0x20, 0xE0}) {
        bytes[36] = static_cast<std::uint8_t>(extras);
        const Rejection r = rejected(bytes);
        EXPECT_EQ(r.error, DecodeError::BadLength) << extras;
        EXPECT_EQ(r.reason,
                  "extension block without any sensor flag (bits 0-4 of offset 36 all clear)");
    }
}

TEST(ProtocolFrameExtension, ReservedExtrasBitsAreIgnored) {
    Bytes bytes = full_bytes();
    bytes[36] = 0xEF;  // bits 5–7 besides the four sensors (bit 4, the laser, stays clear)
    expect_same_frame(decoded_or_fail(bytes).frame, full_frame());
}

// --- The laser scan ------------------------------------------------------------------------

TEST(ProtocolFrameExtension, LaserLayoutWorkedOutByHand) {
    SensorFrame frame = plain_frame();
    frame.has_compass = true;
    frame.compass_deg = 90;
    frame.has_beacon_scan = true;
    frame.beacons.count = 1;
    frame.beacons.sightings[0] = {7, 1.5};
    frame.has_laser_scan = true;
    frame.laser.beam_count = 3;
    frame.laser.range_mm = {kRangeNoEcho, 1234, 0xFFFF};

    Bytes expected = encode(FramePacket{plain_frame(), {}});
    expected.resize(52 + 9 + 2 * 3, 0);
    put_le(expected, 6, 67, 2);  // length 52 + 9·1 + 2·3
    expected[36] = 0x1C;         // compass | beacon scan | laser scan
    expected[37] = 1;            // beacon count
    put_i16(expected, 48, 90);   // compass
    put_le(expected, 50, 3, 2);  // laser beam count
    expected[52] = 7;
    put_f64(expected, 53, 1.5);
    const std::vector<std::uint8_t> ranges{0x00, 0x00, 0xD2, 0x04, 0xFF, 0xFF};  // 0, 1234, 65535
    std::copy(ranges.begin(), ranges.end(), expected.begin() + 61);

    EXPECT_EQ(encode(FramePacket{frame, {}}), expected);
    expect_same_frame(decoded_or_fail(expected).frame, frame);
}

TEST(ProtocolFrameExtension, TheDocumentedLaserExampleIsWhatTheEncoderWrites) {
    // docs/protocol.md, "Example datagrams": the first 64 bytes of a frame with a URG-04LX
    // scan (682 beams) and nothing else optional.
    const Bytes documented_start{0x4c, 0x46, 0x55, 0x50, 0x01, 0x01, 0x88, 0x05, 0xc4, 0x01, 0x00,
                                 0x00, 0x50, 0x8f, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00, 0x29, 0x15,
                                 0x00, 0x00, 0x4f, 0x14, 0x00, 0x00, 0xb1, 0x00, 0x1f, 0x00, 0x03,
                                 0x00, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xaa, 0x02, 0xd2, 0x04, 0xd3,
                                 0x04, 0x00, 0x00, 0x01, 0x00, 0x02, 0x00, 0x35, 0x02};
    FramePacket packet;
    packet.frame.time = 22.45;
    packet.frame.sequence = 452;
    packet.frame.encoder_counts = {5417, 5199};
    packet.frame.ir_adc = {177, 31};
    packet.frame.ir_valid = {true, true};
    packet.frame.has_laser_scan = true;
    packet.frame.laser.beam_count = 682;
    packet.frame.laser.range_mm.fill(2000);
    const std::array<std::uint16_t, 6> first{1234,          1235,          kRangeNoEcho,
                                             kRangeTooNear, kRangeDropout, 565};
    std::copy(first.begin(), first.end(), packet.frame.laser.range_mm.begin());
    std::fill(packet.frame.laser.range_mm.begin() + 682, packet.frame.laser.range_mm.end(), 0);
    const Bytes bytes = encode(packet);
    ASSERT_EQ(bytes.size(), 1416U);  // 52 + 2·682: one Ethernet frame (≤ 1472 bytes of UDP)
    EXPECT_EQ(Bytes(bytes.begin(), bytes.begin() + 64), documented_start);
    expect_same_frame(decoded_or_fail(bytes).frame, packet.frame);
}

TEST(ProtocolFrameExtension, TheLongestFrameRoundTrips) {
    SensorFrame frame = full_frame();
    frame.has_laser_scan = true;
    frame.laser = laser_scan(kMaxScanBeams);
    const Bytes bytes = encode(FramePacket{frame, {true, false, true}});
    ASSERT_EQ(bytes.size(), kMaxPacketSize);
    EXPECT_EQ(bytes[36], 0x1F);
    const FramePacket decoded = decoded_or_fail(bytes);
    expect_same_frame(decoded.frame, frame);
    EXPECT_TRUE(decoded.flags.watchdog_stopped);
    EXPECT_TRUE(decoded.flags.reset);

    SensorFrame beyond = frame;  // a beam count beyond the array: the first 1024 travel
    beyond.laser.beam_count = 2000;
    EXPECT_EQ(encode(FramePacket{beyond, {}}), encode(FramePacket{frame, {}}));
}

TEST(ProtocolFrameExtension, AnEmptyLaserScanIsNotTheSameAsNoScanner) {
    SensorFrame frame = plain_frame();
    frame.has_laser_scan = true;  // scanned, zero beams
    const Bytes bytes = encode(FramePacket{frame, {}});
    ASSERT_EQ(bytes.size(), 52U);
    EXPECT_EQ(bytes[36], 0x10);
    const FramePacket decoded = decoded_or_fail(bytes);
    EXPECT_TRUE(decoded.frame.has_laser_scan);
    EXPECT_EQ(decoded.frame.laser.beam_count, 0);
}

Bytes laser_bytes(std::uint16_t beams, int sightings) {
    SensorFrame frame = full_frame();
    frame.beacons.count = static_cast<std::uint8_t>(sightings);
    frame.has_laser_scan = true;
    frame.laser = laser_scan(beams);
    return encode(FramePacket{frame, {}});
}

TEST(ProtocolFrameExtension, ALaserBeamCountBeyond1024IsRejected) {
    Bytes bytes = laser_bytes(1024, 0);
    ASSERT_EQ(bytes.size(), 52U + 2048U);
    put_le(bytes, 50, 1025, 2);
    Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason, "laser beam count 1025 exceeds 1024");
    put_le(bytes, 50, 65535, 2);
    EXPECT_EQ(rejected(bytes).reason, "laser beam count 65535 exceeds 1024");
}

TEST(ProtocolFrameExtension, ALaserBeamCountThatDisagreesWithTheLengthIsRejected) {
    Bytes bytes = laser_bytes(682, 2);
    ASSERT_EQ(bytes.size(), 52U + 18U + 1364U);
    put_le(bytes, 50, 681, 2);
    Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason,
              "beacon count 2 and laser beam count 681 need length 1432, the length field says "
              "1434");
    put_le(bytes, 50, 682, 2);
    bytes[37] = 4;  // 18 bytes more would be sightings: the ranges would have to be 9 fewer
    EXPECT_EQ(rejected(bytes).reason,
              "beacon count 4 and laser beam count 682 need length 1452, the length field says "
              "1434");
}

TEST(ProtocolFrameExtension, LaserRangesWithoutTheLaserFlagAreRejected) {
    Bytes bytes = laser_bytes(10, 8);
    bytes[36] = 0x0F;  // laser bit cleared, beam count still 10
    const Rejection r = rejected(bytes);
    EXPECT_EQ(r.error, DecodeError::BadLength);
    EXPECT_EQ(r.reason, "laser beam count 10 without the laser-scan flag (bit 4)");
}

TEST(ProtocolFrameExtension, ALaserScanCutShortIsTruncated) {
    const Bytes bytes = laser_bytes(682, 8);
    for (const std::size_t size :
         {std::size_t{124}, std::size_t{125}, std::size_t{1000}, bytes.size() - 1}) {
        const Bytes cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size));
        const Rejection r = rejected(cut);
        EXPECT_EQ(r.error, DecodeError::Truncated) << size;
    }
}

}  // namespace
}  // namespace legofeup::comms
