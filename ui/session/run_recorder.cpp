#include "legofeup/ui/session/run_recorder.hpp"

#include <fstream>
#include <optional>
#include <utility>

#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui {

RunRecorder::RunRecorder(Files files, lessons::ResolvedRun run)
    : thread_([this, files = std::move(files), run = std::move(run)]() mutable {
          work(std::move(files), std::move(run));
      }) {}

RunRecorder::~RunRecorder() {
    finish();
}

void RunRecorder::append(const std::vector<RunSample>& batch) {
    if (batch.empty()) {
        return;
    }
    {
        const std::lock_guard lock(mutex_);
        if (finishing_) {
            return;
        }
        queue_.push_back(batch);
    }
    wake_.notify_one();
}

void RunRecorder::finish() {
    {
        const std::lock_guard lock(mutex_);
        finishing_ = true;
    }
    wake_.notify_one();
    if (thread_.joinable()) {
        thread_.join();
    }
}

std::vector<RunRecorder::Problem> RunRecorder::take_problems() {
    const std::lock_guard lock(mutex_);
    return std::exchange(problems_, {});
}

void RunRecorder::work(Files files, lessons::ResolvedRun run) {
    using Kind = Problem::Kind;
    const auto report = [this](Kind kind, std::string detail) {
        const std::lock_guard lock(mutex_);
        problems_.push_back({kind, std::move(detail)});
    };
    // 1. Create the files. The trace writer keeps a reference to the loop's configuration:
    //    `run` lives on this thread's stack for as long as the writer.
    std::ofstream trace_file(files.trace, std::ios::binary);
    std::optional<lessons::TraceCsvWriter> trace;
    if (trace_file) {
        trace.emplace(trace_file, run.loop);
        trace_file.flush();
    } else {
        report(Kind::TraceNotCreated, files.trace.string());
    }
    std::unique_ptr<lessons::RunLogWriter> log;
    if (!files.run_log.empty()) {
        try {
            log = std::make_unique<lessons::RunLogWriter>(files.run_log, run, files.title,
                                                          std::move(files.options));
        } catch (const lessons::RunLogWriteError& error) {
            report(Kind::RunLogNotCreated, error.what());
        }
    }
    // 2. Write each batch as it comes, until finish() and the queue is empty.
    for (;;) {
        std::vector<RunSample> batch;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return finishing_ || !queue_.empty(); });
            if (queue_.empty()) {
                break;  // finishing, and everything queued is written
            }
            batch = std::move(queue_.front());
            queue_.pop_front();
        }
        if (trace) {
            for (const RunSample& sample : batch) {
                trace->on_step(sample.snapshot, truth_or_unknown(sample));
            }
            if (!trace_file.flush()) {
                trace.reset();  // said once, then the trace stops
                report(Kind::TraceStopped, files.trace.string());
            }
        }
        if (log) {
            try {
                for (const RunSample& sample : batch) {
                    log->on_step(sample.snapshot, truth_or_unknown(sample));
                }
            } catch (const lessons::RunLogWriteError& error) {
                log.reset();  // a recording that fails says so once, then stops
                report(Kind::RunLogStopped, error.what());
            }
        }
    }
    // 3. End the run log: its end line says the run was recorded to its end.
    if (log) {
        try {
            log->close();
        } catch (const lessons::RunLogWriteError& error) {
            report(Kind::RunLogNotCompleted, error.what());
        }
    }
}

}  // namespace legofeup::ui
