// Run log format version 2 (and 3): the optional sensors of a frame (gyro, accelerometers,
// compass, beacon scan) are written and read back bit for bit, a version-1 log still loads (as
// frames without them), and malformed optional-sensor cells are reported at file:line with their
// column (docs/recording.md).

#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "run_log_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace run_log_testing;

SensorFrame optional_sensor_base_frame(std::uint32_t sequence) {
    SensorFrame frame;
    frame.time = 0.05 * sequence;
    frame.sequence = sequence;
    frame.encoder_counts = {static_cast<std::int32_t>(10 * sequence), -3};
    frame.ir_adc = {300, 17};
    frame.ir_valid = {true, false};
    return frame;
}

/// The frames recorded: every optional sensor at its extremes with eight sightings whose
/// bearings need all 17 digits; none; an empty scan with a compass; a gyro and one sighting.
std::vector<SensorFrame> optional_sensor_frames() {
    std::vector<SensorFrame> out;
    SensorFrame full = optional_sensor_base_frame(1);
    full.has_gyro = true;
    full.gyro_raw = std::numeric_limits<std::int16_t>::min();
    full.has_accelerometers = true;
    full.accel_raw = {{{std::numeric_limits<std::int16_t>::max(), -1}, {0, -201}}};
    full.has_compass = true;
    full.compass_deg = 359;
    full.has_beacon_scan = true;
    full.beacons.count = kMaxBeaconSightings;
    const std::array<double, kMaxBeaconSightings> bearings{
        -0.0,
        std::numbers::pi,
        std::numeric_limits<double>::denorm_min(),
        0.1,
        std::nextafter(-std::numbers::pi, 0.0),
        1.0 / 3.0,
        -2.718281828459045,
        1e-300};
    for (std::size_t k = 0; k < kMaxBeaconSightings; ++k) {
        full.beacons.sightings[k] = {static_cast<std::uint8_t>(k == 7 ? 255 : k), bearings[k]};
    }
    out.push_back(full);
    out.push_back(optional_sensor_base_frame(2));
    SensorFrame empty_scan = optional_sensor_base_frame(3);
    empty_scan.has_beacon_scan = true;
    empty_scan.has_compass = true;
    empty_scan.compass_deg = 0;
    out.push_back(empty_scan);
    SensorFrame one = optional_sensor_base_frame(4);
    one.has_gyro = true;
    one.gyro_raw = 612;
    one.has_beacon_scan = true;
    one.beacons.count = 1;
    one.beacons.sightings[0] = {9, -1.5707963267948966};
    out.push_back(one);
    return out;
}

void expect_same_frame(const SensorFrame& actual, const SensorFrame& expected) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(actual.time),
              std::bit_cast<std::uint64_t>(expected.time));
    EXPECT_EQ(actual.sequence, expected.sequence);
    EXPECT_EQ(actual.encoder_counts, expected.encoder_counts);
    EXPECT_EQ(actual.ir_adc, expected.ir_adc);
    EXPECT_EQ(actual.ir_valid, expected.ir_valid);
    EXPECT_EQ(actual.has_gyro, expected.has_gyro);
    EXPECT_EQ(actual.gyro_raw, expected.gyro_raw);
    EXPECT_EQ(actual.has_accelerometers, expected.has_accelerometers);
    EXPECT_EQ(actual.accel_raw, expected.accel_raw);
    EXPECT_EQ(actual.has_compass, expected.has_compass);
    EXPECT_EQ(actual.compass_deg, expected.compass_deg);
    EXPECT_EQ(actual.has_beacon_scan, expected.has_beacon_scan);
    ASSERT_EQ(actual.beacons.count, expected.beacons.count);
    for (std::size_t k = 0; k < kMaxBeaconSightings; ++k) {
        EXPECT_EQ(actual.beacons.sightings[k].id, expected.beacons.sightings[k].id);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(actual.beacons.sightings[k].bearing),
                  std::bit_cast<std::uint64_t>(expected.beacons.sightings[k].bearing))
            << "sighting " << k << ": " << actual.beacons.sightings[k].bearing << " vs "
            << expected.beacons.sightings[k].bearing;
    }
}

