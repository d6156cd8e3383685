#pragma once
// The session owns what the window shows: the configuration, the link choice, the running
// experiment (a LiveRun on its worker thread, and the embedded simulator on its own) and the
// run's history. Widgets receive it through their constructor; they read from it and ask it
// for changes, and it tells them what changed through signals.
//
// Threading: every method runs on the GUI thread and returns at once. The worker hands
// samples over in batches; the session takes them at most once per display frame (~60 Hz)
// and emits one samplesAppended() per batch, so the views repaint once per frame however
// fast the simulator runs, and a frame the GUI could not keep up with is merged into the
// next one, never queued.

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QTimer>
#include <atomic>
#include <future>
#include <memory>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/links/link_kind.hpp"
#include "legofeup/lessons/recording/run_log.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "legofeup/ui/run_history.hpp"
#include "legofeup/ui/session/live_run.hpp"
#include "legofeup/ui/session/run_recorder.hpp"

namespace legofeup::simserver {
class SimServer;
}

namespace legofeup::ui {

class EmulatedBrick;

/// Where the robot is: the simulator inside the application, a legofeup-sim elsewhere, or
/// a LEGO NXT (over Bluetooth, a serial port or TCP; or an emulated brick in the application).
enum class LinkKind : std::uint8_t { Embedded, External, Nxt };

struct LinkChoice {
    LinkKind kind = LinkKind::Embedded;
    QString address = QStringLiteral("udp://127.0.0.1:5600");  ///< External: the robot port
    double speed = 1.0;  ///< Embedded: simulated seconds per real second (is_simulator_speed)
    /// Nxt: the brick's address as typed (see nxt_address.hpp; a bare XX:XX:… is bt:).
    QString nxt_address;
    bool relay = false;     ///< Nxt: the relay program on the brick (docs/nxt.md)
    QString robot_profile;  ///< Nxt: a robot profile (TOML) for the run; empty: none
    /// Nxt: rehearse without a robot — an emulated brick inside the application, driven
    /// through the whole NXT path over loopback TCP, with the simulator's ground truth.
    bool emulated = false;
};

/// The embedded simulator's speeds, simulated seconds per real second: the time scales
/// simserver::validate() accepts, without its 0 (lockstep, as fast as the loop answers),
/// which is no speed to watch a run at.
inline constexpr double kMinSimulatorSpeed = 0.05;
inline constexpr double kMaxSimulatorSpeed = 1000.0;

/// Whether the embedded simulator runs at `speed` (a finite number in the range above).
constexpr bool is_simulator_speed(double speed) {
    return speed >= kMinSimulatorSpeed && speed <= kMaxSimulatorSpeed;  // false for NaN
}

class Session : public QObject {
    Q_OBJECT

  public:
    /// Starts with `config` (normally experiment f), resolved; throws InputError if it is not
    /// valid.
    explicit Session(const lessons::RunConfig& config, QObject* parent = nullptr);
    ~Session() override;

    const RunHistory& history() const { return history_; }
    const lessons::RunConfig& config() const { return config_; }
    const lessons::ResolvedRun& resolved() const { return resolved_; }
    RunPhase phase() const { return phase_; }
    /// The run's status as last reported (steps, time, frames missing, failure message).
    const LiveRunStatus& status() const { return status_; }
    const LinkChoice& linkChoice() const { return link_; }
    bool manualDriving() const { return manual_; }
    bool running() const;  ///< a run exists and is not over (Connecting, Running, Paused)

    /// Replaces the whole configuration (an experiment preset, a loaded file). Returns every
    /// problem, one per line; nothing changes unless the list is empty.
    QStringList setConfig(const lessons::RunConfig& config);
    /// Changes one setting (the configuration panel). Returns why it was refused, or an empty
    /// string when it was applied — live if a run is going and the setting applies live
    /// (lessons::Setting::applies_live()).
    QString changeSetting(const lessons::Setting& setting, const lessons::SettingValue& value);
    /// Takes effect at the next start.
    void setLinkChoice(const LinkChoice& choice);
    /// The latest NXT link's health (nullopt for a simulator, or before an NXT run).
    /// The robot's own health (an NXT's battery and cycle); null for a simulator.
    const lessons::LinkHealth* robotHealth() const { return status_.robot_health(); }

    /// Why the robot cannot be kidnapped now ("" when it can): a real or emulated NXT has no
    /// simulator to move it, and there must be a run going.
    QString teleportRefusal() const;
    /// Kidnaps the simulated robot: the simulator puts it at `pose` (world frame, at rest)
    /// through its control channel, on the worker thread; the filter is not told (paper 001
    /// §IV-B). Returns why it was refused, or "" when asked (a pose the simulator refuses,
    /// inside a wall, comes back through problem()).
    QString teleport(const Pose2& pose);

