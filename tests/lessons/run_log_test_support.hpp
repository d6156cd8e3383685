// What the run-log tests share: a per-process scratch directory, whole-file and line/cell
// text helpers, recording a list of frames through RunLogWriter, and the load error's text.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "csv_test_support.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons::run_log_testing {

namespace fs = std::filesystem;

// Per process: ctest runs each test in its own process, in parallel, and several of them
// write files of the same name.
inline fs::path temp_file(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("legofeup_run_log_tests_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

inline std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    // Through rdbuf, not istreambuf_iterator: GCC 12 at -O3 reports a null dereference
    // inside the iterator's inlined streambuf calls (a false positive).
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_text(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

inline std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += line + '\n';
    }
    return text;
}

using csv_testing::cells_of;

inline std::string joined_cells(const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        line += (i == 0 ? "" : ",") + cells[i];
    }
    return line;
}

/// The 1-based line number of the first record: the line after "columns: …".
inline int first_record_line(const std::vector<std::string>& lines) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].rfind("columns: ", 0) == 0) {
            return static_cast<int>(i) + 1;
        }
    }
    ADD_FAILURE() << "no columns line";
    return 0;
}

/// What loading the log throws, or "(no error)".
inline std::string message_of(const fs::path& path) {
    try {
        load_run_log(path);
    } catch (const InputError& error) {
        return error.what();
    }
    return "(no error)";
}

/// Records `frames` through the writer, one step each (`step` gives every step's other
/// fields), then `missing` as a step without a frame, into temp_file(name). The
/// configuration block is then emptied ("config: 0 lines"): tests of the records alone.
inline fs::path record_frames(const std::string& name, const std::string& description,
                              const std::vector<SensorFrame>& frames, LoopSnapshot step,
                              LoopSnapshot missing) {
    const fs::path path = temp_file(name);
    {
        const ResolvedRun run{};  // unresolved defaults: only the header is taken from it
        RunLogWriter writer(path, run, description);
        std::uint64_t count = 0;
        for (const SensorFrame& frame : frames) {
            step.step = ++count;
            step.time = frame.time;
            step.frame = frame;
            writer.on_step(step, GroundTruth{});
        }
        missing.step = ++count;
        missing.frame_missing = true;
        writer.on_step(missing, GroundTruth{});
        writer.close();
    }
    std::vector<std::string> kept;
    const std::vector<std::string> lines = lines_of(read_text(path));
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].rfind("config: ", 0) == 0) {
            kept.push_back("config: 0 lines");
            i += static_cast<std::size_t>(std::stoi(lines[i].substr(8)));
        } else {
            kept.push_back(lines[i]);
        }
    }
    write_text(path, joined(kept));
    return path;
}

/// Keeps what the live loop computed at every step, to compare against the log and replays.
class SnapshotKeeper final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        snapshots.push_back(snapshot);
        truths.push_back(truth.pose);
    }
    std::vector<LoopSnapshot> snapshots;
    std::vector<Pose2> truths;
};

/// Passes every step to two observers.
class Both final : public RunObserver {
  public:
    Both(RunObserver& a, RunObserver& b) : a_(a), b_(b) {}
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        a_.on_step(snapshot, truth);
        b_.on_step(snapshot, truth);
    }

  private:
    RunObserver& a_;
    RunObserver& b_;
};

}  // namespace legofeup::lessons::run_log_testing
