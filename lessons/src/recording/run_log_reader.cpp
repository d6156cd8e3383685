#include <cmath>
#include <sstream>
#include <utility>

#include "../text_file.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "run_log_format.hpp"

namespace legofeup::lessons {
namespace {

namespace format = run_log_format;

/// Walks the file's lines, each with its 1-based number; knows whether the last one was
/// cut off (the file does not end in a line break).
class LineReader {
  public:
    LineReader(std::string text, std::string source)
        : text_(std::move(text)), source_(std::move(source)) {}

    bool at_end() const { return position_ >= text_.size(); }
    int line() const { return line_; }
    const std::string& source() const { return source_; }
    /// The line just read had no line break after it: the writer was stopped mid-line.
    bool last_cut_off() const { return cut_off_; }

    std::string_view next() {
        const std::size_t end = text_.find('\n', position_);
        cut_off_ = end == std::string::npos;
        const std::size_t stop = cut_off_ ? text_.size() : end;
        std::string_view line(text_.data() + position_, stop - position_);
        position_ = cut_off_ ? text_.size() : end + 1;
        ++line_;
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        return line;
    }

    [[noreturn]] void fail(const std::string& reason, const std::string& key = {},
                           const std::string& value = {}) const {
        throw InputError({{source_, line_, key, value, reason}});
    }

  private:
    std::string text_;
    std::string source_;
    std::size_t position_ = 0;
    int line_ = 0;
    bool cut_off_ = false;
};

std::string_view rest_after(std::string_view text, std::string_view prefix) {
    return text.substr(prefix.size());
}

/// The value of header line "key: value"; the key must be `key`.
std::string header_value(LineReader& reader, std::string_view key) {
    if (reader.at_end()) {
        reader.fail("the log ends inside its header (expected \"" + std::string(key)
                    + ": …\"): the recording stopped before its first step");
    }
    const std::string_view line = reader.next();
    const std::string prefix = std::string(key) + ": ";
    if (reader.last_cut_off() || line.substr(0, prefix.size()) != prefix) {
        reader.fail("expected the header line \"" + std::string(key) + ": …\"", "",
                    std::string(line.substr(0, 60)));
    }
    return std::string(rest_after(line, prefix));
}

void read_version(LineReader& reader, RunLogHeader& header) {
    const std::string_view first = reader.at_end() ? std::string_view{} : reader.next();
    const std::string prefix = std::string(kRunLogFormat) + ' ';
    if (first.substr(0, prefix.size()) != prefix) {
        reader.fail("not a LegoFeup run log: the first line must be \"" + prefix
                    + std::to_string(kRunLogVersion) + "\"");
    }
    const std::string version(rest_after(first, prefix));
    const auto number = format::parse<int>(version);
    if (!number || *number < 1) {
        reader.fail("not a valid format version", "version", version);
    }
    if (*number > kRunLogVersion) {
        reader.fail("run log format version " + version
                        + " is newer than this program reads (up to "
                        + std::to_string(kRunLogVersion) + "): update LegoFeup Lab",
                    "version", version);
    }
    header.version = *number;
}

/// The configuration block: its line count, then that many lines of TOML, read over the
/// defaults. Its problems are reported at their lines in the log.
void read_config(LineReader& reader, RunLog& log) {
    const std::string count_text = header_value(reader, format::kConfig);
    const std::size_t space = count_text.find(' ');
    const auto count = format::parse<int>(std::string_view(count_text).substr(0, space));
    if (!count || *count < 0
        || count_text.substr(space == std::string::npos ? 0 : space) != " lines") {
        reader.fail("expected \"config: <number> lines\"", "config", count_text);
    }
    const int first_line = reader.line() + 1;
    std::string text;
    for (int i = 0; i < *count; ++i) {
        if (reader.at_end()) {
            reader.fail(
                "the log ends inside its configuration block: the recording stopped "
                "before its first step");
        }
        text += reader.next();
        text += '\n';
    }
    log.header.config_toml = text;
    const std::filesystem::path source(reader.source());
    try {
        apply_config_toml(text, reader.source(), log.config, source.parent_path());
    } catch (const InputError& error) {
        // apply_config_toml counts lines from the block's start; the log counts from its own.
        std::vector<InputProblem> problems = error.problems();
        for (InputProblem& problem : problems) {
            if (problem.source == reader.source() && problem.line > 0) {
                problem.line += first_line - 1;
            }
        }
        throw InputError(std::move(problems));
    }
    for (auto& [name, origin] : log.config.origins) {
        if (origin.source == reader.source() && origin.line > 0) {
            origin.line += first_line - 1;
        }
    }
}

std::vector<std::string_view> split(std::string_view line) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string_view::npos) {
            return cells;
        }
        start = comma + 1;
    }
}

