// Run logs and re-filtering: a recorded run reads back field for field, replaying it with
// the recorded configuration repeats every estimate bit for bit (also with lost frames and
// a robot profile), a new tuning changes the estimates on the identical frames, a log cut
// off mid-write still reads, bad lines are reported at file:line, and the writer flushes on
// its clock.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"
#include "run_log_test_support.hpp"

namespace legofeup::lessons {
namespace {

using namespace run_log_testing;

/// Experiment f, one lap: walls, updates and rejections all happen.
ResolvedRun experiment_f(std::uint64_t seed = 5) {
    RunConfig config = find_experiment("f")->config;
    config.seed = seed;
    config.laps = 1;
    return resolve(config);
}

/// Experiment f's settings on a short drive past the first wall (about 300 steps): quick
/// under the sanitizers, with wall updates all along.
ResolvedRun short_drive(std::uint64_t seed = 5) {
    RunConfig config = find_experiment("f")->config;
    config.seed = seed;
    config.routine.kind = RoutineSpec::Kind::Line;
    config.routine.line_from = {-1.0, -1.0};
    config.routine.line_to = {0.2, -1.0};
    config.duration = 20.0;
    return resolve(config);
}

struct RecordedRun {
    fs::path path;
    RunResult result;
    SnapshotKeeper live;
};

RecordedRun record_lockstep(const ResolvedRun& run, const std::string& name) {
    RecordedRun recorded;
    recorded.path = temp_file(name);
    RunLogWriter::Options options;
    options.program = "test-program 1.2.3";
    options.link = "lockstep";
    RunLogWriter writer(recorded.path, run, "experiment f, test", options);
    Both both(writer, recorded.live);
    recorded.result = run_lockstep(run, &both);
    writer.close();
    return recorded;
}

/// A lockstep link that loses every 9th frame (the runner times out and predicts without
/// it), so a log holds steps without a frame.
class LossyLink final : public RobotLink {
  public:
    explicit LossyLink(sim::Simulator& simulator) : inner_(simulator) {}
    std::optional<SensorFrame> next_frame() override {
        std::optional<SensorFrame> frame = inner_.next_frame();
        return ++calls_ % 9 == 0 ? std::nullopt : frame;
    }
    void send_command(const WheelSpeeds& command) override { inner_.send_command(command); }

  private:
    sim::LockstepLink inner_;
    int calls_ = 0;
};

std::string with_line(const std::string& text, int number, const std::string& replacement) {
    std::istringstream in(text);
    std::string out;
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
        out += (++line_number == number ? replacement : line) + "\n";
    }
    return out;
}

int line_starting(const std::string& text, const std::string& prefix) {
    std::istringstream in(text);
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
        ++line_number;
        if (line.rfind(prefix, 0) == 0) {
            return line_number;
        }
    }
    return 0;
}

/// A recorded short drive, shared by the tests that only read it.
const RecordedRun& short_recording() {
    static const RecordedRun recorded = record_lockstep(short_drive(), "short.log");
    return recorded;
}

TEST(RunLog, RoundTripHoldsTheHeaderAndEveryFrameCommandAndTruth) {
    const ResolvedRun run = experiment_f();
    const RecordedRun recorded = record_lockstep(run, "lap.log");
    const std::string text = read_text(recorded.path);
    EXPECT_EQ(text.rfind("legofeup-run-log 3\n", 0), 0U);

    const RunLog log = load_run_log(recorded.path);
    EXPECT_EQ(log.header.version, 3);
    EXPECT_EQ(log.header.program, "test-program 1.2.3");
    EXPECT_EQ(log.header.title, "experiment f, test");
    EXPECT_EQ(log.header.seed, 5U);
    EXPECT_EQ(log.header.world, run.world.name);
    EXPECT_EQ(log.header.link, "lockstep");
    EXPECT_TRUE(log.ended);
    EXPECT_FALSE(log.truncated);
    EXPECT_TRUE(log.notes.empty());
    // The configuration reads back to the same settings.
    EXPECT_EQ(config_to_toml(log.config, "x"), config_to_toml(run.config, "x"));

    const std::vector<LoopSnapshot>& live = recorded.live.snapshots;
    ASSERT_EQ(log.records.size(), live.size());
    ASSERT_EQ(log.records.size(), recorded.result.metrics.steps);
    for (std::size_t i = 0; i < live.size(); ++i) {
        const RunLogRecord& r = log.records[i];
        const LoopSnapshot& s = live[i];
        ASSERT_EQ(r.step, s.step);
        ASSERT_FALSE(r.frame_missing);
        ASSERT_EQ(r.frame.time, s.frame.time);
        ASSERT_EQ(r.frame.sequence, s.frame.sequence);
        ASSERT_EQ(r.frame.encoder_counts, s.frame.encoder_counts);
        ASSERT_EQ(r.frame.ir_adc, s.frame.ir_adc);
        ASSERT_EQ(r.frame.ir_valid, s.frame.ir_valid);
        ASSERT_EQ(r.command.right, s.wheels.right);
        ASSERT_EQ(r.command.left, s.wheels.left);
        ASSERT_TRUE(r.truth.has_value());
        ASSERT_EQ(r.truth->x, recorded.live.truths[i].x);
        ASSERT_EQ(r.truth->theta, recorded.live.truths[i].theta);
        ASSERT_EQ(r.estimate, s.estimate);
        ASSERT_EQ(r.covariance, s.covariance);
    }
    // The frames really carry the readings (not default values).
    EXPECT_NE(log.records.back().frame.encoder_counts[0], 0);
    EXPECT_NE(log.records[10].frame.ir_adc[0], 0);
}

