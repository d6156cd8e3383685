#pragma once
// What one control period brings in from the robot or the simulator: the loop's only input.
// The encoders and IR sensors are always there; the further lessons' sensors (beacon scanner,
// gyroscope, accelerometers, compass) are optional and flagged, raw as the hardware reports
// them. Fixed size, no heap: a frame is copied across threads and recorded.

#include <array>
#include <cstdint>

#include "legofeup/core/laser_scan.hpp"

namespace legofeup {

/// At most this many beacon sightings per scan (more beacons are allowed in a world; the
/// scanner reports the first this many it sees, in beacon id order).
inline constexpr int kMaxBeaconSightings = 8;

/// One beacon seen by the 360° bearing-only scanner.
struct BeaconSighting {
    std::uint8_t id = 0;  ///< the beacon's id (as in the world file)
    /// rad in (−π, π]: direction of the beacon relative to the robot's heading,
    /// counter-clockwise positive (0 = straight ahead).
    double bearing = 0.0;

    friend bool operator==(const BeaconSighting&, const BeaconSighting&) = default;
};

struct BeaconScan {
    std::uint8_t count = 0;  ///< sightings[0 .. count) are valid
    std::array<BeaconSighting, kMaxBeaconSightings> sightings{};

    friend bool operator==(const BeaconScan&, const BeaconScan&) = default;
};

/// Accelerometer axes: [kAccelForward] along the robot's heading, [kAccelLeft] to its left.
enum AccelAxis : int { kAccelForward = 0, kAccelLeft = 1 };
/// The two accelerometers sit over the wheels (paper 003): [kAccelRightWheel], [kAccelLeftWheel].
enum AccelUnit : int { kAccelRightWheel = 0, kAccelLeftWheel = 1 };

struct SensorFrame {
    double time = 0.0;           ///< s, the source's clock (simulated or robot time)
    std::uint32_t sequence = 0;  ///< frame counter of the source
    /// Cumulative encoder counts (1 count = 1°): [0] right wheel (1), [1] left wheel (2).
    std::array<std::int32_t, 2> encoder_counts{};
    /// Raw 10-bit A/D values of the IR sensors: [0] front (d_s1), [1] rear (d_s2).
    std::array<std::uint16_t, 2> ir_adc{};
    /// false when the source had no valid reading for a sensor (e.g. just after SETINPUTMODE).
    std::array<bool, 2> ir_valid{true, true};

    // Optional sensors of the further lessons (docs/sensors.md): each is present only when
    // its has_ flag is set.
    bool has_beacon_scan = false;
    BeaconScan beacons;  ///< the scan completed in this period
    bool has_gyro = false;
    /// Raw single-axis gyroscope value (HiTechnic-like): offset + rate in °/s (≈1 count per
    /// °/s, counter-clockwise positive) + bias; saturates at offset ± 360.
    std::int16_t gyro_raw = 0;
    bool has_accelerometers = false;
    /// Raw two-axis accelerometer values, ≈200 counts per g: [unit][axis].
    std::array<std::array<std::int16_t, 2>, 2> accel_raw{};
    bool has_compass = false;
    /// Compass heading in whole degrees [0, 360), measured counter-clockwise from the world's
    /// x axis (the arena's "magnetic east"), disturbed by the indoor field.
    std::int16_t compass_deg = 0;
    bool has_laser_scan = false;
    /// The laser rangefinder's scan completed in this period (paper 001; URG-04LX-like,
    /// one scan per 100 ms, so on every other 50 ms frame).
    LaserScan laser;
};

}  // namespace legofeup