/// Reads record cells by column, failing with the column's name.
class CellReader {
  public:
    CellReader(const LineReader& reader, const std::vector<std::string_view>& cells)
        : reader_(reader), cells_(cells), names_(split(format::kColumnList)) {}

    template <typename T>
    T get(int column) const {
        const auto value = format::parse<T>(cell(column));
        if (!value) {
            reader_.fail("not a valid number", name(column), std::string(cell(column)));
        }
        return *value;
    }
    bool flag(int column) const {
        const std::string_view text = cell(column);
        if (text != "0" && text != "1") {
            reader_.fail("expected 0 or 1", name(column), std::string(text));
        }
        return text == "1";
    }
    bool empty(int column) const { return cell(column).empty(); }
    std::string_view text(int column) const { return cell(column); }
    [[noreturn]] void fail(int column, const std::string& why) const {
        reader_.fail(why, name(column), std::string(cell(column)));
    }
    void require_empty(int column, const char* why) const {
        if (!empty(column)) {
            reader_.fail(why, name(column), std::string(cell(column)));
        }
    }

  private:
    std::string_view cell(int column) const { return cells_[static_cast<std::size_t>(column)]; }
    std::string name(int column) const {
        return std::string(names_[static_cast<std::size_t>(column)]);
    }

    const LineReader& reader_;
    const std::vector<std::string_view>& cells_;
    std::vector<std::string_view> names_;
};

// Column indices of format::kColumnList.
enum Column : int {
    kStep,
    kTime,
    kSequence,
    kFrameMissing,
    kEncoderRight,
    kEncoderLeft,
    kAdcFront,
    kAdcRear,
    kValidFront,
    kValidRear,
    kV1,
    kV2,
    kTruthX,
    kTruthY,
    kTruthTheta,
    kEstimate,  // x, y, theta, then P's upper triangle by rows
    // Version 2: the optional sensors.
    kGyro = format::kColumnCountV1,
    kAccelRightForward,  // then right left, left forward, left left
    kCompass = kAccelRightForward + 4,
    kBeacons,
    // Version 3: the laser scan.
    kLaserScan,
};
static_assert(kBeacons + 1 == format::kColumnCountV2);
static_assert(kLaserScan + 1 == format::kColumnCount);

/// The beacons cell: "<count>" then ";<id>:<bearing>" per sighting.
BeaconScan parse_beacons(const CellReader& c) {
    const std::string_view text = c.text(kBeacons);
    std::size_t end = text.find(format::kSightingSeparator);
    const auto count = format::parse<int>(text.substr(0, end));
    if (!count || *count < 0 || *count > kMaxBeaconSightings) {
        c.fail(kBeacons, "expected the sighting count (0 … " + std::to_string(kMaxBeaconSightings)
                             + ") first, then \";id:bearing\" per sighting");
    }
    BeaconScan scan;
    scan.count = static_cast<std::uint8_t>(*count);
    for (int k = 0; k < *count; ++k) {
        const std::string sighting_name = "sighting " + std::to_string(k + 1);
        if (end == std::string_view::npos) {
            c.fail(kBeacons, "the count says " + std::to_string(*count) + " sightings, "
                                 + sighting_name + " is missing");
        }
        const std::size_t start = end + 1;
        end = text.find(format::kSightingSeparator, start);
        const std::string_view sighting = text.substr(start, end - start);
        const std::size_t colon = sighting.find(format::kIdBearingSeparator);
        const auto id = format::parse<std::uint8_t>(sighting.substr(0, colon));
        if (colon == std::string_view::npos || !id) {
            c.fail(kBeacons, sighting_name + " must be \"id:bearing\" with an id 0 … 255");
        }
        const auto bearing = format::parse<double>(sighting.substr(colon + 1));
        if (!bearing) {  // non-finite ones ("nan", "inf") are kept: the replay must be exact
            c.fail(kBeacons, sighting_name + ": the bearing is not a number");
        }
        scan.sightings[static_cast<std::size_t>(k)] = {*id, *bearing};
    }
    if (end != std::string_view::npos) {
        c.fail(kBeacons, "more sightings than the count " + std::to_string(*count));
    }
    return scan;
}

