// Run log format version 3: a frame's laser scan is written as "<beam count>;<range>;…" and
// read back exactly (error codes included), a version-2 log still loads (as frames without
// scans), malformed scan cells are reported at file:line with the column, and a recorded
// laser run in the office replays bit for bit, so re-filtering it compares filters on the
// identical scans (docs/recording.md).

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "run_log_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace run_log_testing;

SensorFrame laser_base_frame(std::uint32_t sequence) {
    SensorFrame frame;
    frame.time = 0.05 * sequence;
    frame.sequence = sequence;
    frame.encoder_counts = {static_cast<std::int32_t>(7 * sequence), 11};
    frame.ir_adc = {250, 260};
    frame.ir_valid = {true, true};
    return frame;
}

/// A URG-like scan (682 beams) with every kind of value: error codes 0, 1, 2 and others
/// below 20, the smallest distance, the largest 16-bit value; a scan of no beams; the
/// largest scan; a frame without one; a three-beam scan next to a compass reading.
std::vector<SensorFrame> laser_frames() {
    std::vector<SensorFrame> out;
    SensorFrame urg = laser_base_frame(1);
    urg.has_laser_scan = true;
    urg.laser.beam_count = 682;
    for (std::size_t i = 0; i < 682; ++i) {
        urg.laser.range_mm[i] = static_cast<std::uint16_t>((i * 7919U) % 5600U);
    }
    urg.laser.range_mm[0] = kRangeNoEcho;
    urg.laser.range_mm[1] = kRangeTooNear;
    urg.laser.range_mm[2] = kRangeDropout;
    urg.laser.range_mm[3] = 19;
    urg.laser.range_mm[4] = kRangeFirstValid;
    urg.laser.range_mm[681] = 65535;
    out.push_back(urg);
    SensorFrame empty = laser_base_frame(2);
    empty.has_laser_scan = true;
    out.push_back(empty);
    SensorFrame largest = laser_base_frame(3);
    largest.has_laser_scan = true;
    largest.laser.beam_count = kMaxScanBeams;
    for (std::size_t i = 0; i < static_cast<std::size_t>(kMaxScanBeams); ++i) {
        largest.laser.range_mm[i] = static_cast<std::uint16_t>(1000 + i);
    }
    out.push_back(largest);
    out.push_back(laser_base_frame(4));
    SensorFrame small = laser_base_frame(5);
    small.has_laser_scan = true;
    small.laser.beam_count = 3;
    small.laser.range_mm[0] = 1234;
    small.laser.range_mm[1] = 0;
    small.laser.range_mm[2] = 4000;
    small.has_compass = true;
    small.compass_deg = 90;
    out.push_back(small);
    return out;
}

/// Records laser_frames(), then a step without a frame, with an empty configuration block.
fs::path record_laser_log(const std::string& name) {
    LoopSnapshot missing;
    missing.time = 0.3;
    missing.frame.time = 0.3;
    missing.frame.has_laser_scan = true;  // whatever a missing frame holds is not recorded
    missing.frame.laser.beam_count = 5;
    return record_frames(name, "laser scans", laser_frames(), LoopSnapshot{}, missing);
}

TEST(RunLogLaser, EveryScanRoundTripsExactly) {
    const fs::path path = record_laser_log("scans.log");
    const std::string text = read_text(path);
    EXPECT_EQ(text.rfind("legofeup-run-log 3\n", 0), 0U);
    EXPECT_NE(text.find(",beacons,laser_scan\n"), std::string::npos);
    const RunLog log = load_run_log(path);
    EXPECT_EQ(log.header.version, 3);
    const std::vector<SensorFrame> expected = laser_frames();
    ASSERT_EQ(log.records.size(), expected.size() + 1);
    for (std::size_t i = 0; i < expected.size(); ++i) {
        SCOPED_TRACE(i);
        const SensorFrame& frame = log.records[i].frame;
        EXPECT_EQ(frame.has_laser_scan, expected[i].has_laser_scan);
        EXPECT_EQ(frame.laser, expected[i].laser);  // all kMaxScanBeams entries
        EXPECT_EQ(frame.encoder_counts, expected[i].encoder_counts);
        EXPECT_EQ(frame.has_compass, expected[i].has_compass);
    }
    EXPECT_TRUE(log.records.back().frame_missing);
    EXPECT_FALSE(log.records.back().frame.has_laser_scan);
}

