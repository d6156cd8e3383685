// The UDP protocol's encoders and decoders (comms/src/protocol.cpp) against
// docs/protocol.md: round trips, byte layouts worked out by hand, every malformation with
// its exact DecodeError, the decode-error counters, the µs ↔ s conversions and decoders fed
// truncated and random datagrams (the asan preset turns any read past a datagram into a
// failure).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "legofeup/comms/protocol.hpp"
#include "protocol_bytes_test_support.hpp"

namespace legofeup::comms {
namespace {

using namespace test_bytes;

using Span = std::span<const std::uint8_t>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// --- Test-side byte helpers, independent of comms' own byte order code ----------------------

void put_bytes(Bytes& bytes, std::size_t offset, std::initializer_list<std::uint8_t> values) {
    ASSERT_LE(offset + values.size(), bytes.size());
    std::copy(values.begin(), values.end(), bytes.begin() + static_cast<std::ptrdiff_t>(offset));
}

std::string hex(Span bytes) {
    std::string text;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        char byte[4];
        std::snprintf(byte, sizeof byte, "%02x", bytes[i]);
        if (i != 0) {
            text += (i % 16 == 0) ? '\n' : ' ';
        }
        text += byte;
    }
    return text;
}

/// Compares bytes and, on failure, shows both as hex dumps.
void expect_bytes(const Bytes& actual, const Bytes& expected) {
    EXPECT_EQ(actual, expected) << "actual:\n" << hex(actual) << "\nexpected:\n" << hex(expected);
}

/// Reals must survive bit for bit (−0.0 included).
void expect_same(double actual, double expected, const char* what) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(actual), std::bit_cast<std::uint64_t>(expected))
        << what << ": " << actual << " vs " << expected;
}

// --- The counters in the order of docs/protocol.md (written out here, not taken from comms) -

struct CounterField {
    const char* name;
    std::uint64_t ServerCounters::*member;
};

constexpr std::array<CounterField, 19> kCounters{{
    {"frames_sent", &ServerCounters::frames_sent},
    {"truth_sent", &ServerCounters::truth_sent},
    {"commands_accepted", &ServerCounters::commands_accepted},
    {"commands_duplicate", &ServerCounters::commands_duplicate},
    {"commands_late", &ServerCounters::commands_late},
    {"commands_missing", &ServerCounters::commands_missing},
    {"truncated", &ServerCounters::truncated},
    {"bad_magic", &ServerCounters::bad_magic},
    {"bad_version", &ServerCounters::bad_version},
    {"unknown_type", &ServerCounters::unknown_type},
    {"bad_length", &ServerCounters::bad_length},
    {"oversized", &ServerCounters::oversized},
    {"non_finite", &ServerCounters::non_finite},
    {"bad_time", &ServerCounters::bad_time},
    {"wrong_stream", &ServerCounters::wrong_stream},
    {"unexpected_peer", &ServerCounters::unexpected_peer},
    {"watchdog_stops", &ServerCounters::watchdog_stops},
    {"control_requests", &ServerCounters::control_requests},
    {"overruns", &ServerCounters::overruns},
}};
// Every field is listed: a counter added to the struct must be added here (and to the docs).
static_assert(sizeof(ServerCounters) == kCounters.size() * sizeof(std::uint64_t));

void expect_counters(const ServerCounters& actual, const ServerCounters& expected) {
    for (const CounterField& field : kCounters) {
        EXPECT_EQ(actual.*field.member, expected.*field.member) << field.name;
    }
}

/// Distinct values in every byte, different for each counter.
ServerCounters distinct_counters() {
    ServerCounters counters;
    for (std::size_t i = 0; i < kCounters.size(); ++i) {
        counters.*kCounters[i].member = 0x0102030405060708ULL * (i + 1) + i;
    }
    return counters;
}

// --- Sample packets ---------------------------------------------------------------------------

FramePacket sample_frame() {
    FramePacket packet;
    packet.frame.time = 22.45;
    packet.frame.sequence = 452;
    packet.frame.encoder_counts = {5417, -5199};
    packet.frame.ir_adc = {177, 1023};
    packet.frame.ir_valid = {true, false};
    packet.flags = {true, false, true};
    return packet;
}

/// A frame with the extension block: every optional sensor, two beacon sightings (79 bytes).
FramePacket sample_extended_frame() {
    FramePacket packet = sample_frame();
    packet.frame.has_gyro = true;
    packet.frame.gyro_raw = -17;
    packet.frame.has_accelerometers = true;
    packet.frame.accel_raw = {{{12, -200}, {-7, 201}}};
    packet.frame.has_compass = true;
    packet.frame.compass_deg = 271;
    packet.frame.has_beacon_scan = true;
    packet.frame.beacons.count = 2;
    packet.frame.beacons.sightings[0] = {1, 0.75};
    packet.frame.beacons.sightings[1] = {4, -2.5};
    return packet;
}

/// A frame with a gyroscope and a URG-04LX-like laser scan (682 beams, codes among them).
FramePacket sample_laser_frame() {
    FramePacket packet = sample_frame();
    packet.frame.has_gyro = true;
    packet.frame.gyro_raw = 600;
    packet.frame.has_laser_scan = true;
    packet.frame.laser.beam_count = 682;
    for (std::size_t i = 0; i < 682; ++i) {
        packet.frame.laser.range_mm[i] = static_cast<std::uint16_t>(i % 50 == 0 ? i % 3 : 500 + i);
    }
    return packet;
}

CommandPacket sample_command() {
    return {451, 22.45, {0.148, -0.052}};
}

BarePacket sample_bare(PacketType type) {
    return {type, 77, 0.0};
}

ConnectReplyPacket sample_connect_reply() {
    ConnectReplyPacket packet;
    packet.sequence = 12;
    packet.time = 3.5;
    packet.result = ConnectResult::Busy;
    packet.holder = {0xC0A80114, 40000};  // 192.168.1.20
    packet.control_period = 0.05;
    packet.time_scale = 20.0;
    return packet;
}

TruthPacket sample_truth() {
    TruthPacket packet;
    packet.sequence = 9001;
    packet.truth.time = 12.345678;
    packet.truth.pose = {0.25, -0.75, 3.0};
    packet.truth.velocity = {0.1, -0.8};
    packet.truth.wheel_surface_speeds = {0.148, 0.052};
    packet.truth.touching_wall = true;
    packet.truth.ir_distances = {0.15, 0.8};
    packet.truth.teleports = 3;
    return packet;
}

/// A request for `op` with the arguments that op carries (the others zero, as sent).
ControlRequestPacket sample_request(ControlOp op) {
    ControlRequestPacket packet;
    packet.sequence = 31;
    packet.request_id = 0xCAFEF00D;
    packet.op = static_cast<std::uint8_t>(op);
    switch (op) {
        case ControlOp::Reset:
            packet.seed = 0x0123456789ABCDEFULL;
            packet.pose_given = true;
            packet.pose = {0.5, -0.25, -1.5};
            break;
        case ControlOp::Teleport:
            packet.pose = {-1.0, 1.0, 3.1};
            break;
        case ControlOp::SetNoise:
            packet.noise = {1.01, 0.98, 0.02, 0.005};
            break;
        case ControlOp::SetTimeScale:
            packet.time_scale = 20.0;
            break;
        case ControlOp::Status:
        case ControlOp::Pause:
        case ControlOp::Resume:
            break;
    }
    return packet;
}

ControlReplyPacket sample_reply() {
    ControlReplyPacket packet;
    packet.sequence = 4;
    packet.time = 100.25;
    packet.request_id = 0xDEADBEEF;
    packet.op = static_cast<std::uint8_t>(ControlOp::SetNoise);
    packet.result = ControlResult::Rejected;
    ServerStatus& status = packet.status;
    status.steps = 0x1122334455667788ULL;
    status.control_period = 0.05;
    status.time_scale = 0.0;
    status.seed = 0x8877665544332211ULL;
    status.noise = {1.02, 0.97, 0.03, 0.01};
    status.paused = true;
    status.watchdog_stopped = false;
    status.client_connected = true;
    status.client = {0x0A000002, 51234};
    status.world_name = "standard arena";
    status.counters = distinct_counters();
    packet.message = "set noise: E_d = 3 must be between 0.5 and 2";
    return packet;
}

constexpr std::array kControlOps{ControlOp::Status,      ControlOp::Reset,    ControlOp::Pause,
                                 ControlOp::Resume,      ControlOp::SetNoise, ControlOp::Teleport,
                                 ControlOp::SetTimeScale};

constexpr std::array kBareTypes{PacketType::Connect, PacketType::Disconnect,
                                PacketType::TruthSubscribe, PacketType::TruthUnsubscribe};

constexpr std::array kAllTypes{
    PacketType::SensorFrame,  PacketType::WheelCommand,     PacketType::Connect,
    PacketType::ConnectReply, PacketType::Disconnect,       PacketType::TruthSubscribe,
    PacketType::GroundTruth,  PacketType::TruthUnsubscribe, PacketType::ControlRequest,
    PacketType::ControlReply,
};

/// A valid datagram of each type.
struct Sample {
    PacketType type;
    Bytes bytes;
};

std::vector<Sample> valid_samples() {
    std::vector<Sample> samples{
        {PacketType::SensorFrame, encode(sample_frame())},
        {PacketType::SensorFrame, encode(sample_extended_frame())},
        {PacketType::SensorFrame, encode(sample_laser_frame())},
        {PacketType::WheelCommand, encode(sample_command())},
        {PacketType::ConnectReply, encode(sample_connect_reply())},
        {PacketType::GroundTruth, encode(sample_truth())},
        {PacketType::ControlRequest, encode(sample_request(ControlOp::Reset))},
        {PacketType::ControlReply, encode(sample_reply())},
    };
    for (const PacketType type : kBareTypes) {
        samples.push_back({type, encode(sample_bare(type))});
    }
    return samples;
}

// --- Every decoder behind one signature --------------------------------------------------------

template <typename Packet>
DecodeError decode_as(Span datagram) {
    Packet packet;
    return decode(datagram, packet);
}

