#pragma once
// One run of the loop against a robot — a simulator server, or an NXT (real or emulated) —
// on a thread of its own: the GUI's run.
//
// Unlike the CLI's run_with_link() it is open-ended and can be changed while it runs: a new
// configuration (Q, R, V_ref, noise, …), keyboard driving on or off, the keyboard's command,
// pause. The GUI thread asks for those changes; the worker applies them between two steps, so
// the loop is only ever touched by its own thread. Results go the other way as RunSamples
// the GUI thread takes in batches. Nothing here blocks the caller: every call takes a mutex
// held only to copy a few values.
//
// The robot is taken by a connection factory called on the worker thread, so a slow connect
// (a Bluetooth link can take seconds) never blocks the GUI. The run talks to the robot only
// through lessons::RobotConnection: a robot without ground truth (a real NXT) gives samples
// without truth.
//
// Qt-free on purpose: the session wraps it in signals, tests drive it directly.

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/lessons/robot_connection.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

enum class RunPhase : std::uint8_t {
    Idle,        ///< no run (the session's state before the first start and after a reset)
    Connecting,  ///< taking the robot (the connection factory runs)
    Running,
    Paused,
    Finished,  ///< the routine is done (all laps driven) or the time limit
    Stopped,   ///< stopped by the user
    Failed,    ///< the link failed: see LiveRunStatus::message
};

struct LiveRunStatus {
    RunPhase phase = RunPhase::Connecting;
    std::string message;  ///< why the run failed
    std::string link;     ///< the robot taken (RobotConnection::describe()); empty before
    std::uint64_t steps = 0;
    std::uint64_t frames_missing = 0;  ///< control periods run without a frame
    double time = 0.0;                 ///< time of the latest step, s
    /// What the robot taken can do (RobotConnection::capabilities()); none before.
    lessons::LinkCapabilities capabilities;
    /// How its link is doing (state, counters, cycle time, battery), refreshed every step;
    /// nullopt before the robot is taken.
    std::optional<lessons::LinkHealth> health;

    /// The health of a robot that reports its own (an NXT's battery and cycle); null for a
    /// simulator, whose health is its stream's counters only.
    const lessons::LinkHealth* robot_health() const {
        return capabilities.robot_health && health ? &*health : nullptr;
    }
};

class LiveRun {
  public:
    /// Called from the worker thread when samples wait to be taken (once until the next
    /// take_samples()) or the phase changed. Must be cheap and thread-safe.
    using Notify = std::function<void()>;
    /// Takes the robot (blocking; called once, on the worker thread). Throws with what went
    /// wrong and what to do.
    using ConnectionFactory = std::function<std::unique_ptr<lessons::RobotConnection>()>;

    /// Starts the worker at once: it calls `connect` and runs `run` on the robot it returns.
    LiveRun(lessons::ResolvedRun run, ConnectionFactory connect, Notify notify);
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
    /// Kidnaps a simulated robot (a simulator server's control channel: UDP); a robot that
    /// cannot be moved so (an NXT) says so in a note. The loop is not told.
    void teleport(const Pose2& pose);

    /// The samples produced since the last call, oldest first.
    std::vector<RunSample> take_samples();
    /// What the user should read since the last call (a teleport the simulator refused).
    std::vector<std::string> take_notes();
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
        std::optional<Pose2> teleport;
    };

    void work(const std::stop_token& stop);
    void apply(Requests requests, LegoFeupLoop& loop, lessons::RobotConnection& connection);
    void publish(RunSample sample, std::uint64_t frames_missing, lessons::LinkHealth health);
    /// Throws if the connection reports its link failed (an NXT that stopped answering).
    static void check_link(const lessons::RobotConnection& connection);
    void set_phase(RunPhase phase, std::string message = {});
    void note(std::string text);
    bool is_over(const LoopSnapshot& snapshot) const;

    // Owned by the worker thread once it runs.
    lessons::ResolvedRun run_;
    ConnectionFactory connect_;
    Notify notify_;
    bool manual_ = false;

    mutable std::mutex mutex_;  // guards everything below
    Requests requests_;
    std::vector<RunSample> pending_;
    std::vector<std::string> notes_;
    LiveRunStatus status_;

    std::jthread worker_;  // last: starts once everything above exists
};

}  // namespace legofeup::ui
