#pragma once
// The run log's text format, shared by its writer and its reader (docs/recording.md).
// Private to lessons/.
//
//   legofeup-run-log 3                  format and version (1: no optional-sensor columns,
//                                       2: no laser scan column)
//   program: legofeup-cli 0.4.0         header lines "key: value", in this order
//   title: experiment f: …
//   seed: 42
//   world: standard arena
//   link: lockstep
//   config: 120 lines                   followed by that many lines of TOML
//   columns: step,time,…                the record columns (run_log_columns())
//   1,0.05,1,0,…                        one record per control step
//   end: 2400 records                   written when the run ended normally
//
// Numbers are written shortest-round-trip (std::to_chars), so every double reads back to
// the identical value; empty cells mean "none" (no truth, no frame, no such sensor).
//
// Version 2 appends the optional sensors of the further lessons (docs/recording.md): gyro,
// the four accelerometer axes and compass as raw integers, and the beacon scan as one cell
// "<count>;<id>:<bearing>;…" (e.g. "2;3:-3.141592653589793;200:1.5", "0" for a scan that saw
// nothing). Version 1 logs (their 24 columns) still read, as frames without those sensors.
//
// Version 3 appends the laser scan (paper 001) as one cell "<beam count>;<r0>;<r1>;…" with
// each range in whole millimetres or its error code, exactly as in LaserScan ("0" for a scan
// of no beams); empty when the frame carried no scan. Version 2 logs (31 columns) read as
// frames without scans.

#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace legofeup::lessons::run_log_format {

inline constexpr std::string_view kProgram = "program";
inline constexpr std::string_view kTitle = "title";
inline constexpr std::string_view kSeed = "seed";
inline constexpr std::string_view kWorld = "world";
inline constexpr std::string_view kLink = "link";
inline constexpr std::string_view kConfig = "config";
inline constexpr std::string_view kColumns = "columns";
inline constexpr std::string_view kEnd = "end";

/// Record columns of version 1, in order.
inline constexpr std::string_view kColumnListV1 =
    "step,time,sequence,frame_missing,encoder_right,encoder_left,ir_adc_front,ir_adc_rear,"
    "ir_valid_front,ir_valid_rear,v1,v2,truth_x,truth_y,truth_theta,x,y,theta,"
    "p_xx,p_xy,p_xtheta,p_yy,p_ytheta,p_thetatheta";
inline constexpr int kColumnCountV1 = 24;
/// Record columns of version 2: version 1's, then the optional sensors'.
inline constexpr std::string_view kColumnListV2 =
    "step,time,sequence,frame_missing,encoder_right,encoder_left,ir_adc_front,ir_adc_rear,"
    "ir_valid_front,ir_valid_rear,v1,v2,truth_x,truth_y,truth_theta,x,y,theta,"
    "p_xx,p_xy,p_xtheta,p_yy,p_ytheta,p_thetatheta,"
    "gyro_raw,accel_right_forward,accel_right_left,accel_left_forward,accel_left_left,"
    "compass_deg,beacons";
inline constexpr int kColumnCountV2 = 31;
/// Record columns of the version written (3): version 2's, then the laser scan.
inline constexpr std::string_view kColumnList =
    "step,time,sequence,frame_missing,encoder_right,encoder_left,ir_adc_front,ir_adc_rear,"
    "ir_valid_front,ir_valid_rear,v1,v2,truth_x,truth_y,truth_theta,x,y,theta,"
    "p_xx,p_xy,p_xtheta,p_yy,p_ytheta,p_thetatheta,"
    "gyro_raw,accel_right_forward,accel_right_left,accel_left_forward,accel_left_left,"
    "compass_deg,beacons,laser_scan";
inline constexpr int kColumnCount = 32;
static_assert(kColumnListV2.starts_with(kColumnListV1));
static_assert(kColumnList.starts_with(kColumnListV2));

/// The record columns of a version (1 … kRunLogVersion) and their count.
inline std::string_view column_list(int version) {
    return version == 1 ? kColumnListV1 : version == 2 ? kColumnListV2 : kColumnList;
}
inline int column_count(int version) {
    return version == 1 ? kColumnCountV1 : version == 2 ? kColumnCountV2 : kColumnCount;
}

/// Separators inside the beacons cell: between the count and each sighting, and between a
/// sighting's id and bearing.
inline constexpr char kSightingSeparator = ';';
inline constexpr char kIdBearingSeparator = ':';
/// Separator inside the laser scan cell: between the beam count and each range.
inline constexpr char kRangeSeparator = ';';

/// `x` shortest-round-trip; "nan", "inf", "-inf" for the non-finite.
inline std::string number(double x) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    return {buffer, result.ptr};
}

/// The whole of `text` as a T, or none.
template <typename T>
std::optional<T> parse(std::string_view text) {
    T value{};
    const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || result.ec != std::errc{} || result.ptr != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

/// One line of header text: line breaks would end the line early.
inline std::string single_line(std::string text) {
    for (char& ch : text) {
        if (ch == '\n' || ch == '\r') {
            ch = ' ';
        }
    }
    return text;
}

}  // namespace legofeup::lessons::run_log_format
