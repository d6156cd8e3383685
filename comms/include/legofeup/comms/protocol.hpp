#pragma once
// The LegoFeup UDP protocol, version 1 (docs/protocol.md is the specification; this file
// and protocol.cpp are its one implementation). Every packet is one datagram:
//
//   offset size field
//        0    4 magic     "LFUP" (0x4C 0x46 0x55 0x50)
//        4    1 version   1
//        5    1 type      PacketType
//        6    2 length    u16, the whole packet in bytes, header included
//        8    4 sequence  u32, counts the sender's packets on this stream
//       12    8 time_us   u64, simulated time in microseconds
//       20  ... payload   fixed for each type (the sensor frame may carry an extension block
//                         of the further lessons' sensors: 36 bytes, or 52 + 9 per beacon
//                         sighting + 2 per laser beam)
//
// All integers are little-endian, all reals IEEE-754 binary64 little-endian. Decoders never
// trust a field: every malformation is reported as a DecodeError for the caller to count.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/core/ground_truth.hpp"
#include "legofeup/core/motion.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/core/state.hpp"

namespace legofeup::comms {

inline constexpr std::array<std::uint8_t, 4> kMagic{'L', 'F', 'U', 'P'};
inline constexpr std::uint8_t kProtocolVersion = 1;
inline constexpr std::size_t kHeaderSize = 20;

/// The sensor frame's optional extension block (docs/protocol.md, "SensorFrame extension"):
/// 16 fixed bytes after the plain 36-byte frame, then 9 bytes per beacon sighting, then 2 per
/// laser beam (u16 millimetres or error code).
inline constexpr std::size_t kFrameExtensionOffset = 36;
inline constexpr std::size_t kFrameSightingsOffset = 52;
inline constexpr std::size_t kFrameSightingSize = 9;  ///< u8 id + f64 bearing
inline constexpr std::size_t kFrameRangeSize = 2;     ///< u16 per laser beam

/// No valid packet is longer; anything longer is dropped as oversized. The longest is a sensor
/// frame with eight sightings and a scan of kMaxScanBeams beams: 52 + 72 + 2048 = 2172 bytes.
inline constexpr std::size_t kMaxPacketSize =
    kFrameSightingsOffset + kFrameSightingSize * static_cast<std::size_t>(kMaxBeaconSightings)
    + kFrameRangeSize * static_cast<std::size_t>(kMaxScanBeams);

/// Default ports: the robot stream (frames out, commands in), the ground-truth stream and
/// control requests. A server started with base port P uses P, P + 1 and P + 2.
inline constexpr std::uint16_t kDefaultRobotPort = 5600;
inline constexpr std::uint16_t kDefaultTruthPort = 5601;
inline constexpr std::uint16_t kDefaultControlPort = 5602;

enum class PacketType : std::uint8_t {
    SensorFrame = 0x01,       ///< server → client, robot port
    WheelCommand = 0x02,      ///< client → server, robot port
    Connect = 0x03,           ///< client → server, robot port
    ConnectReply = 0x04,      ///< server → client, robot port
    Disconnect = 0x05,        ///< client → server, robot port
    TruthSubscribe = 0x10,    ///< subscriber → server, truth port
    GroundTruth = 0x11,       ///< server → subscriber, truth port
    TruthUnsubscribe = 0x12,  ///< subscriber → server, truth port
    ControlRequest = 0x20,    ///< anyone → server, control port
    ControlReply = 0x21,      ///< server → requester, control port
};

/// The exact length of a packet of `type`, or 0 for a type this version does not know.
/// For SensorFrame: the length of the plain frame (no extension block); see frame_size().
std::size_t packet_size(PacketType type);

/// The length of the sensor frame that carries `frame`: the plain 36 bytes when it has none
/// of the optional sensors, else 52 + 9n + 2m with n = min(beacon count, kMaxBeaconSightings)
/// if it has a beacon scan (else 0) and m = min(laser beam count, kMaxScanBeams) if it has a
/// laser scan (else 0).
std::size_t frame_size(const SensorFrame& frame);

/// Whether `length` is a valid length field for `type`: packet_size(type) for every type;
/// for SensorFrame also 52 + 9n + 2m, n = 0 … kMaxBeaconSightings, m = 0 … kMaxScanBeams.
bool is_valid_length(PacketType type, std::size_t length);
std::string_view to_string(PacketType type);

/// Why a datagram was dropped. Each has a counter on the server and on the client.
enum class DecodeError : std::uint8_t {
    None,
    Truncated,    ///< shorter than the header or than its length field says
    BadMagic,     ///< does not start with "LFUP"
    BadVersion,   ///< a version other than kProtocolVersion
    UnknownType,  ///< a type this version does not define
    BadLength,    ///< the length field is not the size of its type
    Oversized,    ///< longer than its length field or than kMaxPacketSize
    NonFinite,    ///< a real field is NaN or infinite
    BadTime,      ///< the time stamp is beyond kMaxTimeMicroseconds
    WrongType,    ///< a valid packet of a type this decoder (stream) does not take
};
std::string_view to_string(DecodeError error);

struct PacketHeader {
    PacketType type = PacketType::SensorFrame;
    std::uint32_t sequence = 0;
    std::uint64_t time_us = 0;
};

/// Validates the header against the datagram's size: magic, version, known type, length.
DecodeError decode_header(std::span<const std::uint8_t> datagram, PacketHeader& header);

/// The largest time stamp (2^50 µs, 35 years). Up to it, µs → s (one correctly rounded
/// division) → µs (rounded) gives back the same integer: the relative error 2^-53 of each
/// step stays below a quarter µs. So decoding and re-encoding never changes a time.
inline constexpr std::uint64_t kMaxTimeMicroseconds = std::uint64_t{1} << 50;

/// Seconds ↔ the header's microseconds (rounded to the nearest; negative times and NaN
/// become 0, times beyond kMaxTimeMicroseconds saturate there).
std::uint64_t to_microseconds(double seconds);
double to_seconds(std::uint64_t microseconds);

// --- Robot stream ---------------------------------------------------------------------------

/// Flags of a sensor frame beyond the IR valid bits.
struct FrameFlags {
    bool watchdog_stopped = false;  ///< commands ceased; the motors were stopped (bit 2)
    bool paused = false;            ///< the simulation is paused; time does not advance (bit 3)
    bool reset = false;  ///< first frame after a reset: time and encoders restarted (bit 4)
};

struct FramePacket {
    SensorFrame frame;  ///< time and sequence come from the header
    FrameFlags flags;
};

struct CommandPacket {
    std::uint32_t sequence = 0;
    double answers_time = 0.0;  ///< s, the time of the newest frame the client had seen
    WheelSpeeds wheels;         ///< V1 (right), V2 (left), m/s
};

/// Connect and Disconnect: a header alone.
struct BarePacket {
    PacketType type = PacketType::Connect;
    std::uint32_t sequence = 0;
    double time = 0.0;
};

enum class ConnectResult : std::uint8_t {
    Accepted = 0,
    Busy = 1,  ///< another client drives the robot (see holder)
};

struct ConnectReplyPacket {
    std::uint32_t sequence = 0;
    double time = 0.0;
    ConnectResult result = ConnectResult::Accepted;
    Endpoint holder;              ///< the client now driving the robot (the caller if accepted)
    double control_period = 0.0;  ///< s of simulated time between frames
    double time_scale = 1.0;      ///< simulated s per real s; 0 = lockstep
};

// --- Truth stream ---------------------------------------------------------------------------

struct TruthPacket {
    std::uint32_t sequence = 0;
    GroundTruth truth;  ///< truth.time comes from the header
};

// --- Control stream -------------------------------------------------------------------------

enum class ControlOp : std::uint8_t {
    Status = 1,
    Reset = 2,  ///< seed, and the start pose if pose_given (else the world's start)
    Pause = 3,
    Resume = 4,
    SetNoise = 5,      ///< E_d, E_b, slip and IR noise
    Teleport = 6,      ///< pose
    SetTimeScale = 7,  ///< time_scale (0 = lockstep)
};
std::string_view to_string(ControlOp op);

/// The simulator's error and noise parameters that a client may change while it runs.
struct NoiseSettings {
    double wheel_diameter_ratio = 1.0;  ///< E_d
    double wheel_base_ratio = 1.0;      ///< E_b
    double slip_noise = 0.0;            ///< m^½
    double ir_noise = 0.0;              ///< σ of each IR distance, m

