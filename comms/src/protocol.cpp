#include "legofeup/comms/protocol.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

#include "byte_order.hpp"

namespace legofeup::comms {
namespace {

using detail::ByteReader;
using detail::ByteWriter;

// Packet sizes (docs/protocol.md has the same tables).
constexpr std::size_t kFrameSize = 36;
constexpr std::size_t kCommandSize = 36;
constexpr std::size_t kBareSize = kHeaderSize;
constexpr std::size_t kConnectReplySize = 44;
constexpr std::size_t kTruthSize = 100;
constexpr std::size_t kControlRequestSize = 60;
constexpr std::size_t kControlReplySize = 384;

// Sensor frame flag bits.
constexpr std::uint16_t kFrontValidBit = 1U << 0;
constexpr std::uint16_t kRearValidBit = 1U << 1;
constexpr std::uint16_t kWatchdogBit = 1U << 2;
constexpr std::uint16_t kPausedBit = 1U << 3;
constexpr std::uint16_t kResetBit = 1U << 4;

// Sensor frame extension: which optional sensors the frame carries (offset 36).
constexpr std::uint8_t kGyroBit = 1U << 0;
constexpr std::uint8_t kAccelerometersBit = 1U << 1;
constexpr std::uint8_t kCompassBit = 1U << 2;
constexpr std::uint8_t kBeaconScanBit = 1U << 3;
constexpr std::uint8_t kLaserScanBit = 1U << 4;
constexpr std::uint8_t kSensorBits =
    kGyroBit | kAccelerometersBit | kCompassBit | kBeaconScanBit | kLaserScanBit;
// Its fields: 37 u8 beacon count, 38 i16 gyro, 40 4×i16 accelerometers ([unit][axis] in the
// order of SensorFrame::accel_raw), 48 i16 compass, 50 u16 laser beam count, 52 the
// sightings, then the laser ranges.
constexpr std::size_t kBeaconCountOffset = 37;
constexpr std::size_t kGyroOffset = 38;
constexpr std::size_t kAccelOffset = 40;
constexpr std::size_t kCompassOffset = 48;
constexpr std::size_t kBeamCountOffset = 50;
constexpr auto kMaxSightings = static_cast<std::size_t>(kMaxBeaconSightings);
constexpr auto kMaxBeams = static_cast<std::size_t>(kMaxScanBeams);

/// 52 + 9n + 2m: n sightings, then m laser ranges.
constexpr std::size_t extended_frame_size(std::size_t sightings, std::size_t beams) {
    return kFrameSightingsOffset + kFrameSightingSize * sightings + kFrameRangeSize * beams;
}
static_assert(extended_frame_size(kMaxSightings, kMaxBeams) == kMaxPacketSize);

std::size_t ranges_offset(std::size_t sightings) {
    return extended_frame_size(sightings, 0);
}

// Control request flag bits.
constexpr std::uint8_t kPoseGivenBit = 1U << 0;

// Status block of the control reply, at offset 28.
constexpr std::size_t kStatusOffset = 28;
constexpr std::size_t kWorldNameSize = kWorldNameMaxBytes + 1;  // + the NUL
constexpr std::size_t kCountersOffset = 136;
constexpr std::size_t kMessageOffset = 288;
constexpr std::size_t kMessageSize = kReplyMessageMaxBytes + 1;

/// The counters in wire order: one table for encoding, decoding and counting.
constexpr std::array kCounterFields = {
    &ServerCounters::frames_sent,       &ServerCounters::truth_sent,
    &ServerCounters::commands_accepted, &ServerCounters::commands_duplicate,
    &ServerCounters::commands_late,     &ServerCounters::commands_missing,
    &ServerCounters::truncated,         &ServerCounters::bad_magic,
    &ServerCounters::bad_version,       &ServerCounters::unknown_type,
    &ServerCounters::bad_length,        &ServerCounters::oversized,
    &ServerCounters::non_finite,        &ServerCounters::bad_time,
    &ServerCounters::wrong_stream,      &ServerCounters::unexpected_peer,
    &ServerCounters::watchdog_stops,    &ServerCounters::control_requests,
    &ServerCounters::overruns,
};
static_assert(kCountersOffset + 8 * kCounterFields.size() == kMessageOffset);
static_assert(kMessageOffset + kMessageSize == kControlReplySize);

ByteWriter start_packet(PacketType type, std::uint32_t sequence, double time, std::size_t size) {
    ByteWriter out(size);
    for (std::size_t i = 0; i < kMagic.size(); ++i) {
        out.u8(i, kMagic[i]);
    }
    out.u8(4, kProtocolVersion);
    out.u8(5, static_cast<std::uint8_t>(type));
    out.u16(6, static_cast<std::uint16_t>(size));
    out.u32(8, sequence);
    out.u64(12, to_microseconds(time));
    return out;
}

ByteWriter start_packet(PacketType type, std::uint32_t sequence, double time) {
    return start_packet(type, sequence, time, packet_size(type));
}

/// The header must decode and carry one of `accepted` types.
DecodeError open_packet(std::span<const std::uint8_t> datagram,
                        std::initializer_list<PacketType> accepted, PacketHeader& header) {
    if (const DecodeError error = decode_header(datagram, header); error != DecodeError::None) {
        return error;
    }
    return std::find(accepted.begin(), accepted.end(), header.type) == accepted.end()
               ? DecodeError::WrongType
               : DecodeError::None;
}

bool all_finite(std::initializer_list<double> values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

void write_endpoint(ByteWriter& out, std::size_t address_offset, std::size_t port_offset,
                    const Endpoint& endpoint) {
    // The address in network order, a.b.c.d as four bytes, so it reads the same everywhere.
    for (std::size_t i = 0; i < 4; ++i) {
        out.u8(address_offset + i, static_cast<std::uint8_t>(endpoint.address >> (24 - 8 * i)));
    }
    out.u16(port_offset, endpoint.port);
}

Endpoint read_endpoint(const ByteReader& in, std::size_t address_offset, std::size_t port_offset) {
    Endpoint endpoint;
    endpoint.address = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        endpoint.address = (endpoint.address << 8) | in.u8(address_offset + i);
    }
    endpoint.port = in.u16(port_offset);
    return endpoint;
}

void write_noise(ByteWriter& out, std::size_t offset, const NoiseSettings& noise) {
    out.f64(offset, noise.wheel_diameter_ratio);
    out.f64(offset + 8, noise.wheel_base_ratio);
    out.f64(offset + 16, noise.slip_noise);
    out.f64(offset + 24, noise.ir_noise);
}

NoiseSettings read_noise(const ByteReader& in, std::size_t offset) {
    return {in.f64(offset), in.f64(offset + 8), in.f64(offset + 16), in.f64(offset + 24)};
}

bool finite(const NoiseSettings& noise) {
    return all_finite(
        {noise.wheel_diameter_ratio, noise.wheel_base_ratio, noise.slip_noise, noise.ir_noise});
}

}  // namespace

std::size_t packet_size(PacketType type) {
    switch (type) {
        case PacketType::SensorFrame:
            return kFrameSize;
        case PacketType::WheelCommand:
            return kCommandSize;
        case PacketType::Connect:
        case PacketType::Disconnect:
        case PacketType::TruthSubscribe:
        case PacketType::TruthUnsubscribe:
            return kBareSize;
        case PacketType::ConnectReply:
            return kConnectReplySize;
        case PacketType::GroundTruth:
            return kTruthSize;
        case PacketType::ControlRequest:
            return kControlRequestSize;
        case PacketType::ControlReply:
            return kControlReplySize;
    }
    return 0;
}

namespace {

std::size_t sightings_carried(const SensorFrame& frame) {
    return frame.has_beacon_scan ? std::min<std::size_t>(frame.beacons.count, kMaxSightings) : 0;
}

std::size_t beams_carried(const SensorFrame& frame) {
    return frame.has_laser_scan ? std::min<std::size_t>(frame.laser.beam_count, kMaxBeams) : 0;
}

}  // namespace

std::size_t frame_size(const SensorFrame& frame) {
    if (!frame.has_gyro && !frame.has_accelerometers && !frame.has_compass && !frame.has_beacon_scan
        && !frame.has_laser_scan) {
        return kFrameSize;
    }
    return extended_frame_size(sightings_carried(frame), beams_carried(frame));
}

bool is_valid_length(PacketType type, std::size_t length) {
    const std::size_t size = packet_size(type);
    if (size == 0) {
        return false;
    }
    if (length == size) {
        return true;
    }
    if (type != PacketType::SensorFrame || length < kFrameSightingsOffset
        || length > kMaxPacketSize) {
        return false;
    }
    // 52 + 9n + 2m for some n ≤ 8 and m ≤ 1024.
    for (std::size_t sightings = 0; sightings <= kMaxSightings; ++sightings) {
        const std::size_t used = extended_frame_size(sightings, 0);
        if (used <= length && (length - used) % kFrameRangeSize == 0
            && (length - used) / kFrameRangeSize <= kMaxBeams) {
            return true;
        }
    }
    return false;
}

std::string_view to_string(PacketType type) {
    switch (type) {
        case PacketType::SensorFrame:
            return "sensor frame";
        case PacketType::WheelCommand:
            return "wheel command";
        case PacketType::Connect:
            return "connect";
        case PacketType::ConnectReply:
            return "connect reply";
        case PacketType::Disconnect:
            return "disconnect";
        case PacketType::TruthSubscribe:
            return "truth subscribe";
        case PacketType::GroundTruth:
            return "ground truth";
        case PacketType::TruthUnsubscribe:
            return "truth unsubscribe";
        case PacketType::ControlRequest:
            return "control request";
        case PacketType::ControlReply:
            return "control reply";
    }
    return "unknown";
}

std::string_view to_string(DecodeError error) {
    switch (error) {
        case DecodeError::None:
            return "none";
        case DecodeError::Truncated:
            return "truncated";
        case DecodeError::BadMagic:
            return "bad magic";
        case DecodeError::BadVersion:
            return "bad version";
        case DecodeError::UnknownType:
            return "unknown type";
        case DecodeError::BadLength:
            return "bad length";
        case DecodeError::Oversized:
            return "oversized";
        case DecodeError::NonFinite:
            return "non-finite value";
        case DecodeError::BadTime:
            return "time stamp out of range";
        case DecodeError::WrongType:
            return "wrong type for this stream";
    }
    return "unknown";
}

std::string_view to_string(ControlOp op) {
    switch (op) {
        case ControlOp::Status:
            return "status";
        case ControlOp::Reset:
            return "reset";
        case ControlOp::Pause:
            return "pause";
        case ControlOp::Resume:
            return "resume";
        case ControlOp::SetNoise:
            return "set noise";
        case ControlOp::Teleport:
            return "teleport";
        case ControlOp::SetTimeScale:
            return "set time scale";
    }
    return "unknown";
}

std::string_view to_string(ControlResult result) {
    switch (result) {
        case ControlResult::Ok:
            return "ok";
        case ControlResult::Rejected:
            return "rejected";
        case ControlResult::UnknownOp:
            return "unknown op";
    }
    return "unknown";
}

void count_decode_error(ServerCounters& counters, DecodeError error) {
    switch (error) {
        case DecodeError::None:
            return;
        case DecodeError::Truncated:
            ++counters.truncated;
            return;
        case DecodeError::BadMagic:
            ++counters.bad_magic;
            return;
        case DecodeError::BadVersion:
            ++counters.bad_version;
            return;
        case DecodeError::UnknownType:
            ++counters.unknown_type;
            return;
        case DecodeError::BadLength:
            ++counters.bad_length;
            return;
        case DecodeError::Oversized:
            ++counters.oversized;
            return;
        case DecodeError::NonFinite:
            ++counters.non_finite;
            return;
        case DecodeError::BadTime:
            ++counters.bad_time;
            return;
        case DecodeError::WrongType:
            ++counters.wrong_stream;
            return;
    }
}

std::uint64_t to_microseconds(double seconds) {
    if (!(seconds > 0.0)) {
        return 0;
    }
    const double microseconds = std::round(seconds * 1e6);
    if (microseconds >= static_cast<double>(kMaxTimeMicroseconds)) {
        return kMaxTimeMicroseconds;
    }
    return static_cast<std::uint64_t>(microseconds);
}

double to_seconds(std::uint64_t microseconds) {
    return static_cast<double>(microseconds) / 1e6;
}

DecodeError decode_header(std::span<const std::uint8_t> datagram, PacketHeader& header) {
    if (datagram.size() > kMaxPacketSize) {
        return DecodeError::Oversized;
    }
    if (datagram.size() < kHeaderSize) {
        return DecodeError::Truncated;
    }
    if (!std::equal(kMagic.begin(), kMagic.end(), datagram.begin())) {
        return DecodeError::BadMagic;
    }
    const ByteReader in(datagram);
    if (in.u8(4) != kProtocolVersion) {
        return DecodeError::BadVersion;
    }
    const auto type = static_cast<PacketType>(in.u8(5));
    const std::size_t expected = packet_size(type);
    if (expected == 0) {
        return DecodeError::UnknownType;
    }
    const std::size_t length = in.u16(6);
    if (!is_valid_length(type, length)) {
        return DecodeError::BadLength;
    }
    if (datagram.size() < length) {
        return DecodeError::Truncated;
    }
    if (datagram.size() > length) {
        return DecodeError::Oversized;
    }
    header = {type, in.u32(8), in.u64(12)};
    return header.time_us > kMaxTimeMicroseconds ? DecodeError::BadTime : DecodeError::None;
}

// --- Sensor frame: 20 i32 encoder right, 24 i32 encoder left, 28 u16 IR front A/D,
//     30 u16 IR rear A/D, 32 u16 flags, 34 u16 reserved; then, only when the frame has any
//     optional sensor, the extension block: 36 u8 extras flags, 37 u8 beacon count n,
//     38 i16 gyro, 40 i16 accel right forward, 42 right left, 44 left forward, 46 left left,
//     48 i16 compass degrees, 50 u16 laser beam count m, 52 + 9k u8 sighting k id,
//     53 + 9k f64 bearing, then 52 + 9n + 2i u16 range of laser beam i (mm or error code).
//     Fields of absent sensors are sent as 0 and decoded as 0.

Bytes encode(const FramePacket& packet) {
    const SensorFrame& frame = packet.frame;
    const std::size_t size = frame_size(frame);
    ByteWriter out = start_packet(PacketType::SensorFrame, frame.sequence, frame.time, size);
    out.i32(20, frame.encoder_counts[0]);
    out.i32(24, frame.encoder_counts[1]);
    out.u16(28, frame.ir_adc[0]);
    out.u16(30, frame.ir_adc[1]);
    const auto bit = [](bool set, std::uint16_t mask) { return set ? mask : std::uint16_t{0}; };
    const auto flags = static_cast<std::uint16_t>(
        bit(frame.ir_valid[0], kFrontValidBit) | bit(frame.ir_valid[1], kRearValidBit)
        | bit(packet.flags.watchdog_stopped, kWatchdogBit) | bit(packet.flags.paused, kPausedBit)
        | bit(packet.flags.reset, kResetBit));
    out.u16(32, flags);
    if (size == kFrameSize) {
        return out.take();  // the plain frame, byte for byte as before the extension existed
    }
    const auto extra = [](bool set, std::uint8_t mask) { return set ? mask : std::uint8_t{0}; };
    out.u8(kFrameExtensionOffset,
           static_cast<std::uint8_t>(extra(frame.has_gyro, kGyroBit)
                                     | extra(frame.has_accelerometers, kAccelerometersBit)
                                     | extra(frame.has_compass, kCompassBit)
                                     | extra(frame.has_beacon_scan, kBeaconScanBit)
                                     | extra(frame.has_laser_scan, kLaserScanBit)));
    if (frame.has_gyro) {
        out.i16(kGyroOffset, frame.gyro_raw);
    }
    if (frame.has_accelerometers) {
        for (std::size_t unit = 0; unit < 2; ++unit) {
            for (std::size_t axis = 0; axis < 2; ++axis) {
                out.i16(kAccelOffset + 4 * unit + 2 * axis, frame.accel_raw[unit][axis]);
            }
        }
    }
    if (frame.has_compass) {
        out.i16(kCompassOffset, frame.compass_deg);
    }
    const std::size_t sightings = sightings_carried(frame);
    out.u8(kBeaconCountOffset, static_cast<std::uint8_t>(sightings));
    for (std::size_t k = 0; k < sightings; ++k) {
        const BeaconSighting& sighting = frame.beacons.sightings[k];
        out.u8(kFrameSightingsOffset + kFrameSightingSize * k, sighting.id);
        out.f64(kFrameSightingsOffset + kFrameSightingSize * k + 1, sighting.bearing);
    }
    const std::size_t beams = beams_carried(frame);
    out.u16(kBeamCountOffset, static_cast<std::uint16_t>(beams));
    const std::size_t ranges = ranges_offset(sightings);
    for (std::size_t i = 0; i < beams; ++i) {
        out.u16(ranges + kFrameRangeSize * i, frame.laser.range_mm[i]);
    }
    return out.take();
}

namespace {

/// The extension block of a frame whose header (and so its length, one of 52 + 9n + 2m) was
/// checked already. Fills the optional sensors of `frame` or says what was wrong.
DecodeError decode_frame_extension(const ByteReader& in, std::size_t length, SensorFrame& frame,
                                   std::string& reason) {
    const std::uint8_t extras = in.u8(kFrameExtensionOffset);  // bits 5–7 reserved: ignored
    const std::size_t count = in.u8(kBeaconCountOffset);
    const std::size_t beams = in.u16(kBeamCountOffset);
    frame.has_beacon_scan = (extras & kBeaconScanBit) != 0;
    frame.has_laser_scan = (extras & kLaserScanBit) != 0;
    if ((extras & kSensorBits) == 0) {
        // A frame without optional sensors is the plain 36 bytes: one encoding per frame.
        reason = "extension block without any sensor flag (bits 0-4 of offset 36 all clear)";
        return DecodeError::BadLength;
    }
    if (count > kMaxSightings) {
        reason =
            "beacon count " + std::to_string(count) + " exceeds " + std::to_string(kMaxSightings);
        return DecodeError::BadLength;
    }
    if (count != 0 && !frame.has_beacon_scan) {
        reason = "beacon count " + std::to_string(count) + " without the beacon-scan flag (bit 3)";
        return DecodeError::BadLength;
    }
    if (beams > kMaxBeams) {
        reason =
            "laser beam count " + std::to_string(beams) + " exceeds " + std::to_string(kMaxBeams);
        return DecodeError::BadLength;
    }
    if (beams != 0 && !frame.has_laser_scan) {
        reason =
            "laser beam count " + std::to_string(beams) + " without the laser-scan flag (bit 4)";
        return DecodeError::BadLength;
    }
    if (extended_frame_size(count, beams) != length) {
        reason = "beacon count " + std::to_string(count)
                 + (beams == 0 ? std::string(" needs")
                               : " and laser beam count " + std::to_string(beams) + " need")
                 + " length " + std::to_string(extended_frame_size(count, beams))
                 + ", the length field says " + std::to_string(length);
        return DecodeError::BadLength;
    }
    frame.has_gyro = (extras & kGyroBit) != 0;
    frame.gyro_raw = frame.has_gyro ? in.i16(kGyroOffset) : std::int16_t{0};
    frame.has_accelerometers = (extras & kAccelerometersBit) != 0;
    for (std::size_t unit = 0; unit < 2; ++unit) {
        for (std::size_t axis = 0; axis < 2; ++axis) {
            frame.accel_raw[unit][axis] = frame.has_accelerometers
                                              ? in.i16(kAccelOffset + 4 * unit + 2 * axis)
                                              : std::int16_t{0};
        }
    }
    frame.has_compass = (extras & kCompassBit) != 0;
    frame.compass_deg = frame.has_compass ? in.i16(kCompassOffset) : std::int16_t{0};
    frame.beacons = {};
    frame.beacons.count = static_cast<std::uint8_t>(count);
    for (std::size_t k = 0; k < count; ++k) {
        BeaconSighting& sighting = frame.beacons.sightings[k];
        sighting.id = in.u8(kFrameSightingsOffset + kFrameSightingSize * k);
        sighting.bearing = in.f64(kFrameSightingsOffset + kFrameSightingSize * k + 1);
        if (!std::isfinite(sighting.bearing)) {
            reason = "beacon sighting " + std::to_string(k) + " (offset "
                     + std::to_string(kFrameSightingsOffset + kFrameSightingSize * k + 1)
                     + "): bearing is not finite";
            return DecodeError::NonFinite;
        }
    }
    // Every u16 is a reading: a distance in mm, or an error code below 20.
    frame.laser = {};
    frame.laser.beam_count = static_cast<std::uint16_t>(beams);
    const std::size_t ranges = ranges_offset(count);
    for (std::size_t i = 0; i < beams; ++i) {
        frame.laser.range_mm[i] = in.u16(ranges + kFrameRangeSize * i);
    }
    return DecodeError::None;
}

}  // namespace

DecodeError decode(std::span<const std::uint8_t> datagram, FramePacket& packet,
                   std::string& reason) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::SensorFrame}, header);
        error != DecodeError::None) {
        reason = std::string(to_string(error));
        if (error == DecodeError::BadLength) {
            reason += ": sensor frame length " + std::to_string(ByteReader(datagram).u16(6))
                      + " is neither 36 nor 52 + 9n + 2m (n = 0 … " + std::to_string(kMaxSightings)
                      + " beacon sightings, m = 0 … " + std::to_string(kMaxBeams) + " laser beams)";
        }
        return error;
    }
    const ByteReader in(datagram);
    SensorFrame frame;
    frame.time = to_seconds(header.time_us);
    frame.sequence = header.sequence;
    frame.encoder_counts = {in.i32(20), in.i32(24)};
    frame.ir_adc = {in.u16(28), in.u16(30)};
    const std::uint16_t flags = in.u16(32);
    frame.ir_valid = {(flags & kFrontValidBit) != 0, (flags & kRearValidBit) != 0};
    if (datagram.size() > kFrameSize) {
        if (const auto error = decode_frame_extension(in, datagram.size(), frame, reason);
            error != DecodeError::None) {
            return error;
        }
    }
    packet.frame = frame;
    packet.flags = {(flags & kWatchdogBit) != 0, (flags & kPausedBit) != 0,
                    (flags & kResetBit) != 0};
    reason.clear();
    return DecodeError::None;
}