TEST(RunLog, ReplayingALapRepeatsEveryStepOfTheLiveLoopBitForBit) {
    const RecordedRun recorded = record_lockstep(experiment_f(11), "lap_replay.log");
    const RunLog log = load_run_log(recorded.path);
    LegoFeupLoop loop(resolve(log.config).loop);
    std::size_t index = 0;
    std::uint64_t updates = 0;
    replay_run_log(log, loop, [&](const RunLogRecord& record, const LoopSnapshot& replayed) {
        const LoopSnapshot& live = recorded.live.snapshots.at(index++);
        ASSERT_EQ(replayed.step, live.step);
        ASSERT_EQ(replayed.estimate, live.estimate) << "step " << live.step;
        ASSERT_EQ(replayed.covariance, live.covariance) << "step " << live.step;
        ASSERT_EQ(replayed.update.status, live.update.status) << "step " << live.step;
        // Same estimates, so the same routine output: the recorded command again.
        ASSERT_EQ(replayed.wheels.right, record.command.right) << "step " << live.step;
        ASSERT_EQ(replayed.wheels.left, record.command.left) << "step " << live.step;
        updates += replayed.update.status == StepStatus::Applied ? 1U : 0U;
    });
    EXPECT_EQ(index, recorded.live.snapshots.size());
    EXPECT_EQ(updates, recorded.result.metrics.updates_applied);
    EXPECT_GT(updates, 50U);
}

TEST(RunLog, ReplayWithTheRecordedConfigurationReproducesEveryEstimateExactly) {
    const RecordedRun& recorded = short_recording();
    const RunLog log = load_run_log(recorded.path);
    const RefilterResult result = refilter(log, log.config);

    EXPECT_TRUE(result.reproduces_recording());
    EXPECT_EQ(result.old_replay_deviation, 0.0);
    const std::vector<LoopSnapshot>& live = recorded.live.snapshots;
    ASSERT_EQ(result.steps.size(), live.size());
    for (std::size_t i = 0; i < live.size(); ++i) {
        // Against the live run itself, not only against the numbers in the log.
        ASSERT_EQ(result.steps[i].old_estimate, live[i].estimate) << "step " << i;
        ASSERT_EQ(result.steps[i].old_covariance, live[i].covariance) << "step " << i;
        ASSERT_EQ(result.steps[i].new_estimate, live[i].estimate) << "step " << i;
        ASSERT_EQ(result.steps[i].time, live[i].time);
    }
    ASSERT_TRUE(result.old_metrics.truth.has_value());
    ASSERT_TRUE(result.new_metrics.truth.has_value());
    const RunMetrics& live_metrics = recorded.result.metrics;
    ASSERT_TRUE(live_metrics.truth.has_value());
    const TruthMetrics& live_truth = *live_metrics.truth;
    EXPECT_EQ(result.old_metrics.truth->rms_position_error, live_truth.rms_position_error);
    EXPECT_EQ(result.old_metrics.truth->final_position_error, live_truth.final_position_error);
    EXPECT_EQ(result.old_metrics.updates_applied, live_metrics.updates_applied);
    EXPECT_EQ(result.old_metrics.truth->mean_nees, live_truth.mean_nees);
    EXPECT_EQ(result.new_metrics.truth->mean_nees, live_truth.mean_nees);
}

