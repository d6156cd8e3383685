// libFuzzer target for the NXT direct-command codec (docs/nxt.md): every host-side reply
// decoder and the brick-side request decoder run on each input. Whatever the bytes:
//  - the reply decoders return or throw ReplyError, nothing else; a ReplyError carries a
//    status exactly when the input's status byte refused the request;
//  - decode_request never throws, and has a body exactly when its status is OK;
//  - round trips: a reply that decodes re-encodes (brick-side encoder) to the input, and a
//    request that decodes with status OK re-encodes (host-side encoder) to the input —
//    both up to the bytes the decoders are documented to read leniently, as the firmware
//    does: a boolean byte is true when non-zero, the bytes after a file name's NUL and after
//    a MESSAGEREAD reply's message are ignored. Those bytes are put in canonical form
//    (0/1, zeros) before comparing. A request whose values the host encoder refuses (a port
//    out of range: the brick's handler answers it) has no round trip to check.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <stdexcept>
#include <variant>
#include <vector>

#include "legofeup/comms/nxt/telegram.hpp"

namespace {

using namespace legofeup::comms::nxt;
using Bytes = std::vector<std::uint8_t>;
using Span = std::span<const std::uint8_t>;

void check(bool condition) {
    if (!condition) {
        std::abort();
    }
}

void to_bool_byte(Bytes& bytes, std::size_t index) {
    bytes.at(index) = bytes.at(index) != 0 ? 1 : 0;
}

void zero_from(Bytes& bytes, std::size_t index) {
    std::fill(bytes.begin() + static_cast<std::ptrdiff_t>(std::min(index, bytes.size())),
              bytes.end(), std::uint8_t{0});
}

/// Runs one reply decoder: nullopt when it refused the input (with a consistent ReplyError).
template <typename Decode>
auto try_decode(Span input, Decode decode) -> std::optional<decltype(decode(input))> {
    try {
        return decode(input);
    } catch (const ReplyError& error) {
        if (error.status()) {
            check(input.size() >= 3 && *error.status() == input[2] && *error.status() != 0);
        }
        return std::nullopt;
    }
}

void fuzz_replies(Span input) {
    const Bytes bytes(input.begin(), input.end());
    for (std::uint8_t opcode = 0; opcode <= 0x13; ++opcode) {
        const auto op = static_cast<Opcode>(opcode);
        if (try_decode(input, [&](Span r) { return (decode_status_reply(r, op), 0); })) {
            check(encode_status_reply(opcode, status::kOk) == bytes);
        }
    }
    if (const auto reply = try_decode(input, decode_output_state_reply)) {
        check(encode_output_state_reply(status::kOk, *reply) == bytes);
    }
    if (const auto values = try_decode(input, decode_input_values_reply)) {
        Bytes canonical = bytes;
        to_bool_byte(canonical, 4);  // valid
        to_bool_byte(canonical, 5);  // calibrated
        check(encode_input_values_reply(status::kOk, *values) == canonical);
    }
    if (const auto millivolts = try_decode(input, decode_battery_level_reply)) {
        check(encode_battery_level_reply(status::kOk, *millivolts) == bytes);
    }
    if (const auto sleep_limit = try_decode(input, decode_keep_alive_reply)) {
        check(encode_keep_alive_reply(status::kOk, *sleep_limit) == bytes);
    }
    if (const auto message = try_decode(input, decode_message_read_reply)) {
        if (!message->has_value()) {
            check(bytes.at(2) == status::kMailboxEmpty);
            return;
        }
        Bytes canonical = bytes;
        zero_from(canonical, 5 + (*message)->data.size());  // the padding after the message
        check(encode_message_read_reply(status::kOk, **message) == canonical);
    }
}

/// The host's encoding of a decoded request, with the type byte it arrived with (the reading
/// requests' encoders always ask for a reply); nullopt when the encoder refuses its values.
std::optional<Bytes> reencode(const DecodedRequest& request) {
    const bool reply = request.type == TelegramType::DirectWithReply;
    try {
        Bytes bytes = std::visit(
            [&](const auto& body) -> Bytes {
                using T = std::decay_t<decltype(body)>;
                if constexpr (std::is_same_v<T, StartProgram>) {
                    return encode_start_program(body.file_name, reply);
                } else if constexpr (std::is_same_v<T, StopProgram>) {
                    return encode_stop_program(reply);
                } else if constexpr (std::is_same_v<T, SetOutputState>) {
                    return encode_set_output_state(body.state, reply);
                } else if constexpr (std::is_same_v<T, SetInputMode>) {
                    return encode_set_input_mode(body.port, body.sensor_type, body.sensor_mode,
                                                 reply);
                } else if constexpr (std::is_same_v<T, GetOutputState>) {
                    return encode_get_output_state(body.port);
                } else if constexpr (std::is_same_v<T, GetInputValues>) {
                    return encode_get_input_values(body.port);
                } else if constexpr (std::is_same_v<T, MessageWrite>) {
                    check(!body.message.empty() && body.message.back() == 0);
                    const Span without_nul = Span(body.message).first(body.message.size() - 1);
                    return encode_message_write(body.inbox, without_nul, reply);
                } else if constexpr (std::is_same_v<T, ResetMotorPosition>) {
                    return encode_reset_motor_position(body.port, body.relative, reply);
                } else if constexpr (std::is_same_v<T, GetBatteryLevel>) {
                    return encode_get_battery_level();
                } else if constexpr (std::is_same_v<T, KeepAlive>) {
                    return encode_keep_alive(reply);
                } else {
                    static_assert(std::is_same_v<T, MessageRead>);
                    return encode_message_read(body.remote_inbox, body.local_inbox, body.remove);
                }
            },
            *request.body);
        bytes.at(0) = static_cast<std::uint8_t>(request.type);
        return bytes;
    } catch (const std::invalid_argument&) {
        return std::nullopt;
    }
}

/// The input with its leniently read bytes in the form the host encoder writes them.
Bytes canonical_request(Span input, const DecodedRequest& request) {
    Bytes bytes(input.begin(), input.end());
    if (std::holds_alternative<StartProgram>(*request.body)) {
        zero_from(bytes, 2 + std::get<StartProgram>(*request.body).file_name.size());
    } else if (std::holds_alternative<ResetMotorPosition>(*request.body)) {
        to_bool_byte(bytes, 3);  // relative
    } else if (std::holds_alternative<MessageRead>(*request.body)) {
        to_bool_byte(bytes, 4);  // remove
    }
    return bytes;
}

void fuzz_request(Span input) {
    const DecodedRequest request = decode_request(input);  // must not throw
    check(request.body.has_value() == (request.status == status::kOk));
    if (input.size() >= 2) {
        check(request.opcode == input[1]);
    }
    if (!input.empty()) {
        check(static_cast<std::uint8_t>(request.type) == input[0]);
    }
    if (!request.body) {
        return;
    }
    check(request.type == TelegramType::DirectWithReply
          || request.type == TelegramType::DirectNoReply);
    if (const auto encoded = reencode(request)) {
        check(*encoded == canonical_request(input, request));
    }
}

/// The input with a reply header most decoders accept: type 0x02, an opcode that has a
/// payload (chosen by the input's opcode byte) and, mostly, status OK. Random bytes seldom
/// start 02 · opcode · 00, so without this the round trips would rarely be reached.
Bytes with_reply_header(Span input) {
    constexpr std::uint8_t kOpcodes[] = {0x06, 0x07, 0x0B, 0x0D, 0x13, 0x04};
    Bytes bytes(input.begin(), input.end());
    bytes[0] = static_cast<std::uint8_t>(TelegramType::Reply);
    bytes[1] = kOpcodes[bytes[1] % std::size(kOpcodes)];
    if (bytes[2] >= 0x10 && bytes[2] != status::kMailboxEmpty) {
        bytes[2] = status::kOk;  // keep a few statuses (0x01…0x0F, 0x40) to refuse
    }
    return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const Span input(data, size);
    fuzz_replies(input);
    fuzz_request(input);
    if (input.size() >= 3) {
        fuzz_replies(with_reply_header(input));
    }
    return 0;
}
