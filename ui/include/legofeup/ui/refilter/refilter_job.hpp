#pragma once
// The Re-filter dialog's two long pieces of work, each a BackgroundTask (background_task.hpp)
// so that the dialog stays responsive:
//   RefilterJob     one re-filtering (lessons::refilter): a laser log runs one ICP per scan,
//                   twice — seconds, not milliseconds; its progress is the replay's;
//   RunLogReadJob   reading a run log (lessons::load_run_log) and the walls of its world
//                   (whose file resolve() reads): a long log is tens of megabytes.
// Destroying either cancels it (a replay stops at its next step) and joins its thread.

#include <memory>
#include <vector>

#include "legofeup/core/walls.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/background_task.hpp"

namespace legofeup::ui {

class RefilterJob : public BackgroundTask<lessons::RefilterResult> {
  public:
    /// Starts replaying `log` (shared, not copied: a log can be large) with `new_config`; a
    /// configuration that does not resolve, or a cancel(), finishes with the message.
    RefilterJob(std::shared_ptr<const lessons::RunLog> log, lessons::RunConfig new_config);
};

/// A run log as the dialog shows it.
struct ReadRunLog {
    std::shared_ptr<const lessons::RunLog> log;
    /// The walls of the log's world, for the overlay; none when its world file no longer
    /// reads (the replay itself needs no world file: the log holds the readings).
    std::vector<Wall> walls;
};

class RunLogReadJob : public BackgroundTask<ReadRunLog> {
  public:
    /// Starts reading the run log at `path`; a file that does not read finishes with the
    /// reader's message (file:line and the reason).
    explicit RunLogReadJob(std::string path);
};

}  // namespace legofeup::ui