/// Records optional_sensor_frames(), then a step without a frame, with an empty configuration
/// block.
fs::path record_optional_sensor_log(const std::string& name) {
    LoopSnapshot step;
    step.wheels = {0.1, 0.2};
    LoopSnapshot missing;
    missing.time = 0.25;
    missing.frame.time = 0.25;
    missing.frame.has_gyro = true;  // whatever a missing frame holds is not recorded
    return record_frames(name, "optional sensors", optional_sensor_frames(), step, missing);
}

TEST(RunLogOptionalSensors, EveryFieldRoundTripsBitForBit) {
    const fs::path path = record_optional_sensor_log("optional.log");
    const std::string text = read_text(path);
    EXPECT_EQ(text.rfind("legofeup-run-log 3\n", 0), 0U);
    EXPECT_NE(text.find(",compass_deg,beacons,laser_scan\n"), std::string::npos);

    const RunLog log = load_run_log(path);
    EXPECT_EQ(log.header.version, 3);
    ASSERT_EQ(log.records.size(), 5U);
    const std::vector<SensorFrame> expected = optional_sensor_frames();
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_FALSE(log.records[i].frame_missing);
        expect_same_frame(log.records[i].frame, expected[i]);
    }
    EXPECT_TRUE(log.records[4].frame_missing);
    EXPECT_FALSE(log.records[4].frame.has_gyro);
}

TEST(RunLogOptionalSensors, TheCellsAreThoseOfTheDocumentation) {
    const std::vector<std::string> lines =
        lines_of(read_text(record_optional_sensor_log("cells.log")));
    const int first = first_record_line(lines);
    // The seven cells of version 2's optional sensors (the last, version 3's laser scan, is
    // empty in these frames).
    auto tail = [&](int record, std::size_t count) {
        std::vector<std::string> cells = cells_of(lines[static_cast<std::size_t>(first + record)]);
        EXPECT_EQ(cells.size(), 32U);
        EXPECT_EQ(cells.back(), "");
        cells.pop_back();
        return joined_cells(std::vector<std::string>(
            cells.end() - static_cast<std::ptrdiff_t>(count), cells.end()));
    };
    EXPECT_EQ(tail(0, 7),
              "-32768,32767,-1,0,-201,359,8;0:-0;1:3.141592653589793;2:5e-324;3:0.1;"
              "4:-3.1415926535897927;5:0.3333333333333333;6:-2.718281828459045;255:1e-300");
    EXPECT_EQ(tail(1, 7), ",,,,,,");
    EXPECT_EQ(tail(2, 7), ",,,,,0,0");
    EXPECT_EQ(tail(3, 7), "612,,,,,,1;9:-1.5707963267948966");
    EXPECT_EQ(tail(4, 7), ",,,,,,");  // no frame
}

TEST(RunLogOptionalSensors, AVersionOneLogStillLoadsAsFramesWithoutThem) {
    std::vector<std::string> lines = lines_of(read_text(record_optional_sensor_log("v2.log")));
    lines[0] = "legofeup-run-log 1";
    const int first = first_record_line(lines);
    lines[static_cast<std::size_t>(first - 1)] = std::string("columns: ") +
        "step,time,sequence,frame_missing,encoder_right,encoder_left,ir_adc_front,ir_adc_rear,"
        "ir_valid_front,ir_valid_rear,v1,v2,truth_x,truth_y,truth_theta,x,y,theta,"
        "p_xx,p_xy,p_xtheta,p_yy,p_ytheta,p_thetatheta";
    for (std::size_t i = static_cast<std::size_t>(first); i + 1 < lines.size(); ++i) {
        std::vector<std::string> cells = cells_of(lines[i]);
        ASSERT_EQ(cells.size(), 32U) << lines[i];
        cells.resize(24);
        lines[i] = joined_cells(cells);
    }
    const fs::path path = temp_file("v1.log");
    write_text(path, joined(lines));

    const RunLog log = load_run_log(path);
    EXPECT_EQ(log.header.version, 1);
    EXPECT_TRUE(log.ended);
    ASSERT_EQ(log.records.size(), 5U);
    const std::vector<SensorFrame> recorded = optional_sensor_frames();
    for (std::size_t i = 0; i < recorded.size(); ++i) {
        SCOPED_TRACE(i);
        expect_same_frame(log.records[i].frame, optional_sensor_base_frame(recorded[i].sequence));
    }

    // A version-1 log with version 2's cells is refused: the count is the version's.
    std::vector<std::string> mixed = lines_of(read_text(record_optional_sensor_log("mixed.log")));
    mixed[0] = "legofeup-run-log 1";
    write_text(path, joined(mixed));
    EXPECT_NE(
        message_of(path).find(":" + std::to_string(first_record_line(mixed)) + ": columns = "),
        std::string::npos)
        << message_of(path);
}