struct Decoder {
    const char* name;
    DecodeError (*decode)(Span);
    std::vector<PacketType> accepts;

    bool takes(PacketType type) const {
        return std::find(accepts.begin(), accepts.end(), type) != accepts.end();
    }
};

const std::vector<Decoder>& decoders() {
    static const std::vector<Decoder> all{
        {"frame", &decode_as<FramePacket>, {PacketType::SensorFrame}},
        {"command", &decode_as<CommandPacket>, {PacketType::WheelCommand}},
        {"bare", &decode_as<BarePacket>, {kBareTypes.begin(), kBareTypes.end()}},
        {"connect reply", &decode_as<ConnectReplyPacket>, {PacketType::ConnectReply}},
        {"truth", &decode_as<TruthPacket>, {PacketType::GroundTruth}},
        {"control request", &decode_as<ControlRequestPacket>, {PacketType::ControlRequest}},
        {"control reply", &decode_as<ControlReplyPacket>, {PacketType::ControlReply}},
    };
    return all;
}

const Decoder& decoder_for(PacketType type) {
    for (const Decoder& decoder : decoders()) {
        if (decoder.takes(type)) {
            return decoder;
        }
    }
    throw std::logic_error("no decoder");
}

// --- Field-by-field comparisons ---------------------------------------------------------------

void expect_equal(const FramePacket& actual, const FramePacket& expected) {
    expect_same(actual.frame.time, expected.frame.time, "time");
    EXPECT_EQ(actual.frame.sequence, expected.frame.sequence);
    EXPECT_EQ(actual.frame.encoder_counts, expected.frame.encoder_counts);
    EXPECT_EQ(actual.frame.ir_adc, expected.frame.ir_adc);
    EXPECT_EQ(actual.frame.ir_valid, expected.frame.ir_valid);
    EXPECT_EQ(actual.frame.has_gyro, expected.frame.has_gyro);
    EXPECT_EQ(actual.frame.gyro_raw, expected.frame.gyro_raw);
    EXPECT_EQ(actual.frame.has_accelerometers, expected.frame.has_accelerometers);
    EXPECT_EQ(actual.frame.accel_raw, expected.frame.accel_raw);
    EXPECT_EQ(actual.frame.has_compass, expected.frame.has_compass);
    EXPECT_EQ(actual.frame.compass_deg, expected.frame.compass_deg);
    EXPECT_EQ(actual.frame.has_beacon_scan, expected.frame.has_beacon_scan);
    EXPECT_EQ(actual.frame.beacons, expected.frame.beacons);
    EXPECT_EQ(actual.flags.watchdog_stopped, expected.flags.watchdog_stopped);
    EXPECT_EQ(actual.flags.paused, expected.flags.paused);
    EXPECT_EQ(actual.flags.reset, expected.flags.reset);
}

void expect_equal(const CommandPacket& actual, const CommandPacket& expected) {
    EXPECT_EQ(actual.sequence, expected.sequence);
    expect_same(actual.answers_time, expected.answers_time, "answers_time");
    expect_same(actual.wheels.right, expected.wheels.right, "right");
    expect_same(actual.wheels.left, expected.wheels.left, "left");
}

void expect_equal(const BarePacket& actual, const BarePacket& expected) {
    EXPECT_EQ(actual.type, expected.type);
    EXPECT_EQ(actual.sequence, expected.sequence);
    expect_same(actual.time, expected.time, "time");
}

void expect_equal(const ConnectReplyPacket& actual, const ConnectReplyPacket& expected) {
    EXPECT_EQ(actual.sequence, expected.sequence);
    expect_same(actual.time, expected.time, "time");
    EXPECT_EQ(actual.result, expected.result);
    EXPECT_EQ(actual.holder, expected.holder);
    expect_same(actual.control_period, expected.control_period, "control_period");
    expect_same(actual.time_scale, expected.time_scale, "time_scale");
}

void expect_equal(const TruthPacket& actual, const TruthPacket& expected) {
    EXPECT_EQ(actual.sequence, expected.sequence);
    const GroundTruth& a = actual.truth;
    const GroundTruth& e = expected.truth;
    expect_same(a.time, e.time, "time");
    expect_same(a.pose.x, e.pose.x, "x");
    expect_same(a.pose.y, e.pose.y, "y");
    expect_same(a.pose.theta, e.pose.theta, "theta");
    expect_same(a.velocity.v, e.velocity.v, "v");
    expect_same(a.velocity.w, e.velocity.w, "w");
    expect_same(a.wheel_surface_speeds.right, e.wheel_surface_speeds.right, "right");
    expect_same(a.wheel_surface_speeds.left, e.wheel_surface_speeds.left, "left");
    expect_same(a.ir_distances[0], e.ir_distances[0], "ir front");
    expect_same(a.ir_distances[1], e.ir_distances[1], "ir rear");
    EXPECT_EQ(a.touching_wall, e.touching_wall);
    EXPECT_EQ(a.teleports, e.teleports);
}

void expect_equal(const NoiseSettings& actual, const NoiseSettings& expected) {
    expect_same(actual.wheel_diameter_ratio, expected.wheel_diameter_ratio, "E_d");
    expect_same(actual.wheel_base_ratio, expected.wheel_base_ratio, "E_b");
    expect_same(actual.slip_noise, expected.slip_noise, "slip");
    expect_same(actual.ir_noise, expected.ir_noise, "ir noise");
}

void expect_equal(const ControlRequestPacket& actual, const ControlRequestPacket& expected) {
    EXPECT_EQ(actual.sequence, expected.sequence);
    EXPECT_EQ(actual.request_id, expected.request_id);
    EXPECT_EQ(actual.op, expected.op);
    EXPECT_EQ(actual.seed, expected.seed);
    EXPECT_EQ(actual.pose_given, expected.pose_given);
    expect_same(actual.pose.x, expected.pose.x, "x");
    expect_same(actual.pose.y, expected.pose.y, "y");
    expect_same(actual.pose.theta, expected.pose.theta, "theta");
    expect_equal(actual.noise, expected.noise);
    expect_same(actual.time_scale, expected.time_scale, "time_scale");
}

void expect_equal(const ControlReplyPacket& actual, const ControlReplyPacket& expected) {
    EXPECT_EQ(actual.sequence, expected.sequence);
    expect_same(actual.time, expected.time, "time");
    EXPECT_EQ(actual.request_id, expected.request_id);
    EXPECT_EQ(actual.op, expected.op);
    EXPECT_EQ(actual.result, expected.result);
    const ServerStatus& a = actual.status;
    const ServerStatus& e = expected.status;
    EXPECT_EQ(a.steps, e.steps);
    expect_same(a.control_period, e.control_period, "control_period");
    expect_same(a.time_scale, e.time_scale, "time_scale");
    EXPECT_EQ(a.seed, e.seed);
    expect_equal(a.noise, e.noise);
    EXPECT_EQ(a.paused, e.paused);
    EXPECT_EQ(a.watchdog_stopped, e.watchdog_stopped);
    EXPECT_EQ(a.client_connected, e.client_connected);
    EXPECT_EQ(a.client, e.client);
    EXPECT_EQ(a.world_name, e.world_name);
    expect_counters(a.counters, e.counters);
    EXPECT_EQ(actual.message, expected.message);
}

/// encode → size check → decode → the same fields.
template <typename Packet>
void expect_round_trip(const Packet& packet, PacketType type) {
    const Bytes bytes = encode(packet);
    EXPECT_EQ(bytes.size(), packet_size(type)) << to_string(type);
    Packet decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None) << to_string(type);
    expect_equal(decoded, packet);
}

// ===============================================================================================
// Sizes and names
// ===============================================================================================

TEST(Protocol, PacketSizesAreThoseOfTheSpecification) {
    EXPECT_EQ(packet_size(PacketType::SensorFrame), 36U);
    EXPECT_EQ(packet_size(PacketType::WheelCommand), 36U);
    EXPECT_EQ(packet_size(PacketType::Connect), 20U);
    EXPECT_EQ(packet_size(PacketType::ConnectReply), 44U);
    EXPECT_EQ(packet_size(PacketType::Disconnect), 20U);
    EXPECT_EQ(packet_size(PacketType::TruthSubscribe), 20U);
    EXPECT_EQ(packet_size(PacketType::GroundTruth), 100U);
    EXPECT_EQ(packet_size(PacketType::TruthUnsubscribe), 20U);
    EXPECT_EQ(packet_size(PacketType::ControlRequest), 60U);
    EXPECT_EQ(packet_size(PacketType::ControlReply), 384U);
    for (const PacketType type : kAllTypes) {
        EXPECT_LE(packet_size(type), kMaxPacketSize);
        EXPECT_GE(packet_size(type), kHeaderSize);
    }
}

TEST(Protocol, OnlyTheDefinedTypeBytesHaveASize) {
    for (int value = 0; value < 256; ++value) {
        const auto byte = static_cast<std::uint8_t>(value);
        const bool defined = std::any_of(kAllTypes.begin(), kAllTypes.end(), [&](PacketType t) {
            return static_cast<std::uint8_t>(t) == byte;
        });
        EXPECT_EQ(packet_size(static_cast<PacketType>(byte)) != 0, defined) << value;
    }
}

