#pragma once
// The four sensor inputs as the firmware's input module keeps them (c_input in the firmware
// sources): type and mode, the invalid window after a change, and the raw, normalised and
// scaled values, refreshed from the A/D converter while the data are valid. Private to nxtemu.

#include <array>
#include <cstdint>

#include "legofeup/comms/nxt/telegram.hpp"
#include "legofeup/nxtemu/brick_hardware.hpp"

namespace legofeup::nxtemu {

class InputPorts {
  public:
    /// Power-on: every port NO_SENSOR in raw mode, raw 0 (NO_SENSOR never reads the A/D).
    InputPorts();

    /// SETINPUTMODE (port < kInputCount) at `now`: the data are invalid for 20 ms if the type
    /// changed (300 ms for the sound sensors, 400 ms for the colour sensor), else for one
    /// 1 ms tick of the input module.
    void set_mode(std::uint8_t port, std::uint8_t type, std::uint8_t mode, double now);
    /// A program starts or stops: NO_SENSOR, raw mode, every value 0, data invalid.
    void reset_all(double now);

    /// The A/D converters read `adc` at `now`: valid ports take the new values.
    void update(const std::array<std::uint16_t, kInputCount>& adc, double now);

    comms::nxt::InputValues values(std::uint8_t port, double now) const;

  private:
    struct Port {
        std::uint8_t type = comms::nxt::kSensorNone;
        std::uint8_t mode = comms::nxt::kSensorModeRaw;
        double invalid_until = 0.0;
        std::uint16_t raw = 0;         ///< ADRaw: the A/D value
        std::uint16_t normalized = 0;  ///< SensorRaw: the type's compensation of it
        std::int16_t scaled = 0;       ///< SensorValue: per the mode
    };

    std::array<Port, kInputCount> ports_{};
};

}  // namespace legofeup::nxtemu
