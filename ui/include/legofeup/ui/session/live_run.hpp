#pragma once
// One run of the loop against a simulator server, on a thread of its own: the GUI's run.
//
// Unlike the CLI's run_with_link() it is open-ended and can be changed while it runs: a new
// configuration (Q, R, V_ref, noise, …), keyboard driving on or off, the keyboard's command,
// pause. The GUI thread asks for those changes; the worker applies them between two steps, so
// the loop is only ever touched by its own thread. Results go the other way as RunSamples
// the GUI thread takes in batches. Nothing here blocks the caller: every call takes a mutex
// held only to copy a few values.
//
// Qt-free on purpose: the session wraps it in signals, tests drive it directly.

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "legofeup/lessons/udp_run.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

enum class RunPhase : std::uint8_t {
    Idle,        ///< no run (the session's state before the first start and after a reset)
    Connecting,  ///< taking the simulator's robot
    Running,
    Paused,
    Finished,  ///< the routine is done (all laps driven) or the time limit
    Stopped,   ///< stopped by the user
    Failed,    ///< the link failed: see LiveRunStatus::message
};

struct LiveRunStatus {
    RunPhase phase = RunPhase::Connecting;
    std::string message;  ///< why the run failed
    std::uint64_t steps = 0;
    std::uint64_t frames_missing = 0;  ///< control periods run without a frame
    double time = 0.0;                 ///< simulated time of the latest step, s
};

class LiveRun {
  public:
    /// Called from the worker thread when samples wait to be taken (once until the next
    /// take_samples()) or the phase changed. Must be cheap and thread-safe.
    using Notify = std::function<void()>;

    /// Starts the worker at once: it connects to `target` and runs `run` there.
    LiveRun(lessons::ResolvedRun run, lessons::UdpTarget target, Notify notify);
    /// Stops the motors, releases the robot and joins the worker.
    ~LiveRun();
    LiveRun(const LiveRun&) = delete;
    LiveRun& operator=(const LiveRun&) = delete;

    /// Everything that can change while running (the loop's tuning, gains, speeds and the
    /// simulator's noise) takes effect at the next step; the rest at the next run.
    void reconfigure(const lessons::ResolvedRun& run);
    /// true: the keyboard drives (ManualDrive); false: back to the run's routine, restarted.
    void set_manual_driving(bool manual);
    void set_manual_command(const VelocityCommand& command);
    void set_paused(bool paused);

    /// The samples produced since the last call, oldest first.
    std::vector<RunSample> take_samples();
    LiveRunStatus status() const;
    /// Asks the worker to stop without waiting for it: it stops the motors, releases the
    /// robot and reports RunPhase::Stopped (the destructor then joins at once).
    void request_stop() { worker_.request_stop(); }

  private:
    struct Requests {
        std::optional<lessons::ResolvedRun> run;
        std::optional<bool> manual;
        std::optional<VelocityCommand> command;
        std::optional<bool> paused;
    };

    void work(const std::stop_token& stop);
    void apply(Requests requests, LegoFeupLoop& loop, lessons::UdpRobotConnection& connection);
    void publish(RunSample sample, std::uint64_t frames_missing);
    void set_phase(RunPhase phase, std::string message = {});
    bool is_over(const LoopSnapshot& snapshot) const;

    // Owned by the worker thread once it runs.
    lessons::ResolvedRun run_;
    lessons::UdpTarget target_;
    Notify notify_;
    bool manual_ = false;

    mutable std::mutex mutex_;  // guards everything below
    Requests requests_;
    std::vector<RunSample> pending_;
    LiveRunStatus status_;

    std::jthread worker_;  // last: starts once everything above exists
};

}  // namespace legofeup::ui