TEST(Protocol, NamesAreDistinct) {
    std::vector<std::string> names;
    for (const PacketType type : kAllTypes) {
        names.emplace_back(to_string(type));
    }
    for (const ControlOp op : kControlOps) {
        EXPECT_NE(to_string(op), "unknown");
    }
    EXPECT_EQ(to_string(static_cast<PacketType>(0x7F)), "unknown");
    EXPECT_EQ(to_string(static_cast<ControlOp>(42)), "unknown");
    EXPECT_EQ(to_string(DecodeError::WrongType), "wrong type for this stream");
    EXPECT_EQ(to_string(ControlResult::UnknownOp), "unknown op");
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

// ===============================================================================================
// Round trips
// ===============================================================================================

TEST(ProtocolRoundTrip, SensorFrameWithEveryFlagCombination) {
    for (unsigned bits = 0; bits < 32; ++bits) {
        FramePacket packet = sample_frame();
        packet.frame.ir_valid = {(bits & 1U) != 0, (bits & 2U) != 0};
        packet.flags = {(bits & 4U) != 0, (bits & 8U) != 0, (bits & 16U) != 0};
        SCOPED_TRACE(bits);
        expect_round_trip(packet, PacketType::SensorFrame);
    }
}

TEST(ProtocolRoundTrip, SensorFrameExtremes) {
    FramePacket packet;
    packet.frame.time = to_seconds(kMaxTimeMicroseconds);
    packet.frame.sequence = std::numeric_limits<std::uint32_t>::max();
    packet.frame.encoder_counts = {std::numeric_limits<std::int32_t>::min(),
                                   std::numeric_limits<std::int32_t>::max()};
    packet.frame.ir_adc = {0, std::numeric_limits<std::uint16_t>::max()};
    expect_round_trip(packet, PacketType::SensorFrame);

    packet.frame.time = 0.0;
    packet.frame.sequence = 0;
    packet.frame.encoder_counts = {-1, 0};
    expect_round_trip(packet, PacketType::SensorFrame);
}

TEST(ProtocolRoundTrip, WheelCommand) {
    expect_round_trip(sample_command(), PacketType::WheelCommand);
    // Extremes of the reals: negative zero, the smallest subnormal, the largest finite.
    expect_round_trip(CommandPacket{0, 0.0, {-0.0, std::numeric_limits<double>::denorm_min()}},
                      PacketType::WheelCommand);
    expect_round_trip(
        CommandPacket{std::numeric_limits<std::uint32_t>::max(),
                      1e6,
                      {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest()}},
        PacketType::WheelCommand);
}

TEST(ProtocolRoundTrip, HeaderOnlyPackets) {
    for (const PacketType type : kBareTypes) {
        SCOPED_TRACE(to_string(type));
        expect_round_trip(BarePacket{type, 0, 0.0}, type);
        expect_round_trip(BarePacket{type, 0xFEDCBA98, 7.000001}, type);
    }
}

TEST(ProtocolRoundTrip, ConnectReply) {
    expect_round_trip(sample_connect_reply(), PacketType::ConnectReply);
    ConnectReplyPacket accepted;
    accepted.sequence = 0;
    accepted.result = ConnectResult::Accepted;
    accepted.holder = {0x7F000001, 65535};
    accepted.control_period = 0.1;
    accepted.time_scale = 0.0;
    expect_round_trip(accepted, PacketType::ConnectReply);
}

TEST(ProtocolRoundTrip, GroundTruth) {
    expect_round_trip(sample_truth(), PacketType::GroundTruth);
    TruthPacket other = sample_truth();
    other.truth.touching_wall = false;
    other.truth.pose.theta = -3.141592653589793;
    expect_round_trip(other, PacketType::GroundTruth);
}

TEST(ProtocolRoundTrip, ControlRequestForEveryOp) {
    for (const ControlOp op : kControlOps) {
        SCOPED_TRACE(to_string(op));
        const ControlRequestPacket packet = sample_request(op);
        expect_round_trip(packet, PacketType::ControlRequest);
        // The header time of a request is always 0.
        const Bytes bytes = encode(packet);
        EXPECT_TRUE(std::all_of(bytes.begin() + 12, bytes.begin() + 20,
                                [](std::uint8_t b) { return b == 0; }));
    }
    ControlRequestPacket reset_to_start = sample_request(ControlOp::Reset);
    reset_to_start.pose_given = false;
    reset_to_start.pose = {};
    expect_round_trip(reset_to_start, PacketType::ControlRequest);
}

TEST(ProtocolRoundTrip, ControlReplyWithEveryFieldSet) {
    const ControlReplyPacket packet = sample_reply();
    // The sample really has 19 distinct counters.
    std::vector<std::uint64_t> values;
    for (const CounterField& field : kCounters) {
        values.push_back(packet.status.counters.*field.member);
    }
    std::sort(values.begin(), values.end());
    ASSERT_EQ(std::adjacent_find(values.begin(), values.end()), values.end());
    expect_round_trip(packet, PacketType::ControlReply);

    for (const ControlResult result :
         {ControlResult::Ok, ControlResult::Rejected, ControlResult::UnknownOp}) {
        ControlReplyPacket other = sample_reply();
        other.result = result;
        other.status.paused = false;
        other.status.watchdog_stopped = true;
        other.status.client_connected = false;
        other.message.clear();
        expect_round_trip(other, PacketType::ControlReply);
    }
}

TEST(ProtocolRoundTrip, ControlReplyTextsAreCutToTheirFields) {
    ControlReplyPacket packet = sample_reply();
    packet.status.world_name = std::string(31, 'w');  // exactly fits
    packet.message = std::string(95, 'm');
    expect_round_trip(packet, PacketType::ControlReply);

    packet.status.world_name = std::string(40, 'w') + "tail";
    packet.message = std::string(200, 'm') + "tail";
    const Bytes bytes = encode(packet);
    ASSERT_EQ(bytes.size(), 384U);
    EXPECT_EQ(bytes[104 + 31], 0);  // the NUL that ends the world name
    EXPECT_EQ(bytes[136], 0x08);    // frames_sent starts undamaged after the name
    EXPECT_EQ(bytes[383], 0);       // the NUL that ends the message
    ControlReplyPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_EQ(decoded.status.world_name, std::string(31, 'w'));
    EXPECT_EQ(decoded.message, std::string(95, 'm'));
    expect_counters(decoded.status.counters, packet.status.counters);
}

// A text too long for its field is cut before the character that would not fit whole, never
// inside it: what arrives is valid UTF-8. The characters' bytes are written out by hand.
TEST(ProtocolRoundTrip, ControlReplyTextsAreCutAtACharacterBoundary) {
    const std::string ellipsis = "\xE2\x80\xA6";      // U+2026 "…", 3 bytes
    const std::string e_acute = "\xC3\xA9";           // U+00E9 "é", 2 bytes
    const std::string grinning = "\xF0\x9F\x98\x80";  // U+1F600, 4 bytes
    struct Case {
        std::string text;
        std::string arrives;
    };
    const std::string m94(94, 'm');
    const std::vector<Case> messages = {
        {m94 + ellipsis, m94},  // bytes 94-96: dropped whole
        {std::string(93, 'm') + e_acute, std::string(93, 'm') + e_acute},  // 95 bytes: fits
        {m94 + e_acute, m94},                                     // bytes 94-95: dropped whole
        {std::string(92, 'm') + grinning, std::string(92, 'm')},  // bytes 92-95: dropped
        {std::string(91, 'm') + grinning, std::string(91, 'm') + grinning},  // 95: fits
        {std::string(95, 'm') + e_acute, std::string(95, 'm')},              // the cut is the limit
        {std::string(30, 'm') + ellipsis + ellipsis, std::string(30, 'm') + ellipsis + ellipsis},
    };
    for (const Case& message : messages) {
        ControlReplyPacket packet = sample_reply();
        packet.message = message.text;
        const Bytes bytes = encode(packet);
        ASSERT_EQ(bytes.size(), 384U);
        EXPECT_EQ(bytes[288 + message.arrives.size()], 0) << "the NUL after the kept text";
        ControlReplyPacket decoded;
        ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
        EXPECT_EQ(decoded.message, message.arrives) << message.text.size() << " bytes sent";
    }
    // The world name's field: 31 bytes of text.
    ControlReplyPacket packet = sample_reply();
    packet.status.world_name = std::string(30, 'w') + e_acute;  // bytes 30-31: dropped whole
    ControlReplyPacket decoded;
    ASSERT_EQ(decode(encode(packet), decoded), DecodeError::None);
    EXPECT_EQ(decoded.status.world_name, std::string(30, 'w'));
    packet.status.world_name = std::string(29, 'w') + e_acute;  // 31 bytes: fits
    ASSERT_EQ(decode(encode(packet), decoded), DecodeError::None);
    EXPECT_EQ(decoded.status.world_name, std::string(29, 'w') + e_acute);
}

TEST(ProtocolRoundTrip, TimesSurviveForWholeMicroseconds) {
    for (const double time : {0.0, 1e-6, 0.05, 1.25, 22.45, 3600.000001, 1e9}) {
        BarePacket packet{PacketType::Connect, 1, time};
        BarePacket decoded;
        ASSERT_EQ(decode(encode(packet), decoded), DecodeError::None);
        expect_same(decoded.time, time, "time");
    }
}

// ===============================================================================================
// Byte layouts worked out by hand (docs/protocol.md), independent of the encoder
// ===============================================================================================

TEST(ProtocolLayout, SensorFrame) {
    FramePacket packet;
    packet.frame.sequence = 0x01020304;
    packet.frame.time = 1.25;  // 1 250 000 µs = 0x1312D0
    packet.frame.encoder_counts = {360, -1};
    packet.frame.ir_adc = {512, 1023};
    packet.frame.ir_valid = {true, false};
    packet.flags = {true, false, true};  // watchdog (bit 2), reset (bit 4)

    const Bytes expected{
        0x4C, 0x46, 0x55, 0x50,                          // magic "LFUP"
        0x01,                                            // version
        0x01,                                            // type: sensor frame
        0x24, 0x00,                                      // length 36
        0x04, 0x03, 0x02, 0x01,                          // sequence 0x01020304
        0xD0, 0x12, 0x13, 0x00, 0x00, 0x00, 0x00, 0x00,  // time_us 1 250 000
        0x68, 0x01, 0x00, 0x00,                          // encoder right 360
        0xFF, 0xFF, 0xFF, 0xFF,                          // encoder left −1
        0x00, 0x02,                                      // IR front 512
        0xFF, 0x03,                                      // IR rear 1023
        0x15, 0x00,                                      // flags: front valid | watchdog | reset
        0x00, 0x00,                                      // reserved
    };
    expect_bytes(encode(packet), expected);

    FramePacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, packet);
}