DecodeError decode(std::span<const std::uint8_t> datagram, FramePacket& packet) {
    std::string reason;
    return decode(datagram, packet, reason);
}

// --- Wheel command: 20 f64 V1 (right), 28 f64 V2 (left), m/s.

Bytes encode(const CommandPacket& packet) {
    ByteWriter out = start_packet(PacketType::WheelCommand, packet.sequence, packet.answers_time);
    out.f64(20, packet.wheels.right);
    out.f64(28, packet.wheels.left);
    return out.take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, CommandPacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::WheelCommand}, header);
        error != DecodeError::None) {
        return error;
    }
    const ByteReader in(datagram);
    const WheelSpeeds wheels{in.f64(20), in.f64(28)};
    if (!all_finite({wheels.right, wheels.left})) {
        return DecodeError::NonFinite;
    }
    packet = {header.sequence, to_seconds(header.time_us), wheels};
    return DecodeError::None;
}

// --- Header-only packets.

Bytes encode(const BarePacket& packet) {
    return start_packet(packet.type, packet.sequence, packet.time).take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, BarePacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram,
                                       {PacketType::Connect, PacketType::Disconnect,
                                        PacketType::TruthSubscribe, PacketType::TruthUnsubscribe},
                                       header);
        error != DecodeError::None) {
        return error;
    }
    packet = {header.type, header.sequence, to_seconds(header.time_us)};
    return DecodeError::None;
}

