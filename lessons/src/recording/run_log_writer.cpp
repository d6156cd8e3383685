#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include "legofeup/core/odometry.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "run_log_format.hpp"

namespace legofeup::lessons {
namespace {

namespace format = run_log_format;

/// The configuration the loop of `run` really runs with. A robot profile (CLI --profile)
/// changes the loop's odometry and IR curve after resolve(); those values go into the
/// configuration as explicit settings so that resolving the recorded configuration gives
/// the same loop. The world and map files become absolute (built-in names stay as they
/// are), so the log reads from any directory.
RunConfig configuration_as_run(const ResolvedRun& run) {
    RunConfig config = run.config;
    const LoopConfig& loop = run.loop;
    const double nominal =
        nominal_counts_per_metre(config.robot.wheel_diameter, config.robot.counts_per_turn);
    const double codo_right = config.robot.codo_right > 0.0 ? config.robot.codo_right : nominal;
    const double codo_left = config.robot.codo_left > 0.0 ? config.robot.codo_left : nominal;
    if (loop.odometry.codo_right != codo_right) {
        config.robot.codo_right = loop.odometry.codo_right;
    }
    if (loop.odometry.codo_left != codo_left) {
        config.robot.codo_left = loop.odometry.codo_left;
    }
    config.robot.wheel_base = loop.odometry.wheel_base;
    config.ir_curve = loop.ir_curve;
    for (const Setting& setting : run_settings()) {
        if (!setting.built_in_files) {
            continue;
        }
        const std::string file = std::get<std::string>(setting.get(config));
        const auto& built_in = setting.built_in_files();
        if (file.empty() || std::find(built_in.begin(), built_in.end(), file) != built_in.end()) {
            continue;
        }
        std::error_code ignored;
        const std::filesystem::path absolute = std::filesystem::absolute(file, ignored);
        if (!absolute.empty()) {
            setting.set(config, absolute.lexically_normal().string());
        }
    }
    return config;
}

std::size_t line_count(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'))
           + (text.empty() || text.back() == '\n' ? 0 : 1);
}

/// The version-3 laser scan cell "<beam count>;<r0>;…" (ranges in whole millimetres or
/// error codes), with its leading comma; empty when the frame carried no scan.
void append_laser_scan_cell(const SensorFrame& frame, std::string& cells) {
    cells += ',';
    if (!frame.has_laser_scan) {
        return;
    }
    const LaserScan& scan = frame.laser;
    const int count = std::min<int>(scan.beam_count, kMaxScanBeams);
    cells += std::to_string(count);
    for (int i = 0; i < count; ++i) {
        cells += format::kRangeSeparator;
        cells += std::to_string(scan.range_mm[static_cast<std::size_t>(i)]);
    }
}

/// The version-2 and -3 cells of the optional sensors, each with its leading comma: empty
/// when the frame lacked the sensor (or there was no frame). docs/recording.md, "Optional
/// sensors".
std::string optional_sensor_cells(const SensorFrame& frame, bool frame_missing) {
    if (frame_missing) {
        return ",,,,,,,,";
    }
    std::string cells;
    const auto cell = [&cells](bool present, int value) {
        cells += ',';
        if (present) {
            cells += std::to_string(value);
        }
    };
    cell(frame.has_gyro, frame.gyro_raw);
    for (const auto& unit : frame.accel_raw) {
        for (const std::int16_t axis : unit) {
            cell(frame.has_accelerometers, axis);
        }
    }
    cell(frame.has_compass, frame.compass_deg);
    cells += ',';
    if (frame.has_beacon_scan) {
        const int count = std::min<int>(frame.beacons.count, kMaxBeaconSightings);
        cells += std::to_string(count);
        for (int k = 0; k < count; ++k) {
            const BeaconSighting& sighting = frame.beacons.sightings[static_cast<std::size_t>(k)];
            cells += format::kSightingSeparator + std::to_string(sighting.id)
                     + format::kIdBearingSeparator + format::number(sighting.bearing);
        }
    }
    append_laser_scan_cell(frame, cells);
    return cells;
}

}  // namespace

RunLogWriter::RunLogWriter(const std::filesystem::path& path, const ResolvedRun& run,
                           const std::string& title)
    : RunLogWriter(path, run, title, Options{}) {}

RunLogWriter::RunLogWriter(const std::filesystem::path& path, const ResolvedRun& run,
                           const std::string& title, Options options)
    : path_(path), out_(path, std::ios::out | std::ios::trunc), options_(std::move(options)) {
    if (!out_) {
        throw RunLogWriteError("cannot create the run log " + path_.string());
    }
    std::string config = config_to_toml(configuration_as_run(run), format::single_line(title));
    if (!config.empty() && config.back() != '\n') {
        config += '\n';
    }
    out_ << kRunLogFormat << ' ' << kRunLogVersion << '\n'
         << format::kProgram << ": " << format::single_line(options_.program) << '\n'
         << format::kTitle << ": " << format::single_line(title) << '\n'
         << format::kSeed << ": " << run.config.seed << '\n'
         << format::kWorld << ": " << format::single_line(run.world.name) << '\n'
         << format::kLink << ": " << format::single_line(options_.link) << '\n'
         << format::kConfig << ": " << line_count(config) << " lines\n"
         << config << format::kColumns << ": " << format::kColumnList << '\n';
    out_.flush();
    check("write the header of");
    last_flush_ = options_.clock();
}

RunLogWriter::~RunLogWriter() {
    // Unwinding from an exception (the link failed, the program gave up): keep what was
    // recorded but write no end line, so the log says the run did not end normally.
    if (std::uncaught_exceptions() > 0 && !closed_) {
        out_.flush();
        return;
    }
    try {
        close();
    } catch (const RunLogWriteError&) {
        // Destructors must not throw; close() explicitly to see the error.
    }
}

void RunLogWriter::on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    if (closed_) {
        throw RunLogWriteError("the run log " + path_.string() + " is already closed");
    }
    using format::number;
    const SensorFrame& frame = snapshot.frame;
    std::string line = std::to_string(snapshot.step) + ',' + number(snapshot.time) + ',';
    if (snapshot.frame_missing) {
        line += ",1,,,,,,";  // sequence, encoder counts, A/D and valid flags do not exist
    } else {
        line += std::to_string(frame.sequence) + ",0," + std::to_string(frame.encoder_counts[0])
                + ',' + std::to_string(frame.encoder_counts[1]) + ','
                + std::to_string(frame.ir_adc[0]) + ',' + std::to_string(frame.ir_adc[1]) + ','
                + (frame.ir_valid[0] ? '1' : '0') + ',' + (frame.ir_valid[1] ? '1' : '0');
    }
    line += ',' + number(snapshot.wheels.right) + ',' + number(snapshot.wheels.left) + ',';
    if (truth_known(truth)) {
        line += number(truth.pose.x) + ',' + number(truth.pose.y) + ',' + number(truth.pose.theta);
    } else {
        line += ",,";
    }
    const StateVector& x = snapshot.estimate;
    const StateCovariance& p = snapshot.covariance;
    for (const double value :
         {x(0), x(1), x(2), p(0, 0), p(0, 1), p(0, 2), p(1, 1), p(1, 2), p(2, 2)}) {
        line += ',' + number(value);
    }
    line += optional_sensor_cells(frame, snapshot.frame_missing);
    out_ << line << '\n';
    ++records_;
    check("write to");
    flush_if_due();
}

void RunLogWriter::close() {
    if (closed_) {
        return;
    }
    closed_ = true;
    out_ << format::kEnd << ": " << records_ << " records\n";
    out_.flush();
    check("finish");
    out_.close();
}

void RunLogWriter::check(const char* what) {
    if (!out_) {
        throw RunLogWriteError(std::string("cannot ") + what + " the run log " + path_.string());
    }
}

void RunLogWriter::flush_if_due() {
    const auto now = options_.clock();
    if (now - last_flush_ >= options_.flush_interval) {
        out_.flush();
        check("flush");
        last_flush_ = now;
    }
}

}  // namespace legofeup::lessons
