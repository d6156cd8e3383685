#include "legofeup/ui/session/live_run.hpp"

#include <exception>
#include <utility>

#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui {
LiveRun::LiveRun(lessons::ResolvedRun run, lessons::UdpTarget target, Notify notify)
    : run_(std::move(run)),
      target_(target),
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

void LiveRun::publish(RunSample sample, std::uint64_t frames_missing) {
    bool first = false;
    {
        const std::lock_guard lock(mutex_);
        status_.steps = sample.snapshot.step;
        status_.time = sample.snapshot.time;
        status_.frames_missing = frames_missing;
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

void LiveRun::apply(Requests requests, LegoFeupLoop& loop,
                    lessons::UdpRobotConnection& connection) {
    if (requests.run) {
        // Validated by the session already: reconfigure() cannot refuse it.
        loop.reconfigure(requests.run->loop);
        const comms::NoiseSettings noise = lessons::noise_settings_of(requests.run->robot);
        if (noise != lessons::noise_settings_of(run_.robot)) {
            connection.control().set_noise(noise);
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
        if (*requests.paused) {
            connection.control().pause();
        } else {
            connection.control().resume();
        }
        set_phase(*requests.paused ? RunPhase::Paused : RunPhase::Running);
    }
}

void LiveRun::work(const std::stop_token& stop) {
    try {
        lessons::UdpRobotConnection connection(run_, target_);
        LegoFeupLoop loop(run_.loop);
        lessons::LinkStepper stepper(run_.config.simulator.control_period);
        std::optional<GroundTruth> last_truth;
        set_phase(RunPhase::Running);

        const auto on_step = [&](const LoopSnapshot& snapshot) {
            if (auto truth = connection.truth().truth_at(snapshot.time)) {
                last_truth = truth;
            }
            publish(make_run_sample(snapshot, last_truth), stepper.frames_missing());
            return is_over(snapshot);
        };
        while (!stop.stop_requested()) {
            Requests requests;
            {
                const std::lock_guard lock(mutex_);
                requests = std::exchange(requests_, {});
            }
            apply(std::move(requests), loop, connection);
            const bool over = stepper.advance(loop, connection.link(), on_step);
            if (stepper.stepped()) {
                connection.link().send_command(loop.snapshot().wheels);
            }
            if (over) {
                connection.close();
                set_phase(RunPhase::Finished);
                return;
            }
        }
        connection.close();
        set_phase(RunPhase::Stopped);
    } catch (const std::exception& error) {
        set_phase(RunPhase::Failed, error.what());
    }
}

}  // namespace legofeup::ui