TEST(RunLogLaser, TheCellIsTheCountThenEachRangeInMillimetres) {
    const std::vector<std::string> lines = lines_of(read_text(record_laser_log("cells.log")));
    const std::size_t first = static_cast<std::size_t>(first_record_line(lines));
    const auto last_cell = [&](std::size_t record) {
        const std::vector<std::string> cells = cells_of(lines[first + record]);
        EXPECT_EQ(cells.size(), 32U);
        return cells.back();
    };
    const std::string urg = last_cell(0);
    EXPECT_EQ(urg.rfind("682;0;1;2;19;20;", 0), 0U) << urg.substr(0, 40);
    EXPECT_EQ(urg.substr(urg.size() - 6), ";65535");
    EXPECT_EQ(last_cell(1), "0");
    EXPECT_EQ(last_cell(2).rfind("1024;1000;1001;", 0), 0U);
    EXPECT_EQ(last_cell(3), "");
    EXPECT_EQ(last_cell(4), "3;1234;0;4000");
    EXPECT_EQ(last_cell(5), "");  // no frame
}

TEST(RunLogLaser, AVersionTwoLogStillLoadsAsFramesWithoutScans) {
    std::vector<std::string> lines = lines_of(read_text(record_laser_log("v3.log")));
    lines[0] = "legofeup-run-log 2";
    const std::size_t first = static_cast<std::size_t>(first_record_line(lines));
    std::string& columns = lines[first - 1];
    ASSERT_EQ(columns.substr(columns.size() - 11), ",laser_scan");
    columns.resize(columns.size() - 11);
    for (std::size_t i = first; i + 1 < lines.size(); ++i) {
        std::vector<std::string> cells = cells_of(lines[i]);
        ASSERT_EQ(cells.size(), 32U);
        cells.pop_back();
        lines[i] = joined_cells(cells);
    }
    const fs::path path = temp_file("v2.log");
    write_text(path, joined(lines));
    const RunLog log = load_run_log(path);
    EXPECT_EQ(log.header.version, 2);
    EXPECT_TRUE(log.ended);
    ASSERT_EQ(log.records.size(), 6U);
    for (const RunLogRecord& record : log.records) {
        EXPECT_FALSE(record.frame.has_laser_scan);
        EXPECT_EQ(record.frame.laser.beam_count, 0);
    }
    EXPECT_TRUE(log.records[4].frame.has_compass);  // version 2's sensors are still read

    // A version-2 log with version 3's cells is refused: the count is the version's.
    std::vector<std::string> mixed = lines_of(read_text(record_laser_log("mixed.log")));
    mixed[0] = "legofeup-run-log 2";
    write_text(path, joined(mixed));
    EXPECT_NE(
        message_of(path).find(":" + std::to_string(first_record_line(mixed)) + ": columns = "),
        std::string::npos)
        << message_of(path);
}

TEST(RunLogLaser, MalformedScanCellsAreReportedAtFileLineWithTheColumn) {
    const std::vector<std::string> lines = lines_of(read_text(record_laser_log("good.log")));
    const int first = first_record_line(lines);
    const fs::path path = temp_file("bad.log");
    auto message_with = [&](const std::string& value, int record = 4) {
        std::vector<std::string> changed = lines;
        const std::size_t index = static_cast<std::size_t>(first + record);
        std::vector<std::string> cells = cells_of(changed[index]);
        cells.back() = value;
        changed[index] = joined_cells(cells);
        write_text(path, joined(changed));
        return message_of(path);
    };
    const std::string at = path.string() + ":" + std::to_string(first + 5) + ": ";
    EXPECT_EQ(message_with("many"), at + "laser_scan = many: expected the beam count (0 … 1024) "
                                         "first, then \";range\" per beam in millimetres");
    EXPECT_EQ(message_with("1025"), at + "laser_scan = 1025: expected the beam count (0 … 1024) "
                                         "first, then \";range\" per beam in millimetres");
    EXPECT_EQ(message_with("3;1;2"),
              at + "laser_scan = 3;1;2: the count says 3 beams, beam 2 is missing");
    EXPECT_EQ(message_with("1;1;2"), at + "laser_scan = 1;1;2: more ranges than the beam count 1");
    EXPECT_EQ(
        message_with("2;5;65536"),
        at + "laser_scan = 2;5;65536: beam 1: the range must be whole millimetres, 0 … 65535");
    EXPECT_EQ(message_with("1;-5"),
              at + "laser_scan = 1;-5: beam 0: the range must be whole millimetres, 0 … 65535");
    EXPECT_EQ(message_with("1;2.5"),
              at + "laser_scan = 1;2.5: beam 0: the range must be whole millimetres, 0 … 65535");
    const std::string missing_at = path.string() + ":" + std::to_string(first + 6) + ": ";
    EXPECT_EQ(message_with("1;500", 5),
              missing_at + "laser_scan = 1;500: must be empty in a record without a frame");
}

// --- A recorded laser run ---------------------------------------------------------------------

/// Ten seconds along the office lap with the laser filter (an EKF unless told) and the
/// simulated scanner.
ResolvedRun office_laser_drive(FilterKind kind = FilterKind::Ekf) {
    RunConfig config;
    config.lesson.kind = kind;
    config.seed = 3;
    config.world_file = "office";
    config.lesson.localisation = Localisation::Laser;
    config.physical.laser_scanner.enabled = true;
    config.routine.kind = RoutineSpec::Kind::Line;
    config.routine.line_from = {1.0, 0.8};
    config.routine.line_to = {5.0, 0.8};
    config.duration = 10.0;
    return resolve(config);
}