// --- Connect reply: 20 u8 result, 21 u8 reserved, 22 u16 holder port, 24 4×u8 holder IPv4
//     (a.b.c.d), 28 f64 control period (s), 36 f64 time scale.

Bytes encode(const ConnectReplyPacket& packet) {
    ByteWriter out = start_packet(PacketType::ConnectReply, packet.sequence, packet.time);
    out.u8(20, static_cast<std::uint8_t>(packet.result));
    write_endpoint(out, 24, 22, packet.holder);
    out.f64(28, packet.control_period);
    out.f64(36, packet.time_scale);
    return out.take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, ConnectReplyPacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::ConnectReply}, header);
        error != DecodeError::None) {
        return error;
    }
    const ByteReader in(datagram);
    ConnectReplyPacket decoded;
    decoded.sequence = header.sequence;
    decoded.time = to_seconds(header.time_us);
    decoded.result = in.u8(20) == 0 ? ConnectResult::Accepted : ConnectResult::Busy;
    decoded.holder = read_endpoint(in, 24, 22);
    decoded.control_period = in.f64(28);
    decoded.time_scale = in.f64(36);
    if (!all_finite({decoded.control_period, decoded.time_scale})) {
        return DecodeError::NonFinite;
    }
    packet = decoded;
    return DecodeError::None;
}