/// The laser scan cell: "<beam count>" then ";<range>" per beam (whole millimetres or an
/// error code, 0 … 65535).
LaserScan parse_laser_scan(const CellReader& c) {
    const std::string_view text = c.text(kLaserScan);
    std::size_t end = text.find(format::kRangeSeparator);
    const auto count = format::parse<int>(text.substr(0, end));
    if (!count || *count < 0 || *count > kMaxScanBeams) {
        c.fail(kLaserScan, "expected the beam count (0 … " + std::to_string(kMaxScanBeams)
                               + ") first, then \";range\" per beam in millimetres");
    }
    LaserScan scan;
    scan.beam_count = static_cast<std::uint16_t>(*count);
    for (int i = 0; i < *count; ++i) {
        const std::string beam_name = "beam " + std::to_string(i);
        if (end == std::string_view::npos) {
            c.fail(kLaserScan, "the count says " + std::to_string(*count) + " beams, " + beam_name
                                   + " is missing");
        }
        const std::size_t start = end + 1;
        end = text.find(format::kRangeSeparator, start);
        const auto range = format::parse<std::uint16_t>(text.substr(start, end - start));
        if (!range) {
            c.fail(kLaserScan, beam_name + ": the range must be whole millimetres, 0 … 65535");
        }
        scan.range_mm[static_cast<std::size_t>(i)] = *range;
    }
    if (end != std::string_view::npos) {
        c.fail(kLaserScan, "more ranges than the beam count " + std::to_string(*count));
    }
    return scan;
}

/// The optional-sensor cells (version 2, and 3's laser scan) into `frame`; all empty in a
/// record without a frame.
void parse_optional_sensors(const CellReader& c, int version, bool frame_missing,
                            SensorFrame& frame) {
    const int last = version >= 3 ? kLaserScan : kBeacons;
    if (frame_missing) {
        for (int column = kGyro; column <= last; ++column) {
            c.require_empty(column, "must be empty in a record without a frame");
        }
        return;
    }
    frame.has_gyro = !c.empty(kGyro);
    if (frame.has_gyro) {
        frame.gyro_raw = c.get<std::int16_t>(kGyro);
    }
    int accel_cells = 0;
    for (int i = 0; i < 4; ++i) {
        accel_cells += c.empty(kAccelRightForward + i) ? 0 : 1;
    }
    if (accel_cells != 0 && accel_cells != 4) {
        for (int i = 0; i < 4; ++i) {
            if (c.empty(kAccelRightForward + i)) {
                c.fail(kAccelRightForward + i,
                       "the four accelerometer cells are either all empty or all set");
            }
        }
    }
    frame.has_accelerometers = accel_cells == 4;
    if (frame.has_accelerometers) {
        for (int i = 0; i < 4; ++i) {
            frame.accel_raw[static_cast<std::size_t>(i / 2)][static_cast<std::size_t>(i % 2)] =
                c.get<std::int16_t>(kAccelRightForward + i);
        }
    }
    frame.has_compass = !c.empty(kCompass);
    if (frame.has_compass) {
        frame.compass_deg = c.get<std::int16_t>(kCompass);
    }
    frame.has_beacon_scan = !c.empty(kBeacons);
    if (frame.has_beacon_scan) {
        frame.beacons = parse_beacons(c);
    }
    frame.has_laser_scan = version >= 3 && !c.empty(kLaserScan);
    if (frame.has_laser_scan) {
        frame.laser = parse_laser_scan(c);
    }
}

RunLogRecord parse_record(const LineReader& reader, std::string_view line, int version) {
    const std::vector<std::string_view> cells = split(line);
    const int columns = format::column_count(version);
    if (static_cast<int>(cells.size()) != columns) {
        reader.fail("a record has " + std::to_string(columns) + " cells, this line "
                    + std::to_string(cells.size()));
    }
    const CellReader c(reader, cells);
    RunLogRecord record;
    record.step = c.get<std::uint64_t>(kStep);
    record.frame_missing = c.flag(kFrameMissing);
    record.frame.time = c.get<double>(kTime);
    if (record.frame_missing) {
        for (int column = kSequence; column <= kValidRear; ++column) {
            if (column != kFrameMissing) {
                c.require_empty(column, "must be empty in a record without a frame");
            }
        }
    } else {
        record.frame.sequence = c.get<std::uint32_t>(kSequence);
        record.frame.encoder_counts = {c.get<std::int32_t>(kEncoderRight),
                                       c.get<std::int32_t>(kEncoderLeft)};
        record.frame.ir_adc = {c.get<std::uint16_t>(kAdcFront), c.get<std::uint16_t>(kAdcRear)};
        record.frame.ir_valid = {c.flag(kValidFront), c.flag(kValidRear)};
    }
    record.command = {c.get<double>(kV1), c.get<double>(kV2)};
    if (c.empty(kTruthX) && c.empty(kTruthY) && c.empty(kTruthTheta)) {
        record.truth.reset();
    } else {
        record.truth =
            Pose2{c.get<double>(kTruthX), c.get<double>(kTruthY), c.get<double>(kTruthTheta)};
    }
    for (int i = 0; i < 3; ++i) {
        record.estimate(i) = c.get<double>(kEstimate + i);
    }
    int column = kEstimate + 3;
    for (int row = 0; row < 3; ++row) {
        for (int col = row; col < 3; ++col) {
            record.covariance(row, col) = c.get<double>(column++);
            record.covariance(col, row) = record.covariance(row, col);
        }
    }
    if (version >= 2) {
        parse_optional_sensors(c, version, record.frame_missing, record.frame);
    }
    return record;
}

