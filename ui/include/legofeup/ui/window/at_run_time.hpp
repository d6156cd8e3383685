#pragma once
// A moment of the run rather than of the wall clock: `legofeup --screenshot-at` takes its
// picture when the run reaches a time, so the picture shows the same moment of the run
// however long the start took and however busy the machine is.

#include <functional>

namespace legofeup::ui {

class Session;

/// Calls `then` once, on the GUI thread: as soon as the session's latest sample is at
/// `seconds` of run time or later, or when the run ends before it (Finished, Stopped, Failed),
/// whichever comes first. Nothing is called if the session is destroyed before.
void at_run_time(Session& session, double seconds, std::function<void()> then);

}  // namespace legofeup::ui