// --- Ground truth: 20 f64 x, 28 y, 36 θ, 44 v, 52 w, 60 right wheel surface speed,
//     68 left, 76 true front IR distance, 84 rear, 92 u8 touching wall, 93–95 reserved,
//     96 u32 teleports since the last reset.

Bytes encode(const TruthPacket& packet) {
    const GroundTruth& t = packet.truth;
    ByteWriter out = start_packet(PacketType::GroundTruth, packet.sequence, t.time);
    const std::array values{t.pose.x,
                            t.pose.y,
                            t.pose.theta,
                            t.velocity.v,
                            t.velocity.w,
                            t.wheel_surface_speeds.right,
                            t.wheel_surface_speeds.left,
                            t.ir_distances[0],
                            t.ir_distances[1]};
    for (std::size_t i = 0; i < values.size(); ++i) {
        out.f64(20 + 8 * i, values[i]);
    }
    out.u8(92, t.touching_wall ? 1 : 0);
    out.u32(96, t.teleports);
    return out.take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, TruthPacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::GroundTruth}, header);
        error != DecodeError::None) {
        return error;
    }
    const ByteReader in(datagram);
    std::array<double, 9> values{};
    for (std::size_t i = 0; i < values.size(); ++i) {
        values[i] = in.f64(20 + 8 * i);
        if (!std::isfinite(values[i])) {
            return DecodeError::NonFinite;
        }
    }
    GroundTruth& t = packet.truth;
    packet.sequence = header.sequence;
    t.time = to_seconds(header.time_us);
    t.pose = {values[0], values[1], values[2]};
    t.velocity = {values[3], values[4]};
    t.wheel_surface_speeds = {values[5], values[6]};
    t.ir_distances = {values[7], values[8]};
    t.touching_wall = in.u8(92) != 0;
    t.teleports = in.u32(96);
    return DecodeError::None;
}