// The GUI's progress bar and cancel: told after every step of both replays, in order, up to
// twice the records; a false answer stops it there, with nothing more replayed.
TEST(RunLog, RefilterReportsItsProgressAndStopsWhenTold) {
    const RecordedRun& recorded = short_recording();
    const RunLog log = load_run_log(recorded.path);
    const std::size_t total = 2 * log.records.size();
    std::size_t calls = 0;
    const RefilterResult result = refilter(log, log.config, [&](std::size_t done, std::size_t of) {
        EXPECT_EQ(done, calls + 1);
        EXPECT_EQ(of, total);
        ++calls;
        return true;
    });
    EXPECT_EQ(calls, total);
    EXPECT_TRUE(result.reproduces_recording());  // watched, the same replay

    const std::size_t stop_at = log.records.size() + 7;  // in the second replay
    calls = 0;
    EXPECT_THROW(refilter(log, log.config,
                          [&](std::size_t done, std::size_t) {
                              ++calls;
                              return done < stop_at;
                          }),
                 RefilterCancelled);
    EXPECT_EQ(calls, stop_at);
}

TEST(RunLog, RefilterWithOtherNoiseChangesTheEstimatesOnTheIdenticalFrames) {
    const RecordedRun& recorded = short_recording();
    const RunLog log = load_run_log(recorded.path);
    RunConfig tuned = log.config;
    tuned.filter.r11 *= 100.0;  // trust the IR sensors far less
    tuned.filter.r22 *= 100.0;
    tuned.filter.q11 *= 10.0;
    const RefilterResult result = refilter(log, tuned);

    EXPECT_TRUE(result.reproduces_recording());
    double largest_change = 0.0;
    double largest_variance_ratio = 0.0;
    for (const RefilterStep& step : result.steps) {
        largest_change =
            std::max(largest_change, (step.new_estimate - step.old_estimate).head<2>().norm());
        largest_variance_ratio =
            std::max(largest_variance_ratio, step.new_covariance(0, 0) / step.old_covariance(0, 0));
    }
    EXPECT_GT(largest_change, 1e-3);         // metres: the estimate moved
    EXPECT_GT(largest_variance_ratio, 1.5);  // and trusts itself less
    ASSERT_TRUE(result.new_metrics.truth.has_value());
    ASSERT_TRUE(result.old_metrics.truth.has_value());
    EXPECT_NE(result.new_metrics.truth->rms_position_error,
              result.old_metrics.truth->rms_position_error);

    // The new loop got exactly the recorded frames (not a new simulation).
    LegoFeupLoop loop(resolve(tuned).loop);
    std::size_t index = 0;
    replay_run_log(log, loop, [&](const RunLogRecord& record, const LoopSnapshot& snapshot) {
        const LoopSnapshot& live = recorded.live.snapshots[index++];
        EXPECT_EQ(snapshot.frame.encoder_counts, live.frame.encoder_counts);
        EXPECT_EQ(snapshot.frame.ir_adc, live.frame.ir_adc);
        EXPECT_EQ(snapshot.frame.time, record.frame.time);
    });
    EXPECT_EQ(index, recorded.live.snapshots.size());
}

TEST(RunLog, StepsWithoutAFrameAreRecordedAndReplayedExactly) {
    const ResolvedRun run = short_drive(8);
    sim::WorldSpec world = run.world;
    world.start = run.true_start;
    sim::Simulator simulator(world, run.robot, run.config.simulator, run.config.seed);
    LossyLink link(simulator);
    UnknownTruth truth;  // as on a real robot: no truth is recorded
    const fs::path path = temp_file("lossy.log");
    SnapshotKeeper live;
    RunResult result;
    {
        RunLogWriter writer(path, run, "lossy");
        Both both(writer, live);
        result = run_with_link(run, link, truth, &both);
    }  // the destructor closes the log
    ASSERT_GT(result.frames_missing, 10U);

    const RunLog log = load_run_log(path);
    EXPECT_TRUE(log.ended);
    std::uint64_t missing = 0;
    for (std::size_t i = 0; i < log.records.size(); ++i) {
        if (log.records[i].frame_missing) {
            ++missing;
            EXPECT_EQ(log.records[i].frame.time, live.snapshots[i].time);  // the due time
        }
    }
    EXPECT_EQ(missing, result.frames_missing);
    EXPECT_FALSE(log.records.back().truth.has_value());
    const RefilterResult replay = refilter(log, log.config);
    EXPECT_EQ(replay.old_replay_deviation, 0.0);
    // No truth, no errors; the counts all the same, as the live run's.
    EXPECT_FALSE(result.metrics.truth.has_value());
    EXPECT_FALSE(replay.old_metrics.truth.has_value());
    EXPECT_EQ(result.metrics.steps, log.records.size());
    EXPECT_EQ(result.steps_without_truth, log.records.size());
    EXPECT_EQ(replay.old_metrics.steps, result.metrics.steps);
    EXPECT_GT(result.metrics.updates_applied, 0U);
    EXPECT_EQ(replay.old_metrics.updates_applied, result.metrics.updates_applied);
    EXPECT_EQ(replay.old_metrics.updates_rejected, result.metrics.updates_rejected);
    ASSERT_EQ(replay.steps.size(), live.snapshots.size());
    for (std::size_t i = 0; i < replay.steps.size(); ++i) {
        ASSERT_EQ(replay.steps[i].old_estimate, live.snapshots[i].estimate) << "step " << i;
        ASSERT_EQ(replay.steps[i].frame_missing, live.snapshots[i].frame_missing);
    }
}

