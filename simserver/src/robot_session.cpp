#include "robot_session.hpp"

namespace legofeup::simserver {

comms::ConnectResult RobotSession::connect(const comms::Endpoint& from, Clock::time_point now) {
    expire(now);
    if (client_ && *client_ != from) {
        return comms::ConnectResult::Busy;
    }
    if (!client_) {
        client_ = from;
        commands_.restart();  // a new client numbers its commands afresh
    }
    last_heard_ = now;
    return comms::ConnectResult::Accepted;
}

void RobotSession::disconnect(const comms::Endpoint& from) {
    if (is_client(from)) {
        client_.reset();
    }
}

void RobotSession::expire(Clock::time_point now) {
    if (client_ && now - last_heard_ >= peer_timeout_) {
        client_.reset();
    }
}

comms::Arrival RobotSession::command(std::uint32_t sequence) {
    const comms::Arrival arrival = commands_.classify(sequence);
    if (arrival == comms::Arrival::New) {
        periods_without_command_ = 0;
        watchdog_stopped_ = false;
    }
    return arrival;
}

bool RobotSession::watchdog_due() {
    if (periods_without_command_ < kWatchdogPeriods) {
        return false;
    }
    if (!watchdog_stopped_) {
        watchdog_stopped_ = true;
        ++watchdog_stops_;
    }
    return true;
}

}  // namespace legofeup::simserver