TEST(ProtocolLayout, SensorFrameFlagBitsOneByOne) {
    // Each flag alone sets exactly its documented bit at offset 32.
    struct Case {
        const char* name;
        std::array<bool, 2> valid;
        FrameFlags flags;
        std::uint8_t bits;
    };
    const std::array cases{
        Case{"none", {false, false}, {false, false, false}, 0x00},
        Case{"front valid", {true, false}, {false, false, false}, 0x01},
        Case{"rear valid", {false, true}, {false, false, false}, 0x02},
        Case{"watchdog", {false, false}, {true, false, false}, 0x04},
        Case{"paused", {false, false}, {false, true, false}, 0x08},
        Case{"reset", {false, false}, {false, false, true}, 0x10},
    };
    for (const Case& c : cases) {
        FramePacket packet;
        packet.frame.ir_valid = c.valid;
        packet.flags = c.flags;
        const Bytes bytes = encode(packet);
        ASSERT_EQ(bytes.size(), 36U);
        EXPECT_EQ(bytes[32], c.bits) << c.name;
        EXPECT_EQ(bytes[33], 0) << c.name;
    }
}

TEST(ProtocolLayout, DecodesTheSpecificationsExampleFrame) {
    // docs/protocol.md, "Example datagrams".
    const Bytes datagram{0x4c, 0x46, 0x55, 0x50, 0x01, 0x01, 0x24, 0x00, 0xc4, 0x01, 0x00, 0x00,
                         0x50, 0x8f, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00, 0x29, 0x15, 0x00, 0x00,
                         0x4f, 0x14, 0x00, 0x00, 0xb1, 0x00, 0x1f, 0x00, 0x03, 0x00, 0x00, 0x00};
    FramePacket packet;
    ASSERT_EQ(decode(datagram, packet), DecodeError::None);
    EXPECT_EQ(packet.frame.sequence, 452U);
    EXPECT_EQ(packet.frame.time, 22.45);
    EXPECT_EQ(packet.frame.encoder_counts, (std::array<std::int32_t, 2>{5417, 5199}));
    EXPECT_EQ(packet.frame.ir_adc, (std::array<std::uint16_t, 2>{177, 31}));
    EXPECT_EQ(packet.frame.ir_valid, (std::array<bool, 2>{true, true}));
    EXPECT_FALSE(packet.flags.watchdog_stopped);
    EXPECT_FALSE(packet.flags.paused);
    EXPECT_FALSE(packet.flags.reset);
    expect_bytes(encode(packet), datagram);
}

TEST(ProtocolLayout, WheelCommand) {
    // 0.1 = 0x3FB999999999999A, −0.25 = 0xBFD0000000000000.
    const CommandPacket packet{7, 22.45, {0.1, -0.25}};
    const Bytes expected{
        0x4C, 0x46, 0x55, 0x50, 0x01, 0x02, 0x24, 0x00,  // magic, version, command, 36
        0x07, 0x00, 0x00, 0x00,                          // sequence 7
        0x50, 0x8F, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00,  // time_us 22 450 000
        0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xB9, 0x3F,  // V1 (right) 0.1
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0xBF,  // V2 (left) −0.25
    };
    expect_bytes(encode(packet), expected);

    CommandPacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, packet);
}

TEST(ProtocolLayout, DecodesTheSpecificationsExampleCommand) {
    const Bytes datagram{0x4c, 0x46, 0x55, 0x50, 0x01, 0x02, 0x24, 0x00, 0xc3, 0x01, 0x00, 0x00,
                         0x50, 0x8f, 0x56, 0x01, 0x00, 0x00, 0x00, 0x00, 0x8b, 0x6c, 0xe7, 0xfb,
                         0xa9, 0xf1, 0xc2, 0x3f, 0x39, 0xb4, 0xc8, 0x76, 0xbe, 0x9f, 0xaa, 0x3f};
    CommandPacket packet;
    ASSERT_EQ(decode(datagram, packet), DecodeError::None);
    EXPECT_EQ(packet.sequence, 451U);
    EXPECT_EQ(packet.answers_time, 22.45);
    EXPECT_EQ(packet.wheels.right, 0.148);
    EXPECT_EQ(packet.wheels.left, 0.052);
}

TEST(ProtocolLayout, Connect) {
    // docs/protocol.md: the first Connect of a client.
    const Bytes expected{0x4c, 0x46, 0x55, 0x50, 0x01, 0x03, 0x14, 0x00, 0x00, 0x00,
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
    expect_bytes(encode(BarePacket{PacketType::Connect, 0, 0.0}), expected);
    BarePacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    EXPECT_EQ(decoded.type, PacketType::Connect);
}

TEST(ProtocolLayout, HeaderOnlyTypeBytes) {
    const std::array<std::pair<PacketType, std::uint8_t>, 4> types{{
        {PacketType::Connect, 0x03},
        {PacketType::Disconnect, 0x05},
        {PacketType::TruthSubscribe, 0x10},
        {PacketType::TruthUnsubscribe, 0x12},
    }};
    for (const auto& [type, byte] : types) {
        const Bytes bytes = encode(BarePacket{type, 0x0A0B0C0D, 0.000002});
        Bytes expected{0x4C, 0x46, 0x55, 0x50, 0x01, byte, 0x14, 0x00, 0x0D, 0x0C,
                       0x0B, 0x0A, 0x02, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
        expect_bytes(bytes, expected);
    }
}

TEST(ProtocolLayout, ConnectReplyPortBeforeAddressInNetworkOrder) {
    ConnectReplyPacket packet;
    packet.sequence = 3;
    packet.time = 1.5;  // 1 500 000 µs = 0x16E360
    packet.result = ConnectResult::Busy;
    packet.holder = {0x7F000001, 5600};  // 127.0.0.1:5600
    packet.control_period = 0.05;        // 0x3FA999999999999A
    packet.time_scale = 1.0;             // 0x3FF0000000000000
    const Bytes expected{
        0x4C, 0x46, 0x55, 0x50, 0x01, 0x04, 0x2C, 0x00,  // magic, version, connect reply, 44
        0x03, 0x00, 0x00, 0x00,                          // sequence 3
        0x60, 0xE3, 0x16, 0x00, 0x00, 0x00, 0x00, 0x00,  // time_us 1 500 000
        0x01,                                            // result: busy
        0x00,                                            // reserved
        0xE0, 0x15,                                      // holder port 5600
        0x7F, 0x00, 0x00, 0x01,                          // holder 127.0.0.1
        0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xA9, 0x3F,  // control period 0.05
        0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // time scale 1
    };
    expect_bytes(encode(packet), expected);

    ConnectReplyPacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, packet);

    // An address whose bytes all differ: 192.168.1.20:40000.
    Bytes other = expected;
    put_bytes(other, 22, {0x40, 0x9C, 0xC0, 0xA8, 0x01, 0x14});
    ASSERT_EQ(decode(other, decoded), DecodeError::None);
    EXPECT_EQ(decoded.holder.address, 0xC0A80114U);
    EXPECT_EQ(decoded.holder.port, 40000);
    EXPECT_EQ(decoded.holder.to_string(), "192.168.1.20:40000");
}

TEST(ProtocolLayout, GroundTruth) {
    TruthPacket packet;
    packet.sequence = 0x100;
    packet.truth.time = 0.5;  // 500 000 µs = 0x07A120
    packet.truth.pose = {1.5, -0.25, 0.1};
    packet.truth.velocity = {0.05, 1.0};
    packet.truth.wheel_surface_speeds = {0.148, 0.052};
    packet.truth.ir_distances = {0.3, -2.75};
    packet.truth.touching_wall = true;
    packet.truth.teleports = 0x01020304;

    Bytes expected(100, 0);
    put_bytes(expected, 0, {0x4C, 0x46, 0x55, 0x50, 0x01, 0x11, 0x64, 0x00,  // 100 bytes
                            0x00, 0x01, 0x00, 0x00,                          // sequence 256
                            0x20, 0xA1, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00});
    put_bytes(expected, 20, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F});  // x 1.5
    put_bytes(expected, 28, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0xBF});  // y −0.25
    put_bytes(expected, 36, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xB9, 0x3F});  // θ 0.1
    put_bytes(expected, 44, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xA9, 0x3F});  // v 0.05
    put_bytes(expected, 52, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F});  // w 1
    put_bytes(expected, 60, {0x8B, 0x6C, 0xE7, 0xFB, 0xA9, 0xF1, 0xC2, 0x3F});  // right 0.148
    put_bytes(expected, 68, {0x39, 0xB4, 0xC8, 0x76, 0xBE, 0x9F, 0xAA, 0x3F});  // left 0.052
    put_bytes(expected, 76, {0x33, 0x33, 0x33, 0x33, 0x33, 0x33, 0xD3, 0x3F});  // front 0.3
    put_bytes(expected, 84, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x06, 0xC0});  // rear −2.75
    put_bytes(expected, 92, {0x01});                                            // touching
    put_bytes(expected, 96, {0x04, 0x03, 0x02, 0x01});  // teleports 0x01020304, u32 LE
    expect_bytes(encode(packet), expected);

    TruthPacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, packet);
}

Bytes request_header() {
    Bytes bytes(60, 0);
    put_bytes(bytes, 0, {0x4C, 0x46, 0x55, 0x50, 0x01, 0x20, 0x3C, 0x00,  // 60 bytes
                         0x05, 0x00, 0x00, 0x00,                          // sequence 5
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // time 0
                         0x44, 0x33, 0x22, 0x11});                        // request id
    return bytes;
}

