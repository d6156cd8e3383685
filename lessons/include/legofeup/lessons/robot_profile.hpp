#pragma once
// A real robot's profile (TOML): how this particular NXT is built and wired, and what
// calibration found — wheel diameters and wheel base (UMBmark), the IR curve (eq. 2 fit),
// the ports and the motor constant. docs/calibration.md describes every field;
// resources/robots/nxt-default.toml is the profile of the nominal robot.
//
// Codo (counts per metre, eq. 9) follows from a wheel's diameter: Codo = 360/(π·D) for the
// NXT's 1° encoder counts. A profile stores the diameters; codo_right/codo_left are derived
// from them when the file leaves them out, and a file that sets them overrides the
// derivation (e.g. Codo measured directly by driving a known distance). save_robot_profile
// writes a Codo only when it is such an override.

#include <array>
#include <optional>
#include <string>

#include "legofeup/core/loop_config.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/core/sharp_ir.hpp"

namespace legofeup::lessons {

/// Encoder counts per wheel revolution of the NXT motors (1° each).
inline constexpr double kNxtCountsPerTurn = 360.0;

struct RobotProfile {
    std::string name;
    /// "" (choose at connection time) or the brick's address "00:16:53:XX:XX:XX".
    std::string bluetooth_address;
    double right_wheel_diameter = 0.0432;  ///< m (wheel 1)
    double left_wheel_diameter = 0.0432;   ///< m (wheel 2)
    double wheel_base = 0.12;              ///< b, m
    /// Codo1, Codo2 in counts per metre; the derived values unless the file overrides them.
    double codo_right = nominal_counts_per_metre(0.0432, kNxtCountsPerTurn);
    double codo_left = nominal_counts_per_metre(0.0432, kNxtCountsPerTurn);
    SharpIrCurve ir_curve;  ///< both sensors' curve (eq. 2) and trusted range
    /// A sensor's own eq. 2 parameters ([kFrontSensor], [kRearSensor]) where calibrate-ir
    /// fitted each unit (`front_c_m`, … in [ir_curve]); empty: ir_curve's.
    std::array<std::optional<IrCurveParameters>, kIrSensorCount> ir_sensor_parameters;
    double power_per_meter_per_second = 265.3;  ///< motor power per m/s of wheel speed
    int right_motor_port = 2;                   ///< output port: 0 = A, 1 = B, 2 = C
    int left_motor_port = 1;
    int front_ir_port = 0;  ///< input port: 0 = sensor port 1 … 3 = port 4
    int rear_ir_port = 1;
    bool reversed_motors = false;  ///< positive power drives the robot backwards
    std::string relay_program;     ///< "" = direct commands only; else e.g. "legofeup.rxe"
};

/// Sets codo_right and codo_left to the values derived from the wheel diameters.
void derive_codo(RobotProfile& profile);

/// The wheel diameters the profile's odometry stands for: the stored diameter of a wheel
/// whose Codo is derived, counts_per_turn/(π·Codo) for one whose Codo is overridden.
struct WheelDiameters {
    double right = 0.0;  ///< m
    double left = 0.0;   ///< m
};
WheelDiameters odometry_wheel_diameters(const RobotProfile& profile);

/// Reads a profile. Keys the file leaves out keep the defaults above. Throws InputError
/// listing every problem (path:line, field, value, reason): unknown keys, wrong types,
/// values out of range, ports used twice, a malformed Bluetooth address.
RobotProfile load_robot_profile(const std::string& path);

/// Parses a profile from text; `source` names it in messages.
RobotProfile parse_robot_profile(std::string_view text, const std::string& source);

/// The profile as a TOML document that load_robot_profile reads back to the same values,
/// each field with a comment saying what it is.
std::string robot_profile_to_toml(const RobotProfile& profile);

/// Writes the profile to `path` atomically (legofeup/fileio/atomic_file.hpp: `path`.partial
/// first, then a rename), so an existing profile is never left half-written. Throws
/// InputError if the profile is not valid, fileio::WriteError (a std::runtime_error) if the
/// file cannot be written.
void save_robot_profile(const std::string& path, const RobotProfile& profile);

/// The robot's part of the loop: odometry (Codo, wheel base) and the IR curves. Nothing
/// else in `config` changes.
void apply_robot_profile(const RobotProfile& profile, LoopConfig& config);

}  // namespace legofeup::lessons
