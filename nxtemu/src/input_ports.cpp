#include "input_ports.hpp"

#include <algorithm>

namespace legofeup::nxtemu {
namespace {

namespace nxt = comms::nxt;

// Sensor types the firmware knows beyond those telegram.hpp names (c_input.h).
constexpr std::uint8_t kReflection = 3;
constexpr std::uint8_t kAngle = 4;
constexpr std::uint8_t kLightActive = 5;
constexpr std::uint8_t kSoundDb = 7;
constexpr std::uint8_t kSoundDba = 8;
constexpr std::uint8_t kHighSpeed = 12;
constexpr std::uint8_t kColorFirst = 13;  // COLORFULL … COLORNONE
constexpr std::uint8_t kColorLast = 17;

// How long the data stay invalid after SETINPUTMODE (INVALID_RELOAD_* of c_input.c, in 1 ms
// ticks of the input module).
constexpr double kInvalidAfterTypeChange = 0.020;
constexpr double kInvalidSound = 0.300;
constexpr double kInvalidColor = 0.400;
constexpr double kInvalidSameType = 0.001;

constexpr std::uint8_t kModeMask = 0xE0;
constexpr std::uint8_t kModePercentFullScale = 0x80;
constexpr int kFullScale = 1023;

bool is_sound(std::uint8_t type) {
    return type == kSoundDb || type == kSoundDba;
}

bool is_color(std::uint8_t type) {
    return type >= kColorFirst && type <= kColorLast;
}

double invalid_window(std::uint8_t old_type, std::uint8_t new_type) {
    if (old_type == new_type) {
        return kInvalidSameType;  // a mode change: one tick to take the new mode
    }
    if (is_sound(new_type)) {
        return kInvalidSound;
    }
    return is_color(new_type) ? kInvalidColor : kInvalidAfterTypeChange;
}

/// cInputCalcFullScale: the sensor's useful span [zero, zero + span % of full scale] stretched
/// to 0–1023, inverted for sensors whose voltage falls as the quantity rises.
std::uint16_t full_scale(std::uint16_t raw, int zero, int span_percent) {
    const int above = raw > zero ? raw - zero : 0;
    const int stretched = std::min(above * 100 / span_percent, kFullScale);
    return static_cast<std::uint16_t>(kFullScale - stretched);
}

/// SensorRaw ("normalized") from ADRaw for the analog types. The zero points and spans are
/// those of c_input.c for a 5 V, 10-bit converter (e.g. light: 800 mV → 200, 68 %).
std::uint16_t normalized(std::uint8_t type, std::uint16_t raw) {
    switch (type) {
        case kLightActive:
        case nxt::kSensorLightInactive:
            return full_scale(raw, 200, 68);
        case kSoundDb:
        case kSoundDba:
            return full_scale(raw, 162, 83);
        case kReflection:
            return full_scale(raw, 476, 41);
        default:
            return raw;  // switch, angle, custom; temperature's table is not emulated
    }
}

/// Types whose pin 1 carries 9 V (the RCX active sensors, the ultrasonic sensor's supply):
/// an analog sensor on that pin reads full scale.
bool powers_pin1(std::uint8_t type) {
    return type == kReflection || type == kAngle || type == nxt::kSensorLowSpeed9V;
}

}  // namespace

InputPorts::InputPorts() = default;

void InputPorts::set_mode(std::uint8_t port, std::uint8_t type, std::uint8_t mode, double now) {
    Port& p = ports_.at(port);
    p.invalid_until = now + invalid_window(p.type, type);
    p.type = type;
    p.mode = mode;
}

void InputPorts::reset_all(double now) {
    for (std::uint8_t port = 0; port < kInputCount; ++port) {
        set_mode(port, nxt::kSensorNone, nxt::kSensorModeRaw, now);
        Port& p = ports_.at(port);
        p.raw = 0;
        p.normalized = 0;
        p.scaled = 0;
    }
}

void InputPorts::update(const std::array<std::uint16_t, kInputCount>& adc, double now) {
    for (std::size_t i = 0; i < kInputCount; ++i) {
        Port& p = ports_.at(i);
        if (now < p.invalid_until || p.type == nxt::kSensorNone || is_color(p.type)) {
            continue;  // invalid data are not refreshed; NO_SENSOR never reads (stale)
        }
        p.raw = powers_pin1(p.type) ? std::uint16_t{kFullScale} : adc.at(i);
        if (p.type >= nxt::kSensorLowSpeed && p.type <= kHighSpeed) {
            continue;  // digital sensors: only the A/D value is kept
        }
        p.normalized = normalized(p.type, p.raw);
        const bool percent = (p.mode & kModeMask) == kModePercentFullScale;
        // Raw mode (and, not emulated, the counting modes): the scaled value is SensorRaw.
        p.scaled =
            static_cast<std::int16_t>(percent ? p.normalized * 100 / kFullScale : p.normalized);
    }
}

nxt::InputValues InputPorts::values(std::uint8_t port, double now) const {
    const Port& p = ports_.at(port);
    nxt::InputValues values;
    values.port = port;
    values.valid = now >= p.invalid_until;
    values.calibrated = false;  // a placeholder in the protocol: always false
    values.type = p.type;
    values.mode = p.mode;
    values.raw = p.raw;
    values.normalized = p.normalized;
    values.scaled = p.scaled;
    values.calibrated_value = static_cast<std::int16_t>(p.normalized);  // as the firmware
    return values;
}

}  // namespace legofeup::nxtemu