    /// Writes the configuration as TOML (the CLI reads the same file). Returns an error or "".
    QString saveConfig(const QString& path) const;
    /// Reads a TOML configuration (over the defaults). Returns the problems (file:line).
    QStringList loadConfig(const QString& path);
    /// Writes the whole history as trace.csv (the CLI's format). Returns an error or "".
    QString exportTrace(const QString& path) const;
    /// Records the coming run(s) into `directory`: config.toml now; as each run goes,
    /// trace.csv (flushed every frame) and run.log, the run log `legofeup-cli refilter` and
    /// File ▸ Re-filter replay (lessons/recording; flushed every half second). A later run
    /// writes trace-2.csv and run-2.log, never over an earlier one. "" to stop recording.
    /// Returns an error or "".
    QString setRecordingDirectory(const QString& directory);
    const QString& recordingDirectory() const { return recording_directory_; }
    /// The run log being written (or last written while recording); empty if none.
    const QString& recordingFile() const { return recording_file_; }

  public slots:
    /// Starts a new run (from a clean history), or resumes a paused one. After a failed run
    /// it connects again with the same choice: reconnecting needs no restart.
    void start();
    /// Stops the run: the motors stop and the robot is released; the history stays.
    void stop();
    /// Stops any run and returns to the start: empty history, initial pose.
    void reset();
    void setPaused(bool paused);
    /// Keyboard driving on (the path controller off) or off.
    void setManualDriving(bool manual);
    /// The keyboard's command: forward speed (m/s) and turn rate (rad/s).
    void setManualCommand(double speed, double turn_rate);

  signals:
    void historyRestarted();
    void samplesAppended(int first, int count);
    void phaseChanged(legofeup::ui::RunPhase phase);
    void configChanged();
    void manualDrivingChanged(bool manual);
    void linkChoiceChanged();
    /// Something the user should read (a failed link, a refused file).
    void problem(const QString& message);

  private:
    void workerNotified();  // any thread
    void drain();           // GUI thread
    void restartHistory();
    void retireRun();
    /// How the next run takes its robot (starting the embedded simulator or the emulated
    /// brick first); nullopt after emitting problem().
    std::optional<LiveRun::ConnectionFactory> prepareConnection();
    /// The NXT's (nxt_connection.hpp), with its robot profile: the brick at the address typed,
    /// or an emulated brick on this run's simulator, started first.
    std::unique_ptr<lessons::LinkPlan> prepareNxt();
    /// The registry's plan for `request`, or null after emitting problem() with why not.
    std::unique_ptr<lessons::LinkPlan> planLink(const lessons::LinkRequest& request);
    /// Starts the embedded simulator for this run and plans the link to it (null: problem()).
    std::unique_ptr<lessons::LinkPlan> startEmbeddedSimulator();
    /// `run` with the NXT run's robot profile applied to the filter (as it is without one).
    lessons::ResolvedRun forThisRobot(lessons::ResolvedRun run) const;
    /// Starts recording this run into the recording folder (a RunRecorder of its own).
    void openTrace();
    /// Ends the recording (the run is over, or another starts): what is queued is written,
    /// the run log gets its end line, and the recorder's problems are shown.
    void finishRecording();
    /// Shows (problem()) what went wrong on the recorder's thread since the last call.
    void showRecorderProblems();

    lessons::RunConfig config_;
    lessons::ResolvedRun resolved_;
    LinkChoice link_;
    bool manual_ = false;
    RunPhase phase_ = RunPhase::Idle;
    LiveRunStatus status_;
    RunHistory history_;

    std::unique_ptr<simserver::SimServer> embedded_;
    std::unique_ptr<EmulatedBrick> emulated_nxt_;
    std::optional<lessons::RobotProfile> profile_;  ///< the NXT run's robot profile, if any
    std::unique_ptr<LiveRun> run_;
    std::vector<std::future<void>> reapers_;  ///< retired runs being stopped and joined

    std::atomic<bool> drain_queued_{false};
    QTimer drain_timer_;
    QElapsedTimer since_drain_;

    QString recording_directory_;
    std::unique_ptr<RunRecorder> recorder_;  ///< writes trace.csv and run.log off this thread
    QString recording_file_;
};

/// A phase as the status bar words it.
QString phase_text(RunPhase phase);

}  // namespace legofeup::ui