    friend bool operator==(const NoiseSettings&, const NoiseSettings&) = default;
};

struct ControlRequestPacket {
    std::uint32_t sequence = 0;
    std::uint32_t request_id = 0;  ///< echoed in the reply
    std::uint8_t op = 0;           ///< a ControlOp; unknown ops decode and get a reply
    // Arguments, depending on op (the others are sent as zero).
    std::uint64_t seed = 0;   ///< Reset
    bool pose_given = false;  ///< Reset
    Pose2 pose;               ///< Reset (if pose_given), Teleport
    NoiseSettings noise;      ///< SetNoise
    double time_scale = 0.0;  ///< SetTimeScale
};

enum class ControlResult : std::uint8_t {
    Ok = 0,
    Rejected = 1,   ///< the arguments were refused; the message says why
    UnknownOp = 2,  ///< this server does not know the op
};
std::string_view to_string(ControlResult result);

/// What the server counts. The order here is the order on the wire (docs/protocol.md).
struct ServerCounters {
    std::uint64_t frames_sent = 0;
    std::uint64_t truth_sent = 0;
    std::uint64_t commands_accepted = 0;
    std::uint64_t commands_duplicate = 0;  ///< a sequence already received
    std::uint64_t commands_late = 0;       ///< older than the newest accepted (reordered)
    std::uint64_t commands_missing = 0;    ///< sequence gaps not filled later (lost)
    std::uint64_t truncated = 0;
    std::uint64_t bad_magic = 0;
    std::uint64_t bad_version = 0;
    std::uint64_t unknown_type = 0;
    std::uint64_t bad_length = 0;
    std::uint64_t oversized = 0;
    std::uint64_t non_finite = 0;
    std::uint64_t bad_time = 0;
    std::uint64_t wrong_stream = 0;     ///< a valid packet sent to the wrong port
    std::uint64_t unexpected_peer = 0;  ///< robot-stream packets from a non-client
    std::uint64_t watchdog_stops = 0;   ///< times the motors were stopped for silence
    std::uint64_t control_requests = 0;
    std::uint64_t overruns = 0;  ///< times the server fell > max(50 ms, a period) behind
};

/// Adds one to the counter for a decode error (None adds nothing).
void count_decode_error(ServerCounters& counters, DecodeError error);

/// The longest texts a control reply carries: its NUL-padded fields are one byte longer. A
/// longer text is cut at the last UTF-8 character boundary that fits.
inline constexpr std::size_t kWorldNameMaxBytes = 31;
inline constexpr std::size_t kReplyMessageMaxBytes = 95;

struct ServerStatus {
    std::uint64_t steps = 0;  ///< control periods since the last reset
    double control_period = 0.0;
    double time_scale = 1.0;
    std::uint64_t seed = 0;
    NoiseSettings noise;
    bool paused = false;
    bool watchdog_stopped = false;
    bool client_connected = false;
    Endpoint client;
    std::string world_name;  ///< at most kWorldNameMaxBytes travel
    ServerCounters counters;
};

struct ControlReplyPacket {
    std::uint32_t sequence = 0;
    double time = 0.0;
    std::uint32_t request_id = 0;
    std::uint8_t op = 0;
    ControlResult result = ControlResult::Ok;
    ServerStatus status;  ///< after the request was carried out
    std::string message;  ///< why it was rejected (at most kReplyMessageMaxBytes travel)
};

// --- Encoding: each returns exactly packet_size(type) bytes (a sensor frame: frame_size()). ---

using Bytes = std::vector<std::uint8_t>;

Bytes encode(const FramePacket& packet);
Bytes encode(const CommandPacket& packet);
Bytes encode(const BarePacket& packet);
Bytes encode(const ConnectReplyPacket& packet);
Bytes encode(const TruthPacket& packet);
Bytes encode(const ControlRequestPacket& packet);
Bytes encode(const ControlReplyPacket& packet);

// --- Decoding: None and the packet, or the first reason to drop it. --------------------------

DecodeError decode(std::span<const std::uint8_t> datagram, FramePacket& packet);
/// The same, and on failure `reason` says which field and which length were wrong (for logs
/// and tests; e.g. "beacon count 3 needs length 79, the length field says 61").
DecodeError decode(std::span<const std::uint8_t> datagram, FramePacket& packet,
                   std::string& reason);
DecodeError decode(std::span<const std::uint8_t> datagram, CommandPacket& packet);
/// Takes Connect, Disconnect, TruthSubscribe and TruthUnsubscribe.
DecodeError decode(std::span<const std::uint8_t> datagram, BarePacket& packet);
DecodeError decode(std::span<const std::uint8_t> datagram, ConnectReplyPacket& packet);
DecodeError decode(std::span<const std::uint8_t> datagram, TruthPacket& packet);
DecodeError decode(std::span<const std::uint8_t> datagram, ControlRequestPacket& packet);
DecodeError decode(std::span<const std::uint8_t> datagram, ControlReplyPacket& packet);

}  // namespace legofeup::comms