TEST(RunLogLaser, ARecordedLaserRunReplaysBitForBitAndRefiltersOnTheSameScans) {
    const ResolvedRun run = office_laser_drive();
    const fs::path path = temp_file("office.log");
    SnapshotKeeper live;
    {
        RunLogWriter writer(path, run, "laser run");
        Both both(writer, live);
        run_lockstep(run, &both);
        writer.close();
    }
    const RunLog log = load_run_log(path);
    ASSERT_EQ(log.records.size(), live.snapshots.size());
    int scans = 0;
    int matches = 0;
    for (std::size_t i = 0; i < live.snapshots.size(); ++i) {
        EXPECT_EQ(log.records[i].frame.has_laser_scan, live.snapshots[i].frame.has_laser_scan);
        EXPECT_EQ(log.records[i].frame.laser, live.snapshots[i].frame.laser) << i;
        scans += log.records[i].frame.has_laser_scan ? 1 : 0;
        matches += live.snapshots[i].laser.matched ? 1 : 0;
    }
    // One scan per 100 ms over 10 s, most of them matched.
    EXPECT_GE(scans, 95);
    EXPECT_GE(matches, scans / 2);

    // The recorded configuration names the built-in world by its name and gives the same map.
    EXPECT_EQ(log.config.world_file, "office");
    const RefilterResult same = refilter(log, log.config);
    EXPECT_TRUE(same.reproduces_recording());
    EXPECT_EQ(same.old_replay_deviation, 0.0);

    // Another filter on the identical scans: the laser switched off is odometry alone.
    RunConfig odometry = log.config;
    odometry.lesson.laser.min_matched_points = kMaxScanBeams;  // more than a scan has
    const RefilterResult other = refilter(log, odometry);
    double largest = 0.0;
    for (const RefilterStep& step : other.steps) {
        largest = std::max(largest, (step.new_estimate - step.old_estimate).norm());
    }
    EXPECT_GT(largest, 0.0);
}

/// office_laser_drive with `kind`, recorded into the temporary file `name` and read back.
RunLog record_office_drive(FilterKind kind, const std::string& name) {
    const fs::path path = temp_file(name);
    const ResolvedRun run = office_laser_drive(kind);
    RunLogWriter writer(path, run, "office drive");
    run_lockstep(run, &writer);
    writer.close();
    return load_run_log(path);
}

// The particle filter draws its samples from streams seeded by the run's seed, so its
// recorded run replays bit for bit as the EKF's does; and the EKF's log re-filtered with
// the particle filter compares the two on the identical scans.
TEST(RunLogLaser, AParticleFilterRunReplaysBitForBitAndAnEkfLogRefiltersWithIt) {
    const RunLog pf_log = record_office_drive(FilterKind::Pf, "office-pf.log");
    EXPECT_EQ(pf_log.config.lesson.kind, FilterKind::Pf);
    const RefilterResult same = refilter(pf_log, pf_log.config);
    EXPECT_TRUE(same.reproduces_recording()) << same.old_replay_deviation;

    // Another particle count draws other samples: the same frames, another estimate.
    RunConfig fewer = pf_log.config;
    fewer.lesson.particles.particle_count /= 2;
    const RefilterResult halved = refilter(pf_log, fewer);
    double moved = 0.0;
    for (const RefilterStep& step : halved.steps) {
        moved = std::max(moved, (step.new_estimate - step.old_estimate).norm());
    }
    EXPECT_GT(moved, 0.0);

    const RunLog ekf_log = record_office_drive(FilterKind::Ekf, "office-ekf.log");
    RunConfig as_pf = ekf_log.config;
    as_pf.lesson.kind = FilterKind::Pf;
    const RefilterResult compared = refilter(ekf_log, as_pf);
    ASSERT_EQ(compared.steps.size(), ekf_log.records.size());
    // Both filters track the robot on these scans (laser:a's EKF is within a few cm; the
    // particle filter's cloud from the same known start stays on it), yet they are two
    // filters: their estimates differ somewhere along the lap.
    double differ = 0.0;
    for (const RefilterStep& step : compared.steps) {
        ASSERT_TRUE(step.truth.has_value());
        const Eigen::Vector2d truth(step.truth->x, step.truth->y);
        EXPECT_LT((step.new_estimate.head<2>() - truth).norm(), 0.15) << step.time;
        EXPECT_LT((step.old_estimate.head<2>() - truth).norm(), 0.15) << step.time;
        differ = std::max(differ, (step.new_estimate - step.old_estimate).norm());
    }
    EXPECT_GT(differ, 1e-3);
    ASSERT_TRUE(compared.new_metrics.truth.has_value());
}

}  // namespace
}  // namespace legofeup::lessons