// --- Control request: 20 u32 request id, 24 u8 op, 25 u8 flags (bit 0: pose given),
//     26 u16 reserved, 28–59 arguments:
//       Reset         28 u64 seed, 36 f64 x, 44 f64 y, 52 f64 θ
//       Teleport      36 f64 x, 44 f64 y, 52 f64 θ
//       SetNoise      28 f64 E_d, 36 f64 E_b, 44 f64 slip, 52 f64 IR σ
//       SetTimeScale  28 f64 time scale

Bytes encode(const ControlRequestPacket& packet) {
    ByteWriter out = start_packet(PacketType::ControlRequest, packet.sequence, 0.0);
    out.u32(20, packet.request_id);
    out.u8(24, packet.op);
    out.u8(25, packet.pose_given ? kPoseGivenBit : 0);
    switch (static_cast<ControlOp>(packet.op)) {
        case ControlOp::Reset:
            out.u64(28, packet.seed);
            [[fallthrough]];
        case ControlOp::Teleport:
            out.f64(36, packet.pose.x);
            out.f64(44, packet.pose.y);
            out.f64(52, packet.pose.theta);
            break;
        case ControlOp::SetNoise:
            write_noise(out, 28, packet.noise);
            break;
        case ControlOp::SetTimeScale:
            out.f64(28, packet.time_scale);
            break;
        case ControlOp::Status:
        case ControlOp::Pause:
        case ControlOp::Resume:
            break;
    }
    return out.take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, ControlRequestPacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::ControlRequest}, header);
        error != DecodeError::None) {
        return error;
    }
    const ByteReader in(datagram);
    ControlRequestPacket decoded;
    decoded.sequence = header.sequence;
    decoded.request_id = in.u32(20);
    decoded.op = in.u8(24);
    decoded.pose_given = (in.u8(25) & kPoseGivenBit) != 0;
    switch (static_cast<ControlOp>(decoded.op)) {
        case ControlOp::Reset:
            decoded.seed = in.u64(28);
            [[fallthrough]];
        case ControlOp::Teleport:
            decoded.pose = {in.f64(36), in.f64(44), in.f64(52)};
            if (!all_finite({decoded.pose.x, decoded.pose.y, decoded.pose.theta})) {
                return DecodeError::NonFinite;
            }
            break;
        case ControlOp::SetNoise:
            decoded.noise = read_noise(in, 28);
            if (!finite(decoded.noise)) {
                return DecodeError::NonFinite;
            }
            break;
        case ControlOp::SetTimeScale:
            decoded.time_scale = in.f64(28);
            if (!std::isfinite(decoded.time_scale)) {
                return DecodeError::NonFinite;
            }
            break;
        case ControlOp::Status:
        case ControlOp::Pause:
        case ControlOp::Resume:
            break;
    }
    packet = decoded;
    return DecodeError::None;
}

