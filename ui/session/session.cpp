#include "legofeup/ui/session/session.hpp"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "legofeup/comms/endpoint.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/links/link_registry.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/simserver/sim_server.hpp"
#include "legofeup/ui/session/nxt_connection.hpp"
#include "legofeup/ui/session/run_samples.hpp"
#include "legofeup/ui/write_atomically.hpp"

namespace legofeup::ui {
namespace {

using namespace std::chrono_literals;

constexpr int kFrameMilliseconds = 16;  // drain at most once per 60 Hz display frame

QStringList problem_lines(const lessons::InputError& error) {
    QStringList lines;
    for (const lessons::InputProblem& problem : error.problems()) {
        lines << QString::fromStdString(problem.message());
    }
    return lines;
}

}  // namespace

QString phase_text(RunPhase phase) {
    switch (phase) {
        case RunPhase::Idle:
            return QObject::tr("Ready");
        case RunPhase::Connecting:
            return QObject::tr("Connecting…");
        case RunPhase::Running:
            return QObject::tr("Running");
        case RunPhase::Paused:
            return QObject::tr("Paused");
        case RunPhase::Finished:
            return QObject::tr("Finished");
        case RunPhase::Stopped:
            return QObject::tr("Stopped");
        case RunPhase::Failed:
            return QObject::tr("Link failed");
    }
    return {};
}

Session::Session(const lessons::RunConfig& config, QObject* parent)
    : QObject(parent), config_(config), resolved_(lessons::resolve(config)) {
    drain_timer_.setSingleShot(true);
    connect(&drain_timer_, &QTimer::timeout, this, &Session::drain);
    since_drain_.start();
    history_.restart(scene_of(resolved_));
}

Session::~Session() {
    run_.reset();      // joins the worker, which may still notify us until then
    reapers_.clear();  // and the retired ones
    embedded_.reset();
    emulated_nxt_.reset();
}

bool Session::running() const {
    return phase_ == RunPhase::Connecting || phase_ == RunPhase::Running
           || phase_ == RunPhase::Paused;
}

QStringList Session::setConfig(const lessons::RunConfig& config) {
    try {
        // The world and map files are read again only when named anew or changed on disk.
        lessons::ResolvedRun resolved = lessons::resolve(config, resolved_);
        config_ = config;
        resolved_ = std::move(resolved);
    } catch (const lessons::InputError& error) {
        return problem_lines(error);
    }
    if (run_ && running()) {
        run_->reconfigure(forThisRobot(resolved_));
        history_.update_scene(scene_of(resolved_));  // a live threshold (min matched points)
    } else {
        history_.restart(scene_of(resolved_));
        emit historyRestarted();
    }
    emit configChanged();
    return {};
}

QString Session::changeSetting(const lessons::Setting& setting,
                               const lessons::SettingValue& value) {
    lessons::RunConfig changed = config_;
    try {
        setting.set(changed, value);
    } catch (const std::exception& error) {
        return QString::fromStdString(setting.key + ": " + error.what());
    }
    changed.origins[setting.field] = {"the configuration panel", 0, setting.key};
    const QStringList problems = setConfig(changed);
    return problems.join('\n');
}

void Session::setLinkChoice(const LinkChoice& choice) {
    link_ = choice;
    emit linkChoiceChanged();
}

QString Session::saveConfig(const QString& path) const {
    return write_atomically(path, QByteArray::fromStdString(lessons::config_to_toml(
                                      config_, "LegoFeup Lab configuration")));
}

QStringList Session::loadConfig(const QString& path) {
    try {
        return setConfig(lessons::load_config_file(path.toStdString(), lessons::RunConfig{}));
    } catch (const lessons::InputError& error) {
        return problem_lines(error);
    }
}

QString Session::exportTrace(const QString& path) const {
    return write_atomically(path, QByteArray::fromStdString(history_.trace_csv()));
}

void Session::finishRecording() {
    if (!recorder_) {
        return;
    }
    recorder_->finish();  // writes what is queued and ends the run log
    showRecorderProblems();
    recorder_.reset();
}

void Session::showRecorderProblems() {
    using Kind = RunRecorder::Problem::Kind;
    for (const RunRecorder::Problem& trouble : recorder_->take_problems()) {
        const QString detail = QString::fromStdString(trouble.detail);
        switch (trouble.kind) {
            case Kind::TraceNotCreated:
                emit problem(tr("Cannot record into %1").arg(detail));
                break;
            case Kind::TraceStopped:
                emit problem(tr("The trace stopped: %1 cannot be written").arg(detail));
                break;
            case Kind::RunLogNotCreated:
                recording_file_.clear();
                emit problem(tr("Cannot record the run log: %1").arg(detail));
                break;
            case Kind::RunLogStopped:
                emit problem(tr("The run log stopped: %1").arg(detail));
                break;
            case Kind::RunLogNotCompleted:
                emit problem(tr("The run log was not completed: %1").arg(detail));
                break;
        }
    }
}

QString Session::setRecordingDirectory(const QString& directory) {
    finishRecording();
    recording_directory_.clear();
    recording_file_.clear();
    if (directory.isEmpty()) {
        return {};
    }
    if (!QDir().mkpath(directory) || !QFileInfo(directory).isWritable()) {
        return tr("Cannot record into %1: the folder cannot be created or written").arg(directory);
    }
    recording_directory_ = directory;
    if (const QString error = saveConfig(QDir(directory).filePath("config.toml"));
        !error.isEmpty()) {
        recording_directory_.clear();
        return error;
    }
    if (running()) {
        openTrace();
    }
    return {};
}

void Session::openTrace() {
    finishRecording();
    if (recording_directory_.isEmpty()) {
        return;
    }
    // A new run starts new files; an earlier recording is kept under its own names.
    const QDir directory(recording_directory_);
    QString name = QStringLiteral("trace.csv");
    QString log_name = QStringLiteral("run.log");
    for (int n = 2; directory.exists(name) || directory.exists(log_name); ++n) {
        name = QStringLiteral("trace-%1.csv").arg(n);
        log_name = QStringLiteral("run-%1.log").arg(n);
    }
    // The recorder's thread creates and writes both files. The run log has the
    // configuration the loop starts with (with an NXT's robot profile).
    RunRecorder::Files files;
    files.trace = directory.filePath(name).toStdString();
    files.run_log = directory.filePath(log_name).toStdString();
    files.options.program = "legofeup " + QCoreApplication::applicationVersion().toStdString();
    files.options.link = link_.kind == LinkKind::Nxt ? "gui, nxt"
                         : link_.kind == LinkKind::External
                             ? "gui, udp " + link_.address.toStdString()
                             : "gui, embedded simulator";
    recording_file_ = directory.filePath(log_name);
    recorder_ = std::make_unique<RunRecorder>(std::move(files), forThisRobot(resolved_));
}

void Session::restartHistory() {
    history_.restart(scene_of(resolved_));
    emit historyRestarted();
}

std::optional<LiveRun::ConnectionFactory> Session::prepareConnection() {
    embedded_.reset();
    emulated_nxt_.reset();
    profile_.reset();
    // Every robot is a link of the registry (lessons/links/link_registry.hpp); the embedded
    // simulator is a simulator server like any other, on this run's loopback ports.
    std::unique_ptr<lessons::LinkPlan> plan;
    if (link_.kind == LinkKind::Nxt) {
        plan = prepareNxt();
    } else if (link_.kind == LinkKind::External) {
        lessons::LinkRequest request;
        request.address = link_.address.toStdString();
        plan = planLink(request);
    } else {
        plan = startEmbeddedSimulator();
    }
    if (!plan) {
        return std::nullopt;
    }
    return [run = forThisRobot(resolved_), plan = std::shared_ptr<const lessons::LinkPlan>(
                                               std::move(plan))] { return plan->connect(run); };
}

std::unique_ptr<lessons::LinkPlan> Session::planLink(const lessons::LinkRequest& request) {
    try {
        return lessons::plan_link(request);
    } catch (const lessons::InputError& error) {
        emit problem(problem_lines(error).join('\n'));
        return nullptr;
    }
}

std::unique_ptr<lessons::LinkPlan> Session::startEmbeddedSimulator() {
    // A fresh server per run, on free loopback ports, so it always has this run's world,
    // robot and timing.
    simserver::SimServerOptions options;
    options.bind = comms::Endpoint{comms::kLoopbackAddress, 0};
    options.time_scale = link_.speed;
    try {
        embedded_ = std::make_unique<simserver::SimServer>(resolved_.world, resolved_.robot,
                                                           resolved_.config.simulator,
                                                           resolved_.config.seed, options);
    } catch (const std::exception& error) {
        emit problem(tr("The embedded simulator did not start: %1").arg(error.what()));
        return nullptr;
    }
    embedded_->start();
    const simserver::BoundPorts ports = embedded_->ports();
    lessons::LinkRequest request;
    request.address = "udp://" + options.bind.with_port(ports.robot).to_string();
    request.truth_port = ports.truth;
    request.control_port = ports.control;
    return planLink(request);
}

lessons::ResolvedRun Session::forThisRobot(lessons::ResolvedRun run) const {
    if (profile_) {
        lessons::apply_robot_profile(*profile_, run.loop);  // its odometry and IR curve
    }
    return run;
}

std::unique_ptr<lessons::LinkPlan> Session::prepareNxt() {
    if (!link_.robot_profile.isEmpty()) {
        try {
            profile_ = lessons::load_robot_profile(link_.robot_profile.toStdString());
        } catch (const lessons::InputError& error) {
            emit problem(tr("The robot profile %1 did not load:\n%2")
                             .arg(link_.robot_profile, problem_lines(error).join('\n')));
            return nullptr;
        }
    }
    NxtConnection nxt = prepare_nxt_connection(link_, profile_ ? &*profile_ : nullptr, config_);
    if (!nxt.plan) {
        emit problem(nxt.problem);
        return nullptr;
    }
    emulated_nxt_ = std::move(nxt.emulated_brick);
    return std::move(nxt.plan);
}

void Session::retireRun() {
    if (!run_) {
        return;
    }
    drain();  // what the worker produced so far belongs to this run's history
    // The worker may be waiting on a socket for up to a control period (or a connection
    // timeout): it stops and is joined on a thread of its own, never on the GUI thread.
    run_->request_stop();
    std::erase_if(reapers_, [](const std::future<void>& reaper) {
        return reaper.wait_for(0s) == std::future_status::ready;
    });
    reapers_.push_back(
        std::async(std::launch::async, [run = std::move(run_)]() mutable { run.reset(); }));
}

void Session::start() {
    if (run_ && phase_ == RunPhase::Paused) {
        setPaused(false);
        return;
    }
    retireRun();
    std::optional<LiveRun::ConnectionFactory> connect = prepareConnection();
    if (!connect) {
        return;
    }
    restartHistory();
    status_ = {};
    phase_ = RunPhase::Connecting;
    emit phaseChanged(phase_);
    run_ = std::make_unique<LiveRun>(forThisRobot(resolved_), std::move(*connect),
                                     [this] { workerNotified(); });
    if (manual_) {
        run_->set_manual_driving(true);
    }
    openTrace();
}

void Session::stop() {
    if (run_ && running()) {
        run_->request_stop();  // the worker reports Stopped when it has let go of the robot
    }
}

void Session::reset() {
    retireRun();
    embedded_.reset();
    emulated_nxt_.reset();
    finishRecording();
    status_ = {};
    phase_ = RunPhase::Idle;
    restartHistory();
    emit phaseChanged(phase_);
}

void Session::setPaused(bool paused) {
    if (run_ && running()) {
        run_->set_paused(paused);
    }
}

QString Session::teleportRefusal() const {
    if (link_.kind == LinkKind::Nxt) {
        return link_.emulated ? tr(
                   "Kidnapping moves a simulated robot: the emulated brick has "
                   "no control channel to move its robot by")
                              : tr(
                                  "Kidnapping moves a simulated robot: nobody can lift a real "
                                  "NXT from here");
    }
    if (!run_ || !running()) {
        return tr("Start a run first: the robot is kidnapped from a running simulator");
    }
    if (!status_.capabilities.teleport) {  // the connection says so (or is not taken yet)
        return tr("The robot of %1 cannot be moved from here")
            .arg(QString::fromStdString(status_.link));
    }
    return {};
}

QString Session::teleport(const Pose2& pose) {
    if (QString why = teleportRefusal(); !why.isEmpty()) {
        return why;
    }
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
        return tr("The pose to put the robot at is not a number");
    }
    run_->teleport(pose);  // the simulator's control channel; the filter is not told
    return {};
}