TEST(ProtocolLayout, ControlRequests) {
    ControlRequestPacket reset;
    reset.sequence = 5;
    reset.request_id = 0x11223344;
    reset.op = 2;
    reset.seed = 0x0102030405060708ULL;
    reset.pose_given = true;
    reset.pose = {1.5, -0.25, 0.1};
    Bytes expected = request_header();
    put_bytes(expected, 24, {0x02, 0x01, 0x00, 0x00});  // Reset, pose given, reserved
    put_bytes(expected, 28, {0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01});  // seed
    put_bytes(expected, 36, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F});  // x 1.5
    put_bytes(expected, 44, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0xBF});  // y −0.25
    put_bytes(expected, 52, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xB9, 0x3F});  // θ 0.1
    expect_bytes(encode(reset), expected);
    ControlRequestPacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, reset);

    // Teleport: the seed slot stays 0, the pose follows at 36.
    ControlRequestPacket teleport = reset;
    teleport.op = 6;
    teleport.pose_given = false;
    expected = request_header();
    put_bytes(expected, 24, {0x06});
    put_bytes(expected, 36, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F});
    put_bytes(expected, 44, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0xBF});
    put_bytes(expected, 52, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xB9, 0x3F});
    expect_bytes(encode(teleport), expected);

    // SetNoise: E_d, E_b, slip, IR σ from 28.
    ControlRequestPacket noise;
    noise.sequence = 5;
    noise.request_id = 0x11223344;
    noise.op = 5;
    noise.noise = {1.5, 1.0, 0.05, 0.3};
    expected = request_header();
    put_bytes(expected, 24, {0x05});
    put_bytes(expected, 28, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F});
    put_bytes(expected, 36, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F});
    put_bytes(expected, 44, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xA9, 0x3F});
    put_bytes(expected, 52, {0x33, 0x33, 0x33, 0x33, 0x33, 0x33, 0xD3, 0x3F});
    expect_bytes(encode(noise), expected);
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, noise);

    // SetTimeScale: 20 = 0x4034000000000000 at 28.
    ControlRequestPacket scale;
    scale.sequence = 5;
    scale.request_id = 0x11223344;
    scale.op = 7;
    scale.time_scale = 20.0;
    expected = request_header();
    put_bytes(expected, 24, {0x07});
    put_bytes(expected, 28, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x34, 0x40});
    expect_bytes(encode(scale), expected);

    // Status, Pause, Resume and unknown ops carry no arguments: fields set in the struct
    // that the op does not use are sent as zero.
    for (const std::uint8_t op : std::initializer_list<std::uint8_t>{1, 3, 4, 42}) {
        ControlRequestPacket bare = reset;
        bare.op = op;
        bare.pose_given = false;
        bare.noise = {2.0, 2.0, 2.0, 2.0};
        bare.time_scale = 3.0;
        expected = request_header();
        put_bytes(expected, 24, {op});
        expect_bytes(encode(bare), expected);
    }
}

TEST(ProtocolLayout, ControlReply) {
    ControlReplyPacket packet;
    packet.sequence = 9;
    packet.time = 2.0;  // 2 000 000 µs = 0x1E8480
    packet.request_id = 0xDEADBEEF;
    packet.op = 2;
    packet.result = ControlResult::Rejected;
    ServerStatus& status = packet.status;
    status.steps = 123456789;  // 0x075BCD15
    status.control_period = 0.05;
    status.time_scale = 0.1;
    status.seed = 0x0102030405060708ULL;
    status.noise = {1.5, 1.0, 0.05, 0.3};
    status.paused = true;
    status.watchdog_stopped = false;
    status.client_connected = true;
    status.client = {0xC0A80114, 40000};  // 192.168.1.20:40000
    status.world_name = "arena";
    for (std::size_t i = 0; i < kCounters.size(); ++i) {
        status.counters.*kCounters[i].member = 0x0101ULL * (i + 1);
    }
    packet.message = "no";

    Bytes expected(384, 0);
    put_bytes(expected, 0, {0x4C, 0x46, 0x55, 0x50, 0x01, 0x21, 0x80, 0x01,  // 384 bytes
                            0x09, 0x00, 0x00, 0x00,                          // sequence 9
                            0x80, 0x84, 0x1E, 0x00, 0x00, 0x00, 0x00, 0x00,  // 2 s
                            0xEF, 0xBE, 0xAD, 0xDE,                          // request id
                            0x02, 0x01, 0x00, 0x00});  // op Reset, rejected, reserved
    put_bytes(expected, 28, {0x15, 0xCD, 0x5B, 0x07, 0x00, 0x00, 0x00, 0x00});  // steps
    put_bytes(expected, 36, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xA9, 0x3F});  // period 0.05
    put_bytes(expected, 44, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xB9, 0x3F});  // scale 0.1
    put_bytes(expected, 52, {0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01});  // seed
    put_bytes(expected, 60, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F});  // E_d 1.5
    put_bytes(expected, 68, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F});  // E_b 1
    put_bytes(expected, 76, {0x9A, 0x99, 0x99, 0x99, 0x99, 0x99, 0xA9, 0x3F});  // slip 0.05
    put_bytes(expected, 84, {0x33, 0x33, 0x33, 0x33, 0x33, 0x33, 0xD3, 0x3F});  // IR σ 0.3
    put_bytes(expected, 92, {0x01, 0x00, 0x01, 0x00});  // paused, watchdog, connected
    put_bytes(expected, 96, {0xC0, 0xA8, 0x01, 0x14, 0x40, 0x9C, 0x00, 0x00});  // client
    put_bytes(expected, 104, {'a', 'r', 'e', 'n', 'a'});
    for (std::size_t i = 0; i < kCounters.size(); ++i) {
        put_u64(expected, 136 + 8 * i, 0x0101ULL * (i + 1));  // the docs' counter table
    }
    put_bytes(expected, 288, {'n', 'o'});
    expect_bytes(encode(packet), expected);

    ControlReplyPacket decoded;
    ASSERT_EQ(decode(expected, decoded), DecodeError::None);
    expect_equal(decoded, packet);
}

// ===============================================================================================
// Malformations: each with its exact DecodeError
// ===============================================================================================

TEST(ProtocolMalformed, ShorterThanTheHeaderIsTruncated) {
    for (const Decoder& decoder : decoders()) {
        SCOPED_TRACE(decoder.name);
        EXPECT_EQ(decoder.decode({}), DecodeError::Truncated);
        const Bytes frame = encode(sample_frame());
        const Bytes nineteen(frame.begin(), frame.begin() + 19);
        EXPECT_EQ(decoder.decode(nineteen), DecodeError::Truncated);
        // Size is checked before content: 19 garbage bytes are truncated, not bad magic.
        EXPECT_EQ(decoder.decode(Bytes(19, 0xAB)), DecodeError::Truncated);
    }
    PacketHeader header;
    EXPECT_EQ(decode_header({}, header), DecodeError::Truncated);
}

TEST(ProtocolMalformed, WrongMagic) {
    for (const Sample& sample : valid_samples()) {
        for (std::size_t i = 0; i < 4; ++i) {
            Bytes bytes = sample.bytes;
            bytes[i] ^= 0x20;  // "lFUP", "LfUP", …
            EXPECT_EQ(decoder_for(sample.type).decode(bytes), DecodeError::BadMagic)
                << to_string(sample.type) << " byte " << i;
        }
    }
    Bytes bytes = encode(sample_frame());
    put_bytes(bytes, 0, {'P', 'U', 'F', 'L'});  // the magic byte-swapped
    FramePacket packet;
    EXPECT_EQ(decode(bytes, packet), DecodeError::BadMagic);
}

TEST(ProtocolMalformed, OtherVersions) {
    for (const std::uint8_t version : std::initializer_list<std::uint8_t>{0, 2, 0x7F, 0xFF}) {
        for (const Sample& sample : valid_samples()) {
            Bytes bytes = sample.bytes;
            bytes[4] = version;
            EXPECT_EQ(decoder_for(sample.type).decode(bytes), DecodeError::BadVersion)
                << to_string(sample.type) << " version " << int{version};
        }
    }
}

TEST(ProtocolMalformed, UnknownTypes) {
    for (int value = 0; value < 256; ++value) {
        const auto type = static_cast<std::uint8_t>(value);
        if (packet_size(static_cast<PacketType>(type)) != 0) {
            continue;
        }
        Bytes bytes = encode(sample_frame());
        bytes[5] = type;
        for (const Decoder& decoder : decoders()) {
            EXPECT_EQ(decoder.decode(bytes), DecodeError::UnknownType)
                << decoder.name << " type " << value;
        }
    }
    // The one the brief names, spelled out.
    Bytes bytes = encode(sample_frame());
    bytes[5] = 0x7F;
    FramePacket packet;
    EXPECT_EQ(decode(bytes, packet), DecodeError::UnknownType);
}

TEST(ProtocolMalformed, LengthFieldNotTheTypesSize) {
    for (const Sample& sample : valid_samples()) {
        const auto size = static_cast<std::uint16_t>(sample.bytes.size());
        std::vector<std::uint16_t> lengths{
            0,   20,    static_cast<std::uint16_t>(size - 1), static_cast<std::uint16_t>(size + 1),
            512, 0xFFFF};
        if (sample.type == PacketType::SensorFrame) {
            // A frame may be 36 or 52 + 9n + 2m long (n ≤ 8 sightings, m ≤ 1024 laser beams):
            // its neighbours are mostly valid too, so take lengths that no frame has.
            lengths = {0, 20, 35, 37, 51, 53, 59, 2165, 2173, 0xFFFF};
        }
        for (const std::uint16_t length : lengths) {
            if (length == size) {
                continue;  // 20 is the right size of the header-only packets
            }
            Bytes bytes = sample.bytes;
            put_u16(bytes, 6, length);
            EXPECT_EQ(decoder_for(sample.type).decode(bytes), DecodeError::BadLength)
                << to_string(sample.type) << " length " << length;
        }
    }
    // A frame-sized datagram claiming a frame's type but a command reply's length, and a
    // datagram whose length field matches its size but not its type.
    Bytes bytes = encode(sample_frame());
    put_u16(bytes, 6, 44);
    FramePacket frame;
    EXPECT_EQ(decode(bytes, frame), DecodeError::BadLength);
    bytes.resize(44, 0);
    EXPECT_EQ(decode(bytes, frame), DecodeError::BadLength);
}

TEST(ProtocolMalformed, ShorterThanTheLengthFieldIsTruncated) {
    for (const Sample& sample : valid_samples()) {
        if (sample.bytes.size() == kHeaderSize) {
            continue;  // header-only packets cannot be cut without cutting the header
        }
        const Bytes cut(sample.bytes.begin(), sample.bytes.end() - 1);
        EXPECT_EQ(decoder_for(sample.type).decode(cut), DecodeError::Truncated)
            << to_string(sample.type);
        const Bytes header_only(sample.bytes.begin(), sample.bytes.begin() + 20);
        EXPECT_EQ(decoder_for(sample.type).decode(header_only), DecodeError::Truncated)
            << to_string(sample.type);
    }
}

