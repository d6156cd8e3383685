#pragma once
// The LEGO NXT direct-command protocol (standard firmware), both directions: the host encodes
// requests and decodes replies; the emulated brick decodes requests and encodes replies.
// Facts: docs/nxt.md. A telegram is  type u8 · opcode u8 · fields (little-endian), at most
// 64 bytes; on the wire it is preceded by its u16 length (framing.hpp). A reply is
// 0x02 · opcode · status · payload. A command sent "no reply" (type 0x80) gets nothing back,
// not even an error — which is why the host sends motor commands that way.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "legofeup/comms/link_error.hpp"

namespace legofeup::comms::nxt {

inline constexpr std::size_t kMaxTelegramSize = 64;
using Telegram = std::vector<std::uint8_t>;

enum class TelegramType : std::uint8_t {
    DirectWithReply = 0x00,
    SystemWithReply = 0x01,
    Reply = 0x02,
    DirectNoReply = 0x80,
    SystemNoReply = 0x81,
};

enum class Opcode : std::uint8_t {
    StartProgram = 0x00,
    StopProgram = 0x01,
    SetOutputState = 0x04,
    SetInputMode = 0x05,
    GetOutputState = 0x06,
    GetInputValues = 0x07,
    MessageWrite = 0x09,
    ResetMotorPosition = 0x0A,
    GetBatteryLevel = 0x0B,
    KeepAlive = 0x0D,
    MessageRead = 0x13,
};

/// Reply status bytes the firmware uses (docs/nxt.md).
namespace status {
inline constexpr std::uint8_t kOk = 0x00;
inline constexpr std::uint8_t kPending = 0x20;
inline constexpr std::uint8_t kMailboxEmpty = 0x40;
inline constexpr std::uint8_t kRequestFailed = 0xBD;
inline constexpr std::uint8_t kUnknownOpcode = 0xBE;
inline constexpr std::uint8_t kInsanePacket = 0xBF;
inline constexpr std::uint8_t kOutOfRange = 0xC0;
inline constexpr std::uint8_t kBusError = 0xDD;
inline constexpr std::uint8_t kBufferFull = 0xDE;
inline constexpr std::uint8_t kInvalidChannel = 0xDF;
inline constexpr std::uint8_t kChannelNotReady = 0xE0;
inline constexpr std::uint8_t kNoActiveProgram = 0xEC;
inline constexpr std::uint8_t kIllegalSize = 0xED;
inline constexpr std::uint8_t kIllegalMailbox = 0xEE;
inline constexpr std::uint8_t kInvalidField = 0xEF;
inline constexpr std::uint8_t kBadPort = 0xF0;
inline constexpr std::uint8_t kOutOfMemory = 0xFB;
inline constexpr std::uint8_t kBadArguments = 0xFF;
}  // namespace status

/// "0xC0 (out of range: bad port or value)": the byte and what it means, for messages.
std::string describe_status(std::uint8_t status);
std::string opcode_name(Opcode opcode);

// Output (motor) constants.
inline constexpr std::uint8_t kModeMotorOn = 0x01;
inline constexpr std::uint8_t kModeBrake = 0x02;
inline constexpr std::uint8_t kModeRegulated = 0x04;
inline constexpr std::uint8_t kRegulationIdle = 0;
inline constexpr std::uint8_t kRegulationMotorSpeed = 1;
inline constexpr std::uint8_t kRegulationMotorSync = 2;
inline constexpr std::uint8_t kRunStateIdle = 0x00;
inline constexpr std::uint8_t kRunStateRampUp = 0x10;
inline constexpr std::uint8_t kRunStateRunning = 0x20;
inline constexpr std::uint8_t kRunStateRampDown = 0x40;
inline constexpr std::uint8_t kAllOutputs = 0xFF;
inline constexpr std::uint8_t kOutputPorts = 3;  ///< A, B, C = 0, 1, 2
inline constexpr std::uint8_t kInputPorts = 4;   ///< 1–4 = 0–3

// Input (sensor) constants.
inline constexpr std::uint8_t kSensorNone = 0x00;
inline constexpr std::uint8_t kSensorSwitch = 0x01;
inline constexpr std::uint8_t kSensorLightInactive = 0x06;
inline constexpr std::uint8_t kSensorCustom = 0x09;
inline constexpr std::uint8_t kSensorLowSpeed = 0x0A;
inline constexpr std::uint8_t kSensorLowSpeed9V = 0x0B;
inline constexpr std::uint8_t kSensorModeRaw = 0x00;

/// Mailboxes: 0–9 are the brick's inboxes; a program's responses go to 10–19.
inline constexpr std::uint8_t kMailboxCount = 20;
inline constexpr std::size_t kMaxMessageSize = 59;  ///< including the terminating NUL

/// The fields of SETOUTPUTSTATE, and the first ones of GETOUTPUTSTATE's reply.
struct OutputState {
    std::uint8_t port = 0;  ///< 0–2, or kAllOutputs in SETOUTPUTSTATE
    std::int8_t power = 0;  ///< −100…100
    std::uint8_t mode = 0;
    std::uint8_t regulation = kRegulationIdle;
    std::int8_t turn_ratio = 0;
    std::uint8_t run_state = kRunStateIdle;
    std::uint32_t tacho_limit = 0;  ///< 0 = run forever
    bool operator==(const OutputState&) const = default;
};

/// GETOUTPUTSTATE's reply payload (22 bytes after type, opcode, status: 25 in all).
struct OutputStateReply {
    OutputState state;
    std::int32_t tacho_count = 0;
    std::int32_t block_tacho_count = 0;
    std::int32_t rotation_count = 0;  ///< cumulative degrees: odometry reads this one
    bool operator==(const OutputStateReply&) const = default;
};

/// GETINPUTVALUES's reply payload (13 bytes after type, opcode, status: 16 in all).
struct InputValues {
    std::uint8_t port = 0;
    bool valid = false;  ///< false for ~20 ms after SETINPUTMODE
    bool calibrated = false;
    std::uint8_t type = kSensorNone;
    std::uint8_t mode = kSensorModeRaw;
    std::uint16_t raw = 0;  ///< the 10-bit A/D value: the IR sensors' reading
    std::uint16_t normalized = 0;
    std::int16_t scaled = 0;
    std::int16_t calibrated_value = 0;
    bool operator==(const InputValues&) const = default;
};

/// MESSAGEREAD's reply payload: the local inbox, and the message (NUL included, ≤ 59 bytes;
/// the reply always carries 59 data bytes, zero-padded).
struct MailboxMessage {
    std::uint8_t local_inbox = 0;
    std::vector<std::uint8_t> data;
    bool operator==(const MailboxMessage&) const = default;
};

// ---------------------------------------------------------------------------------------
// Host side: requests. `reply` chooses type 0x00 (reply wanted) or 0x80 (no reply).
// Arguments out of the protocol's range throw std::invalid_argument naming the field.

Telegram encode_start_program(const std::string& file_name, bool reply);  ///< ≤ 19 chars
Telegram encode_stop_program(bool reply);
Telegram encode_set_output_state(const OutputState& state, bool reply);
Telegram encode_set_input_mode(std::uint8_t port, std::uint8_t sensor_type,
                               std::uint8_t sensor_mode, bool reply);
Telegram encode_get_output_state(std::uint8_t port);
Telegram encode_get_input_values(std::uint8_t port);
Telegram encode_message_write(std::uint8_t inbox, std::span<const std::uint8_t> message,
                              bool reply);  ///< message without its NUL: ≤ 58 bytes
Telegram encode_reset_motor_position(std::uint8_t port, bool relative, bool reply);
Telegram encode_get_battery_level();
Telegram encode_keep_alive(bool reply);
Telegram encode_message_read(std::uint8_t remote_inbox, std::uint8_t local_inbox, bool remove);

/// A reply that is not the one expected, or says the request failed. what() names the
/// opcode and the problem: "GETOUTPUTSTATE reply: status 0xC0 (out of range …)",
/// "GETINPUTVALUES reply: 15 bytes, expected 16", "reply to GETOUTPUTSTATE has opcode 0x07".
class ReplyError : public LinkError {
  public:
    ReplyError(const std::string& message, std::optional<std::uint8_t> status)
        : LinkError(message), status_(status) {}
    /// The status byte when the brick refused the request; nullopt for a malformed reply.
    std::optional<std::uint8_t> status() const { return status_; }