// --- Control reply: 20 u32 request id, 24 u8 op, 25 u8 result, 26 u16 reserved, then the
//     status block: 28 u64 steps, 36 f64 control period, 44 f64 time scale, 52 u64 seed,
//     60 f64 E_d, 68 E_b, 76 slip, 84 IR σ, 92 u8 paused, 93 u8 watchdog stopped,
//     94 u8 client connected, 95 u8 reserved, 96 4×u8 client IPv4, 100 u16 client port,
//     102 u16 reserved, 104 char[32] world name, 136 19×u64 counters, 288 char[96] message.

Bytes encode(const ControlReplyPacket& packet) {
    ByteWriter out = start_packet(PacketType::ControlReply, packet.sequence, packet.time);
    const ServerStatus& status = packet.status;
    out.u32(20, packet.request_id);
    out.u8(24, packet.op);
    out.u8(25, static_cast<std::uint8_t>(packet.result));
    out.u64(kStatusOffset, status.steps);
    out.f64(36, status.control_period);
    out.f64(44, status.time_scale);
    out.u64(52, status.seed);
    write_noise(out, 60, status.noise);
    out.u8(92, status.paused ? 1 : 0);
    out.u8(93, status.watchdog_stopped ? 1 : 0);
    out.u8(94, status.client_connected ? 1 : 0);
    write_endpoint(out, 96, 100, status.client);
    out.text(104, status.world_name, kWorldNameSize);
    for (std::size_t i = 0; i < kCounterFields.size(); ++i) {
        out.u64(kCountersOffset + 8 * i, status.counters.*kCounterFields[i]);
    }
    out.text(kMessageOffset, packet.message, kMessageSize);
    return out.take();
}