TEST(RunLog, ALoopChangedByARobotProfileIsRecordedAsRun) {
    ResolvedRun run = short_drive(4);
    // What --profile does after resolve(): the loop's odometry and IR curve change.
    run.loop.odometry.codo_right *= 1.01;
    run.loop.odometry.wheel_base = 0.125;
    run.loop.ir_curve.c_m *= 1.02;
    const RecordedRun recorded = record_lockstep(run, "profile.log");
    const RunLog log = load_run_log(recorded.path);
    EXPECT_EQ(log.config.robot.codo_right, run.loop.odometry.codo_right);
    EXPECT_EQ(log.config.robot.wheel_base, 0.125);
    const RefilterResult replay = refilter(log, log.config);
    EXPECT_EQ(replay.old_replay_deviation, 0.0);
}

TEST(RunLog, ALastLineCutOffMidWriteIsDroppedAndTheRestKept) {
    const RecordedRun& recorded = short_recording();
    const std::string text = read_text(recorded.path);
    const std::size_t end_line = text.rfind("end: ");
    // Killed in the middle of the last record: its line has no line break.
    const std::size_t last_record = text.rfind('\n', end_line - 2) + 1;
    const std::string cut = text.substr(0, last_record + 37);
    const fs::path path = temp_file("cut.log");
    write_text(path, cut);

    const RunLog log = load_run_log(path);
    EXPECT_TRUE(log.truncated);
    EXPECT_FALSE(log.ended);
    EXPECT_EQ(log.records.size(), recorded.live.snapshots.size() - 1);
    ASSERT_FALSE(log.notes.empty());
    EXPECT_NE(log.notes.front().find("cut off"), std::string::npos);
    EXPECT_EQ(refilter(log, log.config).old_replay_deviation, 0.0);

    // Killed between two lines: nothing cut, but no end line either.
    write_text(path, text.substr(0, last_record));
    const RunLog stopped = load_run_log(path);
    EXPECT_FALSE(stopped.truncated);
    EXPECT_FALSE(stopped.ended);
    EXPECT_EQ(stopped.records.size(), recorded.live.snapshots.size() - 1);
    EXPECT_FALSE(stopped.notes.empty());
}

TEST(RunLog, ALogWithoutItsFirstStepsSaysItCannotReproduceTheRun) {
    const std::string text = read_text(short_recording().path);
    const int first_record = line_starting(text, "columns: ") + 1;
    const fs::path path = temp_file("late.log");
    std::string without_first = text;
    const std::size_t start = text.find("\n1,") + 1;  // the record of step 1
    without_first.erase(start, text.find('\n', start) + 1 - start);
    ASSERT_EQ(line_starting(without_first, "columns: ") + 1, first_record);
    without_first.erase(without_first.rfind("end: "));  // (its count would be one too many)
    write_text(path, without_first);
    const RunLog log = load_run_log(path);
    ASSERT_EQ(log.records.front().step, 2U);
    ASSERT_EQ(log.notes.size(), 2U);  // no end line; starts late
    EXPECT_NE(log.notes.back().find("starts at step 2"), std::string::npos);
    EXPECT_GT(refilter(log, log.config).old_replay_deviation, 0.0);
}

