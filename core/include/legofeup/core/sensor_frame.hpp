#pragma once
// What one control period brings in from the robot or the simulator: the loop's only input.

#include <array>
#include <cstdint>

namespace legofeup {

struct SensorFrame {
    double time = 0.0;           ///< s, the source's clock (simulated or robot time)
    std::uint32_t sequence = 0;  ///< frame counter of the source
    /// Cumulative encoder counts (1 count = 1°): [0] right wheel (1), [1] left wheel (2).
    std::array<std::int32_t, 2> encoder_counts{};
    /// Raw 10-bit A/D values of the IR sensors: [0] front (d_s1), [1] rear (d_s2).
    std::array<std::uint16_t, 2> ir_adc{};
    /// false when the source had no valid reading for a sensor (e.g. just after SETINPUTMODE).
    std::array<bool, 2> ir_valid{true, true};
};

}  // namespace legofeup