void read_records(LineReader& reader, RunLog& log) {
    while (!reader.at_end()) {
        const std::string_view line = reader.next();
        if (reader.last_cut_off()) {
            // Every complete line ends in a line break: this one was cut off mid-write.
            log.truncated = true;
            log.notes.push_back("line " + std::to_string(reader.line())
                                + " was cut off (the recording was stopped mid-write): "
                                  "dropped; the "
                                + std::to_string(log.records.size())
                                + " complete records before it are kept");
            return;
        }
        const std::string end_prefix = std::string(format::kEnd) + ": ";
        if (line.substr(0, end_prefix.size()) == end_prefix) {
            const std::string expected = std::to_string(log.records.size()) + " records";
            if (rest_after(line, end_prefix) != expected) {
                reader.fail("the end line counts \"" + std::string(rest_after(line, end_prefix))
                            + "\" but the log holds " + expected);
            }
            if (!reader.at_end()) {
                reader.next();
                reader.fail("text after the end line");
            }
            log.ended = true;
            return;
        }
        RunLogRecord record = parse_record(reader, line, log.header.version);
        if (!log.records.empty() && record.step != log.records.back().step + 1) {
            reader.fail("steps must follow each other (the previous was "
                            + std::to_string(log.records.back().step) + ")",
                        "step", std::to_string(record.step));
        }
        log.records.push_back(record);
    }
    log.notes.push_back(
        "the log has no end line: the recording stopped early (killed or "
        "crashed); its "
        + std::to_string(log.records.size()) + " records are kept");
}

/// A log whose first record is not the loop's first step cannot be replayed exactly: the
/// steps before it (and their encoder reference) are missing.
void note_late_start(RunLog& log) {
    if (!log.records.empty() && log.records.front().step != 1) {
        log.notes.push_back("the log starts at step " + std::to_string(log.records.front().step)
                            + ", not 1: the steps before it were not recorded, so a replay "
                              "cannot reproduce the run exactly");
    }
}

}  // namespace

const char* run_log_columns() {
    return format::kColumnList.data();
}

RunLog load_run_log(const std::filesystem::path& path) {
    return parse_run_log(read_text_file(path, kRunLogFile), path.string());
}

RunLog parse_run_log(std::string text, const std::string& source) {
    LineReader reader(std::move(text), source);

    RunLog log;
    read_version(reader, log.header);
    log.header.program = header_value(reader, format::kProgram);
    log.header.title = header_value(reader, format::kTitle);
    const std::string seed = header_value(reader, format::kSeed);
    const int seed_line = reader.line();
    const auto seed_value = format::parse<std::uint64_t>(seed);
    if (!seed_value) {
        reader.fail("not a valid seed", "seed", seed);
    }
    log.header.seed = *seed_value;
    log.header.world = header_value(reader, format::kWorld);
    log.header.link = header_value(reader, format::kLink);
    read_config(reader, log);
    const std::string columns = header_value(reader, format::kColumns);
    const std::string_view expected_columns = format::column_list(log.header.version);
    if (columns != expected_columns) {
        reader.fail("unexpected columns for format version " + std::to_string(log.header.version)
                        + " (expected " + std::string(expected_columns) + ")",
                    "columns", columns);
    }
    if (log.config.seed != log.header.seed) {
        throw InputError(
            {{reader.source(), seed_line, "seed", seed,
              "differs from the configuration's seed (" + std::to_string(log.config.seed) + ")"}});
    }
    read_records(reader, log);
    note_late_start(log);
    return log;
}

}  // namespace legofeup::lessons