DecodeError decode(std::span<const std::uint8_t> datagram, ControlReplyPacket& packet) {
    PacketHeader header;
    if (const auto error = open_packet(datagram, {PacketType::ControlReply}, header);
        error != DecodeError::None) {
        return error;
    }
    const ByteReader in(datagram);
    ControlReplyPacket decoded;
    decoded.sequence = header.sequence;
    decoded.time = to_seconds(header.time_us);
    decoded.request_id = in.u32(20);
    decoded.op = in.u8(24);
    const std::uint8_t result = in.u8(25);
    decoded.result = result <= static_cast<std::uint8_t>(ControlResult::UnknownOp)
                         ? static_cast<ControlResult>(result)
                         : ControlResult::Rejected;
    ServerStatus& status = decoded.status;
    status.steps = in.u64(kStatusOffset);
    status.control_period = in.f64(36);
    status.time_scale = in.f64(44);
    status.seed = in.u64(52);
    status.noise = read_noise(in, 60);
    if (!all_finite({status.control_period, status.time_scale}) || !finite(status.noise)) {
        return DecodeError::NonFinite;
    }
    status.paused = in.u8(92) != 0;
    status.watchdog_stopped = in.u8(93) != 0;
    status.client_connected = in.u8(94) != 0;
    status.client = read_endpoint(in, 96, 100);
    status.world_name = in.text(104, kWorldNameSize);
    for (std::size_t i = 0; i < kCounterFields.size(); ++i) {
        status.counters.*kCounterFields[i] = in.u64(kCountersOffset + 8 * i);
    }
    decoded.message = in.text(kMessageOffset, kMessageSize);
    packet = std::move(decoded);
    return DecodeError::None;
}

}  // namespace legofeup::comms