TEST(ProtocolMalformed, LongerThanTheLengthFieldOrTheMaximumIsOversized) {
    for (const Sample& sample : valid_samples()) {
        Bytes longer = sample.bytes;
        longer.push_back(0);
        EXPECT_EQ(decoder_for(sample.type).decode(longer), DecodeError::Oversized)
            << to_string(sample.type);
        Bytes largest = sample.bytes;
        largest.resize(kMaxPacketSize, 0);
        if (largest.size() != sample.bytes.size()) {
            EXPECT_EQ(decoder_for(sample.type).decode(largest), DecodeError::Oversized)
                << to_string(sample.type);
        }
        Bytes beyond = sample.bytes;
        beyond.resize(kMaxPacketSize + 1, 0);
        EXPECT_EQ(decoder_for(sample.type).decode(beyond), DecodeError::Oversized)
            << to_string(sample.type);
    }
    // Beyond kMaxPacketSize (2172) bytes nothing else is looked at (docs' order: oversized
    // first); at 2172 the content is checked.
    for (const Decoder& decoder : decoders()) {
        EXPECT_EQ(decoder.decode(Bytes(kMaxPacketSize + 1, 0xAB)), DecodeError::Oversized)
            << decoder.name;
        EXPECT_EQ(decoder.decode(Bytes(65536, 0)), DecodeError::Oversized) << decoder.name;
        EXPECT_EQ(decoder.decode(Bytes(kMaxPacketSize, 0xAB)), DecodeError::BadMagic)
            << decoder.name;
    }
}

TEST(ProtocolMalformed, ChecksComeInTheDocumentedOrder) {
    const Bytes frame = encode(sample_frame());
    FramePacket packet;
    // Bad magic, version, type and length all at once: magic is reported.
    Bytes bytes = frame;
    put_bytes(bytes, 0, {'X', 'F', 'U', 'P', 9, 0x7F, 0xFF, 0xFF});
    EXPECT_EQ(decode(bytes, packet), DecodeError::BadMagic);
    // Bad version, type and length: version.
    bytes = frame;
    put_bytes(bytes, 4, {9, 0x7F, 0xFF, 0xFF});
    EXPECT_EQ(decode(bytes, packet), DecodeError::BadVersion);
    // Bad type and length: type.
    bytes = frame;
    put_bytes(bytes, 5, {0x7F, 0xFF, 0xFF});
    EXPECT_EQ(decode(bytes, packet), DecodeError::UnknownType);
    // Bad length and bad time: length.
    bytes = frame;
    put_u16(bytes, 6, 37);
    put_u64(bytes, 12, ~std::uint64_t{0});
    EXPECT_EQ(decode(bytes, packet), DecodeError::BadLength);
    // Bad time on the wrong stream: time.
    bytes = encode(sample_command());
    put_u64(bytes, 12, kMaxTimeMicroseconds + 1);
    EXPECT_EQ(decode(bytes, packet), DecodeError::BadTime);
    // Non-finite on the wrong stream: wrong type.
    put_u64(bytes, 12, 0);
    put_f64(bytes, 20, kNaN);
    EXPECT_EQ(decode(bytes, packet), DecodeError::WrongType);
    // Non-finite and bad time: time.
    CommandPacket command;
    EXPECT_EQ(decode(bytes, command), DecodeError::NonFinite);
    put_u64(bytes, 12, kMaxTimeMicroseconds + 1);
    EXPECT_EQ(decode(bytes, command), DecodeError::BadTime);
}

/// Bit patterns that are not finite: quiet and signalling NaNs of both signs, ±infinity.
constexpr std::array<std::uint64_t, 6> kNonFinite{
    0x7FF8000000000000ULL,  // quiet NaN
    0xFFF8000000000000ULL,  // negative quiet NaN
    0x7FF0000000000001ULL,  // signalling NaN
    0xFFFFFFFFFFFFFFFFULL,  // NaN, all ones
    0x7FF0000000000000ULL,  // +infinity
    0xFFF0000000000000ULL,  // −infinity
};

static_assert(std::bit_cast<std::uint64_t>(kInf) == 0x7FF0000000000000ULL);

/// Every non-finite value at `offset` makes the datagram NonFinite; the largest finite
/// values there still decode.
void expect_non_finite_rejected(const Bytes& valid, PacketType type, std::size_t offset,
                                const char* field) {
    const Decoder& decoder = decoder_for(type);
    ASSERT_EQ(decoder.decode(valid), DecodeError::None) << field;
    for (const std::uint64_t bits : kNonFinite) {
        Bytes bytes = valid;
        put_u64(bytes, offset, bits);
        EXPECT_EQ(decoder.decode(bytes), DecodeError::NonFinite)
            << to_string(type) << " " << field << " at " << offset << " bits " << std::hex << bits;
    }
    for (const double finite :
         {std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(), -0.0}) {
        Bytes bytes = valid;
        put_f64(bytes, offset, finite);
        EXPECT_EQ(decoder.decode(bytes), DecodeError::None)
            << to_string(type) << " " << field << " = " << finite;
    }
}

TEST(ProtocolMalformed, NonFiniteWheelSpeeds) {
    const Bytes valid = encode(sample_command());
    expect_non_finite_rejected(valid, PacketType::WheelCommand, 20, "V1");
    expect_non_finite_rejected(valid, PacketType::WheelCommand, 28, "V2");
    // Encoding a NaN does not hide it from the decoder.
    CommandPacket packet = sample_command();
    packet.wheels.left = kNaN;
    CommandPacket decoded;
    EXPECT_EQ(decode(encode(packet), decoded), DecodeError::NonFinite);
    packet.wheels = {-kInf, 0.0};
    EXPECT_EQ(decode(encode(packet), decoded), DecodeError::NonFinite);
}

TEST(ProtocolMalformed, NonFiniteGroundTruth) {
    const Bytes valid = encode(sample_truth());
    constexpr std::array names{"x", "y", "theta", "v", "w", "right", "left", "IR front", "IR rear"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        expect_non_finite_rejected(valid, PacketType::GroundTruth, 20 + 8 * i, names[i]);
    }
}

TEST(ProtocolMalformed, NonFiniteConnectReply) {
    const Bytes valid = encode(sample_connect_reply());
    expect_non_finite_rejected(valid, PacketType::ConnectReply, 28, "control period");
    expect_non_finite_rejected(valid, PacketType::ConnectReply, 36, "time scale");
}

TEST(ProtocolMalformed, NonFiniteControlRequestArguments) {
    const Bytes reset = encode(sample_request(ControlOp::Reset));
    expect_non_finite_rejected(reset, PacketType::ControlRequest, 36, "reset x");
    expect_non_finite_rejected(reset, PacketType::ControlRequest, 44, "reset y");
    expect_non_finite_rejected(reset, PacketType::ControlRequest, 52, "reset theta");

    // Reset checks its pose even when "pose given" is clear (docs/protocol.md).
    ControlRequestPacket start = sample_request(ControlOp::Reset);
    start.pose_given = false;
    const Bytes reset_to_start = encode(start);
    expect_non_finite_rejected(reset_to_start, PacketType::ControlRequest, 36, "reset x");
    expect_non_finite_rejected(reset_to_start, PacketType::ControlRequest, 52, "reset theta");

    const Bytes teleport = encode(sample_request(ControlOp::Teleport));
    expect_non_finite_rejected(teleport, PacketType::ControlRequest, 36, "teleport x");
    expect_non_finite_rejected(teleport, PacketType::ControlRequest, 44, "teleport y");
    expect_non_finite_rejected(teleport, PacketType::ControlRequest, 52, "teleport theta");

    const Bytes noise = encode(sample_request(ControlOp::SetNoise));
    expect_non_finite_rejected(noise, PacketType::ControlRequest, 28, "E_d");
    expect_non_finite_rejected(noise, PacketType::ControlRequest, 36, "E_b");
    expect_non_finite_rejected(noise, PacketType::ControlRequest, 44, "slip");
    expect_non_finite_rejected(noise, PacketType::ControlRequest, 52, "IR sigma");

    const Bytes scale = encode(sample_request(ControlOp::SetTimeScale));
    expect_non_finite_rejected(scale, PacketType::ControlRequest, 28, "time scale");
}

TEST(ProtocolMalformed, NonFiniteControlReplyStatus) {
    const Bytes valid = encode(sample_reply());
    expect_non_finite_rejected(valid, PacketType::ControlReply, 36, "control period");
    expect_non_finite_rejected(valid, PacketType::ControlReply, 44, "time scale");
    expect_non_finite_rejected(valid, PacketType::ControlReply, 60, "E_d");
    expect_non_finite_rejected(valid, PacketType::ControlReply, 68, "E_b");
    expect_non_finite_rejected(valid, PacketType::ControlReply, 76, "slip");
    expect_non_finite_rejected(valid, PacketType::ControlReply, 84, "IR sigma");
}

TEST(ProtocolMalformed, NaNPatternsInIntegerFieldsAreJustIntegers) {
    // steps and seed of the reply and the seed of a reset are u64, not reals.
    Bytes reply = encode(sample_reply());
    put_u64(reply, 28, 0x7FF8000000000000ULL);
    put_u64(reply, 52, 0xFFF0000000000000ULL);
    ControlReplyPacket decoded_reply;
    ASSERT_EQ(decode(reply, decoded_reply), DecodeError::None);
    EXPECT_EQ(decoded_reply.status.steps, 0x7FF8000000000000ULL);
    EXPECT_EQ(decoded_reply.status.seed, 0xFFF0000000000000ULL);

    Bytes reset = encode(sample_request(ControlOp::Reset));
    put_u64(reset, 28, 0x7FF0000000000001ULL);
    ControlRequestPacket decoded_reset;
    ASSERT_EQ(decode(reset, decoded_reset), DecodeError::None);
    EXPECT_EQ(decoded_reset.seed, 0x7FF0000000000001ULL);
}

