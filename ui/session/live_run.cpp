#include "legofeup/ui/session/live_run.hpp"

#include <exception>
#include <stdexcept>
#include <utility>

#include "legofeup/comms/link_error.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui {
namespace {

/// Why a connection's link failed, naming the link; empty while it has not.
std::string link_failure(const lessons::RobotConnection& connection) {
    const lessons::LinkHealth health = connection.health();
    if (health.state != lessons::LinkState::Failed) {
        return {};
    }
    const std::string link = connection.describe();  // "NXT at tcp:127.0.0.1:5700 (…)"
    if (health.last_error.empty()) {
        return link + ": the link failed";
    }
    // The link's own message usually names its address already: say it once.
    if (!health.address.empty() && health.last_error.find(health.address) != std::string::npos) {
        return health.last_error;
    }
    return link + ": " + health.last_error;
}

}  // namespace

LiveRun::LiveRun(lessons::ResolvedRun run, ConnectionFactory connect, Notify notify)
    : run_(std::move(run)),
      connect_(std::move(connect)),
      notify_(std::move(notify)),
      worker_([this](const std::stop_token& stop) { work(stop); }) {}

LiveRun::~LiveRun() {
    worker_.request_stop();
    worker_.join();
}

void LiveRun::reconfigure(const lessons::ResolvedRun& run) {
    const std::lock_guard lock(mutex_);
    requests_.run = run;
}

void LiveRun::set_manual_driving(bool manual) {
    const std::lock_guard lock(mutex_);
    requests_.manual = manual;
}

void LiveRun::set_manual_command(const VelocityCommand& command) {
    const std::lock_guard lock(mutex_);
    requests_.command = command;
}

void LiveRun::set_paused(bool paused) {
    const std::lock_guard lock(mutex_);
    requests_.paused = paused;
}

void LiveRun::teleport(const Pose2& pose) {
    const std::lock_guard lock(mutex_);
    requests_.teleport = pose;
}

std::vector<std::string> LiveRun::take_notes() {
    const std::lock_guard lock(mutex_);
    return std::exchange(notes_, {});
}

void LiveRun::note(std::string text) {
    {
        const std::lock_guard lock(mutex_);
        notes_.push_back(std::move(text));
    }
    notify_();
}

std::vector<RunSample> LiveRun::take_samples() {
    const std::lock_guard lock(mutex_);
    return std::exchange(pending_, {});
}

LiveRunStatus LiveRun::status() const {
    const std::lock_guard lock(mutex_);
    return status_;
}

void LiveRun::set_phase(RunPhase phase, std::string message) {
    {
        const std::lock_guard lock(mutex_);
        status_.phase = phase;
        status_.message = std::move(message);
    }
    notify_();
}

void LiveRun::publish(RunSample sample, std::uint64_t frames_missing, lessons::LinkHealth health) {
    bool first = false;
    {
        const std::lock_guard lock(mutex_);
        status_.steps = sample.snapshot.step;
        status_.time = sample.snapshot.time;
        status_.frames_missing = frames_missing;
        status_.health = std::move(health);
        first = pending_.empty();
        pending_.push_back(std::move(sample));
    }
    if (first) {
        notify_();  // one notification per batch: the GUI takes them all at once
    }
}

bool LiveRun::is_over(const LoopSnapshot& snapshot) const {
    // Driving by hand never ends on its own; a routine ends when finished or at the limit.
    return !manual_ && (snapshot.controller.finished || snapshot.time >= run_.max_duration);
}

void LiveRun::check_link(const lessons::RobotConnection& connection) {
    if (std::string why = link_failure(connection); !why.empty()) {
        throw std::runtime_error(why);
    }
}

void LiveRun::apply(Requests requests, LegoFeupLoop& loop, lessons::RobotConnection& connection) {
    if (requests.run) {
        // Validated by the session already: reconfigure() cannot refuse it.
        loop.reconfigure(requests.run->loop);
        if (lessons::robot_noise(requests.run->robot) != lessons::robot_noise(run_.robot)) {
            if (connection.capabilities().live_noise) {  // a real robot has no noise to set
                connection.set_noise(lessons::robot_noise(requests.run->robot));
            }
        }
        run_ = std::move(*requests.run);
    }
    if (requests.manual && *requests.manual != manual_) {
        manual_ = *requests.manual;
        loop.set_controller(manual_ ? Controller(ManualDrive{}) : run_.loop.controller);
    }
    if (requests.command) {
        loop.set_manual_command(*requests.command);
    }
    if (requests.paused) {
        connection.set_paused(*requests.paused);
        set_phase(*requests.paused ? RunPhase::Paused : RunPhase::Running);
    }
    if (requests.teleport) {
        // Only a simulator server can lift its robot: through its control channel, like the
        // noise and the pause.
        try {
            if (const std::string refusal = connection.teleport(*requests.teleport);
                !refusal.empty()) {
                note("The robot was not kidnapped: " + refusal);
            }
        } catch (const comms::LinkError& error) {
            // The server refused the pose (inside a wall, outside the world) or did not answer:
            // the run goes on where the robot is.
            note(std::string("The robot was not kidnapped: ") + error.what());
        }
    }
}

void LiveRun::work(const std::stop_token& stop) {
    std::unique_ptr<lessons::RobotConnection> connection;
    try {
        connection = connect_();
        if (!connection) {
            throw std::runtime_error("no robot to connect to");
        }
        {
            const std::lock_guard lock(mutex_);
            status_.link = connection->describe();
            status_.capabilities = connection->capabilities();
            status_.health = connection->health();
        }
        LegoFeupLoop loop(run_.loop);
        lessons::LinkStepper stepper(run_.config.simulator.control_period);
        TruthSource* const truth_source = connection->truth_source();  // null: a real robot
        std::optional<GroundTruth> last_truth;
        set_phase(RunPhase::Running);

        const auto on_step = [&](const LoopSnapshot& snapshot) {
            if (truth_source != nullptr) {
                if (auto truth = truth_source->truth_at(snapshot.time)) {
                    last_truth = truth;
                }
            }
            RunSample sample = make_run_sample(snapshot, last_truth);
            if (snapshot.particles.count > 0) {  // the particle filter: its cloud to draw
                auto cloud = std::make_shared<std::vector<ParticlePoint>>();
                loop.filter().sample_cloud(kParticlesShown, *cloud);
                sample.particles = std::move(cloud);
            }
            publish(std::move(sample), stepper.frames_missing(), connection->health());
            return is_over(snapshot);
        };
        while (!stop.stop_requested()) {
            Requests requests;
            {
                const std::lock_guard lock(mutex_);
                requests = std::exchange(requests_, {});
            }
            apply(std::move(requests), loop, *connection);
            const bool over = stepper.advance(loop, connection->robot_link(), on_step);
            check_link(*connection);
            if (stepper.stepped()) {
                connection->robot_link().send_command(loop.snapshot().wheels);
            }
            if (over) {
                connection->close();
                set_phase(RunPhase::Finished);
                return;
            }
        }
        connection->close();
        set_phase(RunPhase::Stopped);
    } catch (const std::exception& error) {
        // The link's own reason (an NXT that stopped answering) says more than the runner's
        // "no frame for 40 periods"; closing tries once more to stop the motors.
        std::string message = error.what();
        if (connection) {
            if (std::string why = link_failure(*connection); !why.empty()) {
                message = std::move(why);
            }
            connection->close();
            const std::lock_guard lock(mutex_);
            status_.health = connection->health();
        }
        set_phase(RunPhase::Failed, std::move(message));
    }
}

}  // namespace legofeup::ui