TEST(RunLog, AMalformedLineIsReportedAtFileLineWithTheColumn) {
    const RecordedRun& recorded = short_recording();
    const std::string text = read_text(recorded.path);
    const int columns_line = line_starting(text, "columns: ");
    ASSERT_GT(columns_line, 10);
    const fs::path path = temp_file("bad.log");

    // A record with a word where an encoder count belongs (not the last line: no tolerance).
    const int bad = columns_line + 5;
    std::istringstream in(text);
    std::string line;
    for (int i = 0; i < bad; ++i) {
        std::getline(in, line);
    }
    // Replace the fifth cell, keeping trailing empty cells (absent optional sensors).
    std::size_t start = 0;
    for (int comma = 0; comma < 4; ++comma) {
        start = line.find(',', start) + 1;
    }
    const std::size_t end = line.find(',', start);
    const std::string broken = line.substr(0, start) + "lots" + line.substr(end);
    write_text(path, with_line(text, bad, broken));
    EXPECT_EQ(message_of(path), path.string() + ":" + std::to_string(bad)
                                    + ": encoder_right = lots: not a valid number");

    // Too few cells.
    write_text(path, with_line(text, bad, "1,2,3"));
    EXPECT_NE(message_of(path).find(path.string() + ":" + std::to_string(bad)
                                    + ": a record has 32 cells"),
              std::string::npos);

    // A bad setting in the configuration block is reported at its line in the log.
    const int q11 = line_starting(text, "q11 = ");
    ASSERT_GT(q11, 0);
    write_text(path, with_line(text, q11, "q11 = \"lots\""));
    EXPECT_NE(message_of(path).find(path.string() + ":" + std::to_string(q11) + ":"),
              std::string::npos)
        << message_of(path);

    // A step out of order.
    const std::string duplicate = with_line(text, bad + 1, line);  // step repeats
    write_text(path, duplicate);
    EXPECT_NE(message_of(path).find(":" + std::to_string(bad + 1) + ": step = "), std::string::npos)
        << message_of(path);
}

TEST(RunLog, AnUnknownFormatOrNewerVersionIsRefusedByName) {
    const RecordedRun& recorded = short_recording();
    const std::string text = read_text(recorded.path);
    const fs::path path = temp_file("future.log");
    write_text(path, with_line(text, 1, "legofeup-run-log 4"));
    EXPECT_EQ(message_of(path), path.string()
                                    + ":1: version = 4: run log format version 4 is newer than "
                                      "this program reads (up to 3): update LegoFeup Lab");
    write_text(path, "t,x_true,y_true\n1,2,3\n");
    EXPECT_NE(message_of(path).find(":1: not a LegoFeup run log"), std::string::npos);
    write_text(path, text.substr(0, text.find("config: ")));
    EXPECT_NE(message_of(path).find("ends inside its header"), std::string::npos);
    EXPECT_NE(message_of(temp_file("no-such.log")).find("cannot open"), std::string::npos);
}

TEST(RunLog, TheWriterFlushesEveryHalfSecondOfItsClockAndOnClose) {
    const ResolvedRun run = short_drive();
    const fs::path path = temp_file("flush.log");
    auto now = std::chrono::steady_clock::time_point{};
    RunLogWriter::Options options;
    options.clock = [&now] { return now; };
    RunLogWriter writer(path, run, "flush", options);
    const auto header_size = fs::file_size(path);
    EXPECT_GT(header_size, 1000U);  // the header is on disk at once

    LoopSnapshot snapshot;
    GroundTruth truth;
    for (int i = 1; i <= 4; ++i) {  // 0.1 … 0.4 s: buffered
        now += std::chrono::milliseconds(100);
        snapshot.step = static_cast<std::uint64_t>(i);
        writer.on_step(snapshot, truth);
    }
    EXPECT_EQ(fs::file_size(path), header_size);
    now += std::chrono::milliseconds(100);  // 0.5 s since the header: flushed
    snapshot.step = 5;
    writer.on_step(snapshot, truth);
    const auto flushed = fs::file_size(path);
    EXPECT_GT(flushed, header_size);
    RunLog log = load_run_log(path);
    EXPECT_EQ(log.records.size(), 5U);
    EXPECT_FALSE(log.ended);

    snapshot.step = 6;
    writer.on_step(snapshot, truth);
    writer.close();
    log = load_run_log(path);
    EXPECT_EQ(log.records.size(), 6U);
    EXPECT_TRUE(log.ended);
    EXPECT_THROW(writer.on_step(snapshot, truth), RunLogWriteError);
}

TEST(RunLog, WriteErrorsAreReportedNotSwallowed) {
    const ResolvedRun run = short_drive();
    EXPECT_THROW(RunLogWriter(temp_file("missing-dir") / "x" / "run.log", run, "t"),
                 RunLogWriteError);
    if (fs::exists("/dev/full")) {  // every write fails: disk full
        EXPECT_THROW(RunLogWriter("/dev/full", run, "t"), RunLogWriteError);
    }
}

}  // namespace
}  // namespace legofeup::lessons