TEST(ProtocolMalformed, ArgumentsAnOpDoesNotUseAreNotChecked) {
    struct Case {
        ControlOp op;
        std::vector<std::size_t> unused;
    };
    const std::array cases{
        Case{ControlOp::Status, {28, 36, 44, 52}},   Case{ControlOp::Pause, {28, 36, 44, 52}},
        Case{ControlOp::Resume, {28, 36, 44, 52}},   Case{ControlOp::Teleport, {28}},
        Case{ControlOp::SetTimeScale, {36, 44, 52}},
    };
    for (const Case& c : cases) {
        Bytes bytes = encode(sample_request(c.op));
        for (const std::size_t offset : c.unused) {
            put_f64(bytes, offset, kNaN);
        }
        ControlRequestPacket decoded;
        EXPECT_EQ(decode(bytes, decoded), DecodeError::None) << to_string(c.op);
        EXPECT_EQ(decoded.op, static_cast<std::uint8_t>(c.op));
    }
}

TEST(ProtocolMalformed, TimeBeyondTheLimit) {
    for (const Sample& sample : valid_samples()) {
        const Decoder& decoder = decoder_for(sample.type);
        Bytes bytes = sample.bytes;
        put_u64(bytes, 12, kMaxTimeMicroseconds);
        EXPECT_EQ(decoder.decode(bytes), DecodeError::None) << to_string(sample.type);
        for (const std::uint64_t time :
             {kMaxTimeMicroseconds + 1, kMaxTimeMicroseconds * 2, ~std::uint64_t{0}}) {
            put_u64(bytes, 12, time);
            EXPECT_EQ(decoder.decode(bytes), DecodeError::BadTime)
                << to_string(sample.type) << " time " << time;
        }
    }
    PacketHeader header;
    Bytes bytes = encode(sample_frame());
    put_u64(bytes, 12, kMaxTimeMicroseconds + 1);
    EXPECT_EQ(decode_header(bytes, header), DecodeError::BadTime);
}

TEST(ProtocolMalformed, ValidPacketsGivenToTheWrongDecoder) {
    for (const Sample& sample : valid_samples()) {
        for (const Decoder& decoder : decoders()) {
            const DecodeError expected =
                decoder.takes(sample.type) ? DecodeError::None : DecodeError::WrongType;
            EXPECT_EQ(decoder.decode(sample.bytes), expected)
                << to_string(sample.type) << " given to the " << decoder.name << " decoder";
        }
    }
}

TEST(ProtocolMalformed, DecodeHeaderReadsTheHeader) {
    PacketHeader header;
    ASSERT_EQ(decode_header(encode(sample_frame()), header), DecodeError::None);
    EXPECT_EQ(header.type, PacketType::SensorFrame);
    EXPECT_EQ(header.sequence, 452U);
    EXPECT_EQ(header.time_us, 22450000U);
    ASSERT_EQ(decode_header(encode(sample_reply()), header), DecodeError::None);
    EXPECT_EQ(header.type, PacketType::ControlReply);
    EXPECT_EQ(header.sequence, 4U);
    EXPECT_EQ(header.time_us, 100250000U);
}

// --- Lenient parts: reserved bits and bytes are ignored --------------------------------------

TEST(ProtocolReserved, SensorFrameReservedBitsAndBytes) {
    const FramePacket packet = sample_frame();
    Bytes bytes = encode(packet);
    bytes[32] = static_cast<std::uint8_t>(bytes[32] | 0xE0);  // bits 5–7
    bytes[33] = 0xFF;                                         // bits 8–15
    put_bytes(bytes, 34, {0xAA, 0x55});                       // reserved u16
    FramePacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    expect_equal(decoded, packet);

    // Every combination of the defined flags, with each reserved bit set beside it.
    for (unsigned bits = 0; bits < 32; ++bits) {
        FramePacket flagged = sample_frame();
        flagged.frame.ir_valid = {(bits & 1U) != 0, (bits & 2U) != 0};
        flagged.flags = {(bits & 4U) != 0, (bits & 8U) != 0, (bits & 16U) != 0};
        for (unsigned reserved = 5; reserved < 16; ++reserved) {
            Bytes with_reserved = encode(flagged);
            put_u16(with_reserved, 32, static_cast<std::uint16_t>(bits | (1U << reserved)));
            ASSERT_EQ(decode(with_reserved, decoded), DecodeError::None);
            SCOPED_TRACE(testing::Message() << "flags " << bits << " reserved bit " << reserved);
            expect_equal(decoded, flagged);
        }
    }
}

TEST(ProtocolReserved, ConnectReplyReservedByteAndUnknownResult) {
    const ConnectReplyPacket packet = sample_connect_reply();
    Bytes bytes = encode(packet);
    bytes[21] = 0xFF;
    ConnectReplyPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    expect_equal(decoded, packet);
    // Result values other than 0 and 1 read as busy.
    bytes[20] = 7;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_EQ(decoded.result, ConnectResult::Busy);
    bytes[20] = 0;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_EQ(decoded.result, ConnectResult::Accepted);
}

TEST(ProtocolReserved, GroundTruthReservedBytesAndTouchingByte) {
    const TruthPacket packet = sample_truth();
    Bytes bytes = encode(packet);
    put_bytes(bytes, 93, {1, 2, 0xFF});  // 93–95; 96–99 are the teleport count
    TruthPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    expect_equal(decoded, packet);
    bytes[92] = 0x80;  // any non-zero value is "touching"
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_TRUE(decoded.truth.touching_wall);
    bytes[92] = 0;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_FALSE(decoded.truth.touching_wall);
}

TEST(ProtocolReserved, ControlRequestReservedFlagBitsAndBytes) {
    const ControlRequestPacket packet = sample_request(ControlOp::Reset);
    Bytes bytes = encode(packet);
    bytes[25] = 0xFF;  // pose given and bits 1–7
    put_bytes(bytes, 26, {0x12, 0x34});
    ControlRequestPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    expect_equal(decoded, packet);
    bytes[25] = 0xFE;  // bits 1–7 only: the pose is not given
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_FALSE(decoded.pose_given);
}

TEST(ProtocolReserved, ControlReplyReservedBytesAndUnknownResult) {
    const ControlReplyPacket packet = sample_reply();
    Bytes bytes = encode(packet);
    put_bytes(bytes, 26, {0xFF, 0xFF});
    bytes[95] = 0xFF;
    put_bytes(bytes, 102, {0xFF, 0xFF});
    ControlReplyPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    expect_equal(decoded, packet);
    // Result values beyond UnknownOp read as rejected.
    bytes[25] = 3;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_EQ(decoded.result, ControlResult::Rejected);
    bytes[25] = 2;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    EXPECT_EQ(decoded.result, ControlResult::UnknownOp);
}

TEST(ProtocolReserved, UnterminatedTextsStayInsideTheirFields) {
    Bytes bytes = encode(sample_reply());
    std::fill(bytes.begin() + 104, bytes.begin() + 136, std::uint8_t{'w'});
    std::fill(bytes.begin() + 288, bytes.end(), std::uint8_t{'m'});
    ControlReplyPacket decoded;
    ASSERT_EQ(decode(bytes, decoded), DecodeError::None);
    // Lenient: at most the field (no counter bytes, nothing past the datagram).
    EXPECT_LE(decoded.status.world_name.size(), 32U);
    EXPECT_GE(decoded.status.world_name.size(), 31U);
    EXPECT_EQ(decoded.status.world_name.find_first_not_of('w'), std::string::npos);
    EXPECT_LE(decoded.message.size(), 96U);
    EXPECT_GE(decoded.message.size(), 95U);
    EXPECT_EQ(decoded.message.find_first_not_of('m'), std::string::npos);
    expect_counters(decoded.status.counters, distinct_counters());
}

TEST(ProtocolReserved, UnknownControlOpDecodesWithItsOpKept) {
    for (const std::uint8_t op : std::initializer_list<std::uint8_t>{0, 8, 42, 0xFF}) {
        ControlRequestPacket packet;
        packet.sequence = 3;
        packet.request_id = 0x5EED;
        packet.op = op;
        Bytes bytes = encode(packet);
        // Whatever the arguments hold, they are not looked at, not even NaNs.
        for (std::size_t offset = 28; offset < 60; offset += 8) {
            put_f64(bytes, offset, kNaN);
        }
        ControlRequestPacket decoded;
        ASSERT_EQ(decode(bytes, decoded), DecodeError::None) << int{op};
        EXPECT_EQ(decoded.op, op);
        EXPECT_EQ(decoded.request_id, 0x5EEDU);
        EXPECT_EQ(decoded.sequence, 3U);
    }
}

// ===============================================================================================
// Counting decode errors
// ===============================================================================================

// The table below lists every DecodeError but None: one added later must be added there.
static_assert(static_cast<int>(DecodeError::WrongType) == 9);

TEST(ProtocolCounters, EachDecodeErrorCountsExactlyItsCounter) {
    const std::array<std::pair<DecodeError, std::uint64_t ServerCounters::*>, 9> expected{{
        {DecodeError::Truncated, &ServerCounters::truncated},
        {DecodeError::BadMagic, &ServerCounters::bad_magic},
        {DecodeError::BadVersion, &ServerCounters::bad_version},
        {DecodeError::UnknownType, &ServerCounters::unknown_type},
        {DecodeError::BadLength, &ServerCounters::bad_length},
        {DecodeError::Oversized, &ServerCounters::oversized},
        {DecodeError::NonFinite, &ServerCounters::non_finite},
        {DecodeError::BadTime, &ServerCounters::bad_time},
        {DecodeError::WrongType, &ServerCounters::wrong_stream},
    }};
    for (const auto& [error, member] : expected) {
        SCOPED_TRACE(to_string(error));
        // From zero and from distinct non-zero values.
        for (const ServerCounters& start : {ServerCounters{}, distinct_counters()}) {
            ServerCounters counters = start;
            count_decode_error(counters, error);
            ServerCounters want = start;
            ++(want.*member);
            expect_counters(counters, want);
            count_decode_error(counters, error);
            ++(want.*member);
            expect_counters(counters, want);
        }
    }
    ServerCounters counters = distinct_counters();
    count_decode_error(counters, DecodeError::None);
    expect_counters(counters, distinct_counters());
    counters = {};
    count_decode_error(counters, DecodeError::None);
    expect_counters(counters, ServerCounters{});
}

