#pragma once
// A live run's recording — trace.csv and run.log in the chosen folder — written on a thread
// of its own, so that the GUI thread never waits for the disk.
//
// Session::drain used to write and flush both files for every batch of samples on the GUI
// thread: a slow disk (a lab's network home folder, a USB stick) then stalled the arena and
// the plots. Now drain hands the batch over (`append`, a copy under a mutex held for a
// moment) and the recorder's thread writes it, flushes the trace after each batch (so that
// a crash keeps what was shown) and lets RunLogWriter flush the log every 500 ms.
//
// What goes wrong on that thread comes back as typed problems in a mailbox (`take_problems`):
// the session words them (tr()) and shows them. A run log that fails stops (said once), the trace
// goes on, and the other way round, as before.
//
// `finish` writes what is still queued, ends the run log (its end line) and joins the
// thread: it waits at most for the last few batches, once, when a run ends. The destructor
// finishes too. Qt-free on purpose: tests drive it directly.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

class RunRecorder {
  public:
    /// Something that went wrong on the recorder's thread; `detail` is the file or the
    /// system's message.
    struct Problem {
        enum class Kind : std::uint8_t {
            TraceNotCreated,    ///< the trace cannot be created (nothing is recorded in it)
            TraceStopped,       ///< writing the trace failed: it stops there
            RunLogNotCreated,   ///< the run log cannot be created
            RunLogStopped,      ///< writing the run log failed: it stops there
            RunLogNotCompleted  ///< its end line could not be written
        };
        Kind kind;
        std::string detail;
    };

    /// Where and what to record. An empty `run_log` records the trace alone.
    struct Files {
        std::filesystem::path trace;
        std::filesystem::path run_log;
        std::string title = "LegoFeup Lab run";  ///< the run log's title line
        lessons::RunLogWriter::Options options;
    };

    /// Starts the thread, which creates both files (a file it cannot create is a problem in
    /// the mailbox, and that file is not recorded). `run` is the configuration the loop
    /// starts with: the trace's columns and the run log's header.
    RunRecorder(Files files, lessons::ResolvedRun run);
    ~RunRecorder();
    RunRecorder(const RunRecorder&) = delete;
    RunRecorder& operator=(const RunRecorder&) = delete;

    /// Queues a batch of samples to be written (copied: the caller keeps its own).
    void append(const std::vector<RunSample>& batch);
    /// Writes what is queued, ends the run log and stops the thread; later batches are
    /// dropped. Safe to call twice.
    void finish();
    /// What went wrong since the last call.
    std::vector<Problem> take_problems();

  private:
    void work(Files files, lessons::ResolvedRun run);

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::vector<RunSample>> queue_;
    std::vector<Problem> problems_;
    bool finishing_ = false;
    std::thread thread_;  ///< last: it starts when everything it uses exists
};

}  // namespace legofeup::ui
