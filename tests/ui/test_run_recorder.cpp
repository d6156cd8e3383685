// The GUI's recording (trace.csv and run.log) is written on the recorder's thread: the files
// are the CLI's, byte for byte (trace) and record for record (log); a caller whose disk is
// stuck is never kept waiting; a file that cannot be written is a typed problem, not a
// crash, and the other file goes on.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../lessons/scratch_dir_test_support.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/ui/session/run_recorder.hpp"
#include "support/lockstep_history.hpp"

using namespace legofeup;
using namespace legofeup::ui;

namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Experiment f, one lap: the configuration and every step's sample (run once).
struct Lap {
    lessons::ResolvedRun run;
    std::vector<RunSample> samples;
};
const Lap& lap() {
    static const Lap once = [] {
        lessons::RunConfig config = lessons::find_experiment("f")->config;
        config.laps = 1;
        return Lap{lessons::resolve(config), ui::testing::lockstep_run("f", 1).samples};
    }();
    return once;
}

/// The trace the CLI writes for the lap's samples.
std::string cli_trace() {
    std::ostringstream cli;
    lessons::TraceCsvWriter writer(cli, lap().run.loop);
    for (const RunSample& sample : lap().samples) {
        writer.on_step(sample.snapshot, *sample.truth);
    }
    return cli.str();
}

/// Hands the lap's samples to `recorder` in batches of three, as a session's frames do.
void append_lap(RunRecorder& recorder) {
    const std::vector<RunSample>& samples = lap().samples;
    for (std::size_t first = 0; first < samples.size(); first += 3) {
        const std::size_t end = std::min(first + 3, samples.size());
        recorder.append({samples.begin() + static_cast<std::ptrdiff_t>(first),
                         samples.begin() + static_cast<std::ptrdiff_t>(end)});
    }
}

/// Records the lap into `trace` and `run_log` (none if empty) and returns the problems.
std::vector<RunRecorder::Problem> record_lap(const fs::path& trace, const fs::path& run_log) {
    RunRecorder recorder({trace, run_log, "one lap", {}}, lap().run);
    append_lap(recorder);
    recorder.finish();
    std::vector<RunRecorder::Problem> problems = recorder.take_problems();
    EXPECT_TRUE(recorder.take_problems().empty());  // taken once
    return problems;
}

}  // namespace

TEST(RunRecorder, WritesTheCliTraceAndACompleteRunLog) {
    const fs::path scratch = lessons::scratch_testing::temp_dir();
    ASSERT_GT(lap().samples.size(), 1000U);
    RunRecorder recorder({scratch / "trace.csv", scratch / "run.log", "one lap", {}}, lap().run);
    append_lap(recorder);
    recorder.finish();
    recorder.finish();               // twice is harmless
    recorder.append(lap().samples);  // after finish: dropped, not written
    EXPECT_TRUE(recorder.take_problems().empty());

    EXPECT_EQ(read_all(scratch / "trace.csv"), cli_trace());
    const lessons::RunLog log = lessons::load_run_log(scratch / "run.log");
    EXPECT_TRUE(log.ended);  // finish() wrote the end line
    EXPECT_FALSE(log.truncated);
    ASSERT_EQ(log.records.size(), lap().samples.size());
    for (std::size_t i = 0; i < log.records.size(); ++i) {
        ASSERT_EQ(log.records[i].estimate, lap().samples[i].snapshot.estimate) << i;
    }
}

// The trace is a FIFO nobody reads yet: opening it blocks the recorder's thread, as a stuck
// network disk would. Appending must still return at once (were it written on the caller's
// thread, this test would never get to open the reader and would hang until ctest's
// timeout); once a reader comes, everything appended arrives, in order.
TEST(RunRecorder, TheCallerNeverWaitsForTheDisk) {
    const fs::path scratch = lessons::scratch_testing::temp_dir();
    const fs::path fifo = scratch / "trace.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    RunRecorder recorder({fifo, {}, "one lap", {}}, lap().run);  // the trace alone
    append_lap(recorder);  // returns while the thread is stuck in open()

    std::string received;
    std::thread reader([&] { received = read_all(fifo); });
    recorder.finish();  // the thread writes everything, closes the FIFO: the reader sees EOF
    reader.join();
    EXPECT_EQ(received, cli_trace());
    EXPECT_TRUE(recorder.take_problems().empty());
}

TEST(RunRecorder, FilesThatCannotBeCreatedAreProblemsAndTheOtherFileGoesOn) {
    const fs::path scratch = lessons::scratch_testing::temp_dir();
    using Kind = RunRecorder::Problem::Kind;
    const fs::path lost_trace = scratch / "no-such-folder" / "trace.csv";
    auto problems = record_lap(lost_trace, scratch / "run.log");
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].kind, Kind::TraceNotCreated);
    EXPECT_EQ(problems[0].detail, lost_trace.string());
    EXPECT_EQ(lessons::load_run_log(scratch / "run.log").records.size(), lap().samples.size());

    problems = record_lap(scratch / "trace.csv", scratch / "no-such-folder" / "run.log");
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].kind, Kind::RunLogNotCreated);
    EXPECT_NE(problems[0].detail.find("no-such-folder"), std::string::npos) << problems[0].detail;
    EXPECT_EQ(read_all(scratch / "trace.csv"), cli_trace());
}

// /dev/full accepts the open and fails every write: the trace stops, said once.
TEST(RunRecorder, AFullDiskStopsTheTraceOnceAndTheRunLogGoesOn) {
    const fs::path scratch = lessons::scratch_testing::temp_dir();
    const auto problems = record_lap("/dev/full", scratch / "run.log");
    ASSERT_EQ(problems.size(), 1U);
    EXPECT_EQ(problems[0].kind, RunRecorder::Problem::Kind::TraceStopped);
    const lessons::RunLog log = lessons::load_run_log(scratch / "run.log");
    EXPECT_TRUE(log.ended);
    EXPECT_EQ(log.records.size(), lap().samples.size());
}
