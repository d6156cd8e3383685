// Names for the protocol's bytes, so that every message a user reads says "GETOUTPUTSTATE" and
// "0xC0 (out of range: bad port or value)" rather than bare numbers.

#include <algorithm>
#include <array>
#include <cstdio>
#include <string_view>
#include <utility>

#include "legofeup/comms/nxt/telegram.hpp"
#include "telegram_layout.hpp"

namespace legofeup::comms::nxt {
namespace {

// The meanings follow the firmware's error tables (LEGO NXT firmware v1.29, c_cmd.h and
// c_comm.h), worded for a student reading an error message.
constexpr std::array<std::pair<std::uint8_t, std::string_view>, 18> kStatusTexts{{
    {status::kOk, "success"},
    {status::kPending, "pending: a communication transaction is in progress"},
    {status::kMailboxEmpty, "mailbox empty"},
    {status::kRequestFailed, "request failed, e.g. the file was not found"},
    {status::kUnknownOpcode, "unknown command opcode"},
    {status::kInsanePacket, "insane packet: wrong length or layout"},
    {status::kOutOfRange, "out of range: bad port or value"},
    {status::kBusError, "communication bus error"},
    {status::kBufferFull, "no free memory in the communication buffer"},
    {status::kInvalidChannel, "the channel or connection is not valid"},
    {status::kChannelNotReady, "the channel or connection is not configured or busy"},
    {status::kNoActiveProgram, "no active program"},
    {status::kIllegalSize, "illegal size"},
    {status::kIllegalMailbox, "illegal mailbox number"},
    {status::kInvalidField, "invalid field of a structure"},
    {status::kBadPort, "bad input or output port"},
    {status::kOutOfMemory, "the brick is out of memory"},
    {status::kBadArguments, "bad arguments"},
}};

constexpr std::array<std::pair<Opcode, std::string_view>, 11> kOpcodeNames{{
    {Opcode::StartProgram, "STARTPROGRAM"},
    {Opcode::StopProgram, "STOPPROGRAM"},
    {Opcode::SetOutputState, "SETOUTPUTSTATE"},
    {Opcode::SetInputMode, "SETINPUTMODE"},
    {Opcode::GetOutputState, "GETOUTPUTSTATE"},
    {Opcode::GetInputValues, "GETINPUTVALUES"},
    {Opcode::MessageWrite, "MESSAGEWRITE"},
    {Opcode::ResetMotorPosition, "RESETMOTORPOSITION"},
    {Opcode::GetBatteryLevel, "GETBATTERYLEVEL"},
    {Opcode::KeepAlive, "KEEPALIVE"},
    {Opcode::MessageRead, "MESSAGEREAD"},
}};

}  // namespace

namespace layout {

std::string hex_byte(std::uint8_t byte) {
    std::array<char, 5> text{};
    std::snprintf(text.data(), text.size(), "0x%02X", static_cast<unsigned>(byte));
    return text.data();
}

bool is_known_opcode(std::uint8_t opcode) {
    return std::any_of(kOpcodeNames.begin(), kOpcodeNames.end(), [&](const auto& entry) {
        return static_cast<std::uint8_t>(entry.first) == opcode;
    });
}

}  // namespace layout

std::string describe_status(std::uint8_t status) {
    for (const auto& [code, text] : kStatusTexts) {
        if (code == status) {
            return layout::hex_byte(status) + " (" + std::string(text) + ")";
        }
    }
    return layout::hex_byte(status) + " (a status this firmware does not define)";
}

std::string opcode_name(Opcode opcode) {
    for (const auto& [code, name] : kOpcodeNames) {
        if (code == opcode) {
            return std::string(name);
        }
    }
    return "opcode " + layout::hex_byte(static_cast<std::uint8_t>(opcode));
}

}  // namespace legofeup::comms::nxt