void Session::setManualDriving(bool manual) {
    if (manual == manual_) {
        return;
    }
    manual_ = manual;
    if (run_) {
        run_->set_manual_driving(manual);
        if (!manual) {
            run_->set_manual_command({});
        }
    }
    emit manualDrivingChanged(manual);
}

void Session::setManualCommand(double speed, double turn_rate) {
    if (run_) {
        run_->set_manual_command({speed, turn_rate});
    }
}

void Session::workerNotified() {
    if (!drain_queued_.exchange(true)) {
        QMetaObject::invokeMethod(
            this,
            [this] {
                // At most one drain per display frame: wait out the rest of this one.
                const qint64 elapsed = since_drain_.elapsed();
                if (elapsed >= kFrameMilliseconds) {
                    drain();
                } else if (!drain_timer_.isActive()) {
                    drain_timer_.start(static_cast<int>(kFrameMilliseconds - elapsed));
                }
            },
            Qt::QueuedConnection);
    }
}

void Session::drain() {
    drain_queued_ = false;
    since_drain_.restart();
    if (!run_) {
        return;
    }
    // The status first: the worker publishes a run's last step before it reports the phase
    // that step led to (Finished), so every step of a phase read here is in this batch or an
    // earlier one — the views and the lesson's checks have the whole run when it ends.
    const LiveRunStatus status = run_->status();
    std::vector<RunSample> batch = run_->take_samples();
    for (const std::string& note : run_->take_notes()) {
        emit problem(QString::fromStdString(note));
    }
    if (!batch.empty()) {
        if (recorder_) {
            recorder_->append(batch);  // written on the recorder's thread
            showRecorderProblems();
        }
        const int first = static_cast<int>(history_.size());
        const int count = static_cast<int>(batch.size());
        history_.append(std::move(batch));
        emit samplesAppended(first, count);
    }
    status_ = status;
    if (status.phase != phase_) {
        phase_ = status.phase;
        if (!running()) {
            finishRecording();  // the run is over: its log gets its end line
        }
        if (phase_ == RunPhase::Failed) {
            emit problem(tr("The link failed: %1").arg(QString::fromStdString(status.message)));
        }
        emit phaseChanged(phase_);
    }
}

}  // namespace legofeup::ui