  private:
    std::optional<std::uint8_t> status_;
};

// Host side: replies. Each checks type 0x02, the opcode, the status (non-zero throws with
// describe_status) and the exact length before reading a field.
void decode_status_reply(std::span<const std::uint8_t> reply, Opcode expected);
OutputStateReply decode_output_state_reply(std::span<const std::uint8_t> reply);
InputValues decode_input_values_reply(std::span<const std::uint8_t> reply);
std::uint16_t decode_battery_level_reply(std::span<const std::uint8_t> reply);  ///< mV
std::uint32_t decode_keep_alive_reply(std::span<const std::uint8_t> reply);     ///< sleep limit ms
/// A MESSAGEREAD reply; status kMailboxEmpty gives nullopt rather than an error.
std::optional<MailboxMessage> decode_message_read_reply(std::span<const std::uint8_t> reply);

// ---------------------------------------------------------------------------------------
// Brick side: requests as the firmware sees them.

struct StartProgram {
    std::string file_name;
};
struct StopProgram {};
struct SetOutputState {
    OutputState state;
};
struct SetInputMode {
    std::uint8_t port = 0;
    std::uint8_t sensor_type = 0;
    std::uint8_t sensor_mode = 0;
};
struct GetOutputState {
    std::uint8_t port = 0;
};
struct GetInputValues {
    std::uint8_t port = 0;
};
struct MessageWrite {
    std::uint8_t inbox = 0;
    std::vector<std::uint8_t> message;  ///< as sent, NUL included
};
struct ResetMotorPosition {
    std::uint8_t port = 0;
    bool relative = false;
};
struct GetBatteryLevel {};
struct KeepAlive {};
struct MessageRead {
    std::uint8_t remote_inbox = 0;
    std::uint8_t local_inbox = 0;
    bool remove = false;
};

using RequestBody = std::variant<StartProgram, StopProgram, SetOutputState, SetInputMode,
                                 GetOutputState, GetInputValues, MessageWrite, ResetMotorPosition,
                                 GetBatteryLevel, KeepAlive, MessageRead>;

/// A request decoded by the brick. `status` is kOk when `body` holds it; otherwise what the
/// firmware answers (kUnknownOpcode, kInsanePacket for a wrong length, …) and `body` is
/// empty. Ports and values out of range are not decoding errors: the firmware's handler
/// answers them (kOutOfRange with a zero-filled payload).
struct DecodedRequest {
    TelegramType type = TelegramType::DirectWithReply;
    std::uint8_t opcode = 0;
    std::uint8_t status = status::kOk;
    std::optional<RequestBody> body;
    bool wants_reply() const;
};

/// Decodes one request telegram. Never throws: garbage gets a status, as on the brick. An
/// empty telegram or a type byte the firmware ignores gives wants_reply() == false.
DecodedRequest decode_request(std::span<const std::uint8_t> telegram);

// Brick side: replies (type 0x02 · opcode · status · payload). A non-zero status keeps the
// payload's length, zero-filled, as the firmware does.
Telegram encode_status_reply(std::uint8_t opcode, std::uint8_t status);
Telegram encode_output_state_reply(std::uint8_t status, const OutputStateReply& reply);
Telegram encode_input_values_reply(std::uint8_t status, const InputValues& values);
Telegram encode_battery_level_reply(std::uint8_t status, std::uint16_t millivolts);
Telegram encode_keep_alive_reply(std::uint8_t status, std::uint32_t sleep_limit_ms);
Telegram encode_message_read_reply(std::uint8_t status, const MailboxMessage& message);

}  // namespace legofeup::comms::nxt