TEST(RunLogOptionalSensors, MalformedCellsAreReportedAtFileLineWithTheColumn) {
    const std::vector<std::string> lines =
        lines_of(read_text(record_optional_sensor_log("good.log")));
    const int first = first_record_line(lines);
    const fs::path path = temp_file("bad.log");
    const int line_number = first + 1;  // the full frame's record, 1-based
    // Replaces cell `column` of the full frame's record and returns the reader's message.
    auto message_with = [&](std::size_t column, const std::string& value, int record = 0) {
        std::vector<std::string> changed = lines;
        const std::size_t index = static_cast<std::size_t>(first + record);
        std::vector<std::string> cells = cells_of(changed[index]);
        cells[column] = value;
        changed[index] = joined_cells(cells);
        write_text(path, joined(changed));
        return message_of(path);
    };
    const std::string at = path.string() + ":" + std::to_string(line_number) + ": ";
    constexpr std::size_t kGyro = 24;
    constexpr std::size_t kAccelRightLeft = 26;
    constexpr std::size_t kCompass = 29;
    constexpr std::size_t kBeacons = 30;

    EXPECT_EQ(message_with(kGyro, "fast"), at + "gyro_raw = fast: not a valid number");
    EXPECT_EQ(message_with(kGyro, "40000"), at + "gyro_raw = 40000: not a valid number");
    EXPECT_EQ(message_with(kCompass, "1.5"), at + "compass_deg = 1.5: not a valid number");
    EXPECT_EQ(
        message_with(kAccelRightLeft, ""),
        at + "accel_right_left: the four accelerometer cells are either all empty or all set");
    EXPECT_EQ(message_with(kBeacons, "9"),
              at + "beacons = 9: expected the sighting count (0 … 8) first, then \";id:bearing\" "
                   "per sighting");
    EXPECT_EQ(message_with(kBeacons, "2;1:0.5"),
              at + "beacons = 2;1:0.5: the count says 2 sightings, sighting 2 is missing");
    EXPECT_EQ(message_with(kBeacons, "1;1:0.5;2:0.25"),
              at + "beacons = 1;1:0.5;2:0.25: more sightings than the count 1");
    EXPECT_EQ(message_with(kBeacons, "1;256:0.5"),
              at + "beacons = 1;256:0.5: sighting 1 must be \"id:bearing\" with an id 0 … 255");
    EXPECT_EQ(message_with(kBeacons, "1;7"),
              at + "beacons = 1;7: sighting 1 must be \"id:bearing\" with an id 0 … 255");
    EXPECT_EQ(message_with(kBeacons, "1;7:north"),
              at + "beacons = 1;7:north: sighting 1: the bearing is not a number");
    // A record without a frame must leave every optional-sensor cell empty.
    const std::string missing_at = path.string() + ":" + std::to_string(first + 5) + ": ";
    EXPECT_EQ(message_with(kCompass, "90", 4),
              missing_at + "compass_deg = 90: must be empty in a record without a frame");
}

}  // namespace
}  // namespace legofeup::lessons