// ===============================================================================================
// Seconds ↔ microseconds
// ===============================================================================================

TEST(ProtocolTime, NegativeAndNaNBecomeZero) {
    EXPECT_EQ(to_microseconds(-1.0), 0U);
    EXPECT_EQ(to_microseconds(-1e-9), 0U);
    EXPECT_EQ(to_microseconds(-0.0), 0U);
    EXPECT_EQ(to_microseconds(-kInf), 0U);
    EXPECT_EQ(to_microseconds(std::numeric_limits<double>::lowest()), 0U);
    EXPECT_EQ(to_microseconds(kNaN), 0U);
    EXPECT_EQ(to_microseconds(-kNaN), 0U);
    EXPECT_EQ(to_microseconds(0.0), 0U);
}

TEST(ProtocolTime, RoundsToTheNearestMicrosecond) {
    EXPECT_EQ(to_microseconds(1.25), 1250000U);
    EXPECT_EQ(to_microseconds(22.45), 22450000U);
    EXPECT_EQ(to_microseconds(1e-6), 1U);
    EXPECT_EQ(to_microseconds(0.4e-6), 0U);
    EXPECT_EQ(to_microseconds(0.6e-6), 1U);
    EXPECT_EQ(to_microseconds(1.0000004), 1000000U);
    EXPECT_EQ(to_microseconds(1.0000006), 1000001U);
    EXPECT_EQ(to_microseconds(2.9999996), 3000000U);
    EXPECT_EQ(to_microseconds(2.9999994), 2999999U);
    EXPECT_EQ(to_microseconds(0.05 * 3), 150000U);   // 0.15000000000000002
    EXPECT_EQ(to_microseconds(0.1 + 0.2), 300000U);  // 0.30000000000000004
    EXPECT_EQ(to_microseconds(std::numeric_limits<double>::denorm_min()), 0U);
}

TEST(ProtocolTime, SaturatesAtTheLimit) {
    const double limit_seconds = to_seconds(kMaxTimeMicroseconds);
    EXPECT_EQ(limit_seconds, 1125899906.842624);
    EXPECT_EQ(to_microseconds(limit_seconds), kMaxTimeMicroseconds);
    EXPECT_EQ(to_microseconds(to_seconds(kMaxTimeMicroseconds - 1)), kMaxTimeMicroseconds - 1);
    EXPECT_EQ(to_microseconds(1125899906.842625), kMaxTimeMicroseconds);  // 1 µs beyond
    EXPECT_EQ(to_microseconds(2e9), kMaxTimeMicroseconds);
    EXPECT_EQ(to_microseconds(1e300), kMaxTimeMicroseconds);
    EXPECT_EQ(to_microseconds(std::numeric_limits<double>::max()), kMaxTimeMicroseconds);
    EXPECT_EQ(to_microseconds(kInf), kMaxTimeMicroseconds);
    // The limit's header is still valid; encoding anything later produces it too.
    BarePacket late{PacketType::Connect, 0, 1e12};
    BarePacket decoded;
    ASSERT_EQ(decode(encode(late), decoded), DecodeError::None);
    EXPECT_EQ(decoded.time, limit_seconds);
}

TEST(ProtocolTime, ToSeconds) {
    EXPECT_EQ(to_seconds(0), 0.0);
    EXPECT_EQ(to_seconds(1), 1e-6);
    EXPECT_EQ(to_seconds(1250000), 1.25);
    EXPECT_EQ(to_seconds(22450000), 22.45);
    EXPECT_EQ(to_seconds(std::uint64_t{1} << 40), 1099511.627776);
}

TEST(ProtocolTime, MicrosecondsSurviveSecondsUpToTheLimit) {
    std::mt19937_64 rng(20240501);
    std::uniform_int_distribution<std::uint64_t> uniform(0, kMaxTimeMicroseconds);
    std::uniform_int_distribution<int> bits(0, 50);
    for (int i = 0; i < 200000; ++i) {
        // Half uniform over the whole range (mostly large), half spread over magnitudes.
        std::uint64_t us = uniform(rng);
        if (i % 2 == 1) {
            us >>= bits(rng);
        }
        ASSERT_EQ(to_microseconds(to_seconds(us)), us) << "at " << us << " µs";
    }
    for (std::uint64_t us = 0; us < 100000; ++us) {
        ASSERT_EQ(to_microseconds(to_seconds(us)), us) << "at " << us << " µs";
    }
    for (std::uint64_t us = kMaxTimeMicroseconds - 100000; us <= kMaxTimeMicroseconds; ++us) {
        ASSERT_EQ(to_microseconds(to_seconds(us)), us) << "at " << us << " µs";
    }
}

// ===============================================================================================
// Decoders never read past the datagram
// ===============================================================================================

TEST(ProtocolRobustness, EveryTruncationOfEveryPacketIsTruncated) {
    for (const Sample& sample : valid_samples()) {
        for (std::size_t size = 0; size < sample.bytes.size(); ++size) {
            // A fresh allocation of exactly `size` bytes, so ASan sees any read beyond it.
            const auto prefix = std::make_unique<std::uint8_t[]>(size);
            std::copy_n(sample.bytes.begin(), size, prefix.get());
            const Span datagram(prefix.get(), size);
            for (const Decoder& decoder : decoders()) {
                ASSERT_EQ(decoder.decode(datagram), DecodeError::Truncated)
                    << to_string(sample.type) << " cut to " << size << " bytes, " << decoder.name
                    << " decoder";
            }
            PacketHeader header;
            ASSERT_EQ(decode_header(datagram, header), DecodeError::Truncated);
        }
    }
}

TEST(ProtocolRobustness, EveryExtensionOfEveryPacketIsOversized) {
    for (const Sample& sample : valid_samples()) {
        for (std::size_t size = sample.bytes.size() + 1; size <= kMaxPacketSize + 2; ++size) {
            Bytes longer = sample.bytes;
            longer.resize(size, 0x5A);
            for (const Decoder& decoder : decoders()) {
                ASSERT_EQ(decoder.decode(longer), DecodeError::Oversized)
                    << to_string(sample.type) << " grown to " << size << " bytes, " << decoder.name
                    << " decoder";
            }
        }
    }
}

TEST(ProtocolRobustness, RandomDatagramsNeverDecodeWithTheWrongSize) {
    std::mt19937_64 rng(0x1F00D);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> kind(0, 2);
    std::uniform_int_distribution<std::size_t> any_size(0, 600);
    std::uniform_int_distribution<std::size_t> type_index(0, kAllTypes.size() - 1);
    const std::vector<Sample> samples = valid_samples();
    std::uniform_int_distribution<std::size_t> sample_index(0, samples.size() - 1);

    int successes = 0;
    for (int i = 0; i < 30000; ++i) {
        Bytes bytes;
        switch (kind(rng)) {
            case 0: {  // noise
                bytes.resize(any_size(rng));
                for (auto& b : bytes) {
                    b = static_cast<std::uint8_t>(byte(rng));
                }
                break;
            }
            case 1: {  // a plausible header with a random size and random payload
                const PacketType type = kAllTypes[type_index(rng)];
                const std::size_t size = packet_size(type);
                std::uniform_int_distribution<std::size_t> near(size - 2, size + 2);
                bytes.resize(byte(rng) < 128 ? size : near(rng));
                for (auto& b : bytes) {
                    b = static_cast<std::uint8_t>(byte(rng));
                }
                const std::array<std::uint8_t, 8> header{'L',
                                                         'F',
                                                         'U',
                                                         'P',
                                                         1,
                                                         static_cast<std::uint8_t>(type),
                                                         static_cast<std::uint8_t>(size & 0xFF),
                                                         static_cast<std::uint8_t>(size >> 8)};
                std::copy_n(header.begin(), std::min(header.size(), bytes.size()), bytes.begin());
                if (bytes.size() >= 20) {
                    bytes[19] = 0;  // keep the time under 2^50 most of the time
                    bytes[18] = static_cast<std::uint8_t>(bytes[18] & 0x03);
                }
                break;
            }
            default: {  // a valid packet with a few bytes flipped and maybe resized
                bytes = samples[sample_index(rng)].bytes;
                std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
                for (int flips = byte(rng) % 4; flips > 0; --flips) {
                    bytes[position(rng)] ^= static_cast<std::uint8_t>(1 + byte(rng) % 255);
                }
                if (byte(rng) < 64) {
                    std::uniform_int_distribution<std::size_t> resize(0, bytes.size() + 8);
                    bytes.resize(resize(rng), 0);
                }
                break;
            }
        }
        // Exactly sized heap copy for ASan.
        const auto copy = std::make_unique<std::uint8_t[]>(bytes.size());
        std::copy(bytes.begin(), bytes.end(), copy.get());
        const Span datagram(copy.get(), bytes.size());

        PacketHeader header;
        const DecodeError header_error = decode_header(datagram, header);
        const bool right_size = bytes.size() >= kHeaderSize
                                && is_valid_length(static_cast<PacketType>(bytes[5]), bytes.size());
        if (header_error == DecodeError::None) {
            ASSERT_TRUE(right_size) << hex(bytes);
        }
        for (const Decoder& decoder : decoders()) {
            const DecodeError error = decoder.decode(datagram);
            if (error != DecodeError::None) {
                continue;
            }
            ++successes;
            ASSERT_EQ(header_error, DecodeError::None) << decoder.name << "\n" << hex(bytes);
            ASSERT_TRUE(right_size) << decoder.name << "\n" << hex(bytes);
            ASSERT_TRUE(decoder.takes(header.type)) << decoder.name << "\n" << hex(bytes);
        }
    }
    // The generator reaches the decoders' bodies, not only the header checks.
    EXPECT_GT(successes, 1000);
}

}  // namespace
}  // namespace legofeup::comms
