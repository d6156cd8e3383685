#pragma once
// Run logs: every control step of a run as the loop saw it — the raw sensor frame (or the
// fact that none came), the wheel command sent, the ground truth when known — behind a
// header with the full configuration and the seed. Written as the run goes and flushed at
// least every half second, so a crash or a kill loses at most the last half second; read
// back to replay the same raw readings through a loop with other settings (refilter.hpp).
// The format (versioned text lines) is documented in docs/recording.md.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "legofeup/core/motion.hpp"
#include "legofeup/core/sensor_frame.hpp"
#include "legofeup/core/state.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// First line of every run log: "legofeup-run-log <version>".
inline constexpr const char* kRunLogFormat = "legofeup-run-log";
/// The version this program writes and the newest it reads (it reads every older one too).
/// Version 2 added the optional sensors of SensorFrame (gyro, accelerometers, compass,
/// beacon scan); a version-1 log reads as frames without them. Version 3 added the laser
/// scan; a version-1 or -2 log reads as frames without one.
inline constexpr int kRunLogVersion = 3;

/// What the header says about the run, besides its configuration.
struct RunLogHeader {
    int version = kRunLogVersion;
    std::string program;  ///< e.g. "legofeup-cli 0.4.0"
    std::string title;    ///< experiment or free text, e.g. "experiment f"
    std::uint64_t seed = 1;
    std::string world;        ///< the world's name
    std::string link;         ///< "lockstep", "udp://…", "bt:…", … (free text, may be empty)
    std::string config_toml;  ///< the configuration exactly as recorded (config_to_toml)
};

/// One control step as recorded.
struct RunLogRecord {
    std::uint64_t step = 0;  ///< the loop's step counter (1 for the first frame)
    /// No frame came this period: the loop predicted without one (step_without_frame) at
    /// `frame.time`, the time the frame was due; the rest of `frame` is meaningless.
    bool frame_missing = false;
    SensorFrame frame;           ///< the raw frame exactly as the loop received it
    WheelSpeeds command;         ///< (V1, V2) the loop sent for the coming period
    std::optional<Pose2> truth;  ///< where the robot really was; none for a real robot
    /// What the recording loop estimated after this step (X̂ and P), to check that a replay
    /// with the recorded configuration reproduces the run exactly.
    StateVector estimate = StateVector::Zero();
    StateCovariance covariance = StateCovariance::Zero();
};

struct RunLog {
    RunLogHeader header;
    RunConfig config;  ///< header.config_toml read back over the defaults
    std::vector<RunLogRecord> records;
    /// The run ended normally (the writer was closed and wrote its end line).
    bool ended = false;
    /// The last line was cut off (the recording program was killed mid-write); it was
    /// dropped and the complete records before it kept.
    bool truncated = false;
    /// Human-readable remarks on the above ("last line 1234 cut off: dropped"), empty if none.
    std::vector<std::string> notes;
};

/// Thrown when the log cannot be written (disk full, file removed, …): a recording that
/// silently stops is worse than a run that stops.
class RunLogWriteError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Records a run to a file as it goes. Plug it into any run as its RunObserver (lockstep,
/// UDP, NXT, the GUI). The file is flushed to the operating system whenever
/// `flush_interval` of wall-clock time has passed since the last flush (checked at every
/// step), and on close() / destruction.
class RunLogWriter final : public RunObserver {
  public:
    using Clock = std::function<std::chrono::steady_clock::time_point()>;
    static constexpr std::chrono::milliseconds kFlushInterval{500};

    struct Options {
        std::string program = "legofeup";  ///< program name and version for the header
        std::string link;                  ///< which link the run uses (free text)
        std::chrono::steady_clock::duration flush_interval = kFlushInterval;
        Clock clock = [] { return std::chrono::steady_clock::now(); };  ///< injectable for tests
    };

    /// Creates (truncates) `path` and writes the header: format and version, program, the
    /// full configuration of `run` as TOML (config_to_toml), the seed and the world's name.
    /// Throws RunLogWriteError if the file cannot be created or written.
    RunLogWriter(const std::filesystem::path& path, const ResolvedRun& run,
                 const std::string& title, Options options);
    RunLogWriter(const std::filesystem::path& path, const ResolvedRun& run,
                 const std::string& title);
    /// Closes the log (end line and flush); errors are swallowed here — call close() to see
    /// them. Destroyed while an exception unwinds (the run failed), it only flushes: no end
    /// line, so the log shows that the run did not end normally.
    ~RunLogWriter() override;
    RunLogWriter(const RunLogWriter&) = delete;
    RunLogWriter& operator=(const RunLogWriter&) = delete;

    /// Appends one record. A truth that is not known (UnknownTruth's NaN pose) is recorded
    /// as none. Throws RunLogWriteError on a write error.
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override;

    /// Writes the end line and flushes. Idempotent. Throws RunLogWriteError on a write error.
    void close();

    std::uint64_t records_written() const { return records_; }
    const std::filesystem::path& path() const { return path_; }

  private:
    void check(const char* what);
    void flush_if_due();

    std::filesystem::path path_;
    std::ofstream out_;
    Options options_;
    std::chrono::steady_clock::time_point last_flush_;
    std::uint64_t records_ = 0;
    bool closed_ = false;
};

/// Reads a run log. Throws InputError with file:line and the reason for a malformed line,
/// a missing or foreign first line, or a version newer than kRunLogVersion (naming it). A
/// last line cut off mid-write (no final newline) is tolerated: see RunLog::truncated.
RunLog load_run_log(const std::filesystem::path& path);

/// Parses a run log's text; `source` names it in messages (its directory anchors the
/// configuration block's relative paths, as the file's does).
RunLog parse_run_log(std::string text, const std::string& source);

/// The column names of a record line of the version written, comma-separated (documented
/// in docs/recording.md).
const char* run_log_columns();

}  // namespace legofeup::lessons
