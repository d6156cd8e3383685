#include "legofeup/simserver/sim_server.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "server_state.hpp"

namespace legofeup::simserver {
namespace {

using namespace std::chrono_literals;
using comms::PacketType;

/// The loop looks at its stop token at least this often.
constexpr std::chrono::microseconds kLongestWait = 100ms;
/// How far behind real time the server may fall and still catch up (see advance()).
constexpr Clock::duration kCatchUpLimit = 50ms;

std::uint16_t port_or_free(const SimServerOptions& options, std::uint16_t port) {
    return options.bind.port == 0 ? 0 : port;
}

}  // namespace

std::vector<ConfigIssue> validate(const SimServerOptions& options) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range_or_zero("server.time_scale", options.time_scale, 0.05, 1000.0);
    if (!options.bind.is_loopback() && !options.allow_remote) {
        issues.push_back({"server.bind", options.bind.to_string(),
                          "not a loopback address: the simulator would take commands from the "
                          "network without authentication; allow it explicitly "
                          "(legofeup-sim --allow-remote) if that is what you want"});
    }
    check.require(options.peer_timeout.count() > 0, "server.peer_timeout",
                  static_cast<double>(options.peer_timeout.count()), "must be positive (ms)");
    check.require(options.lockstep_patience.count() > 0, "server.lockstep_patience",
                  static_cast<double>(options.lockstep_patience.count()), "must be positive (ms)");
    return issues;
}

SimServer::State::State(sim::WorldSpec world, sim::RobotSpec robot_spec,
                        sim::SimulatorSettings settings, std::uint64_t seed_value,
                        SimServerOptions server_options)
    : simulator(std::move(world), robot_spec, settings, seed_value),
      robot(std::move(robot_spec)),
      options(server_options),
      seed(seed_value),
      robot_socket(options.bind),
      truth_socket(options.bind.with_port(port_or_free(options, options.truth_port))),
      control_socket(options.bind.with_port(port_or_free(options, options.control_port))),
      session(options.peer_timeout) {
    restart_clock(Clock::now());
    send_truth();  // to nobody yet: the packet a first subscriber gets at once
    publish_status();
}

Clock::duration SimServer::State::frame_interval() const {
    const double seconds = simulator.settings().control_period / options.time_scale;
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

void SimServer::State::restart_clock(Clock::time_point now) {
    next_step_at = now + (options.time_scale > 0.0 ? frame_interval() : Clock::duration(0));
    frame_sent_at = now;
    answered = false;
}

Clock::time_point SimServer::State::next_deadline(Clock::time_point now) const {
    if (options.time_scale > 0.0) {
        return next_step_at;
    }
    if (!session.client()) {
        return now + kLongestWait;  // lockstep without a client: time stands still
    }
    return answered && !paused ? now : frame_sent_at + options.lockstep_patience;
}

bool SimServer::State::step_due(Clock::time_point now) const {
    if (options.time_scale > 0.0) {
        return now >= next_step_at;
    }
    return session.client()
           && ((answered && !paused) || now >= frame_sent_at + options.lockstep_patience);
}

void SimServer::State::advance(Clock::time_point now) {
    if (!paused) {
        if (session.watchdog_due()) {
            simulator.set_wheel_command(WheelSpeeds{});
        }
        simulator.step_control_period();
        session.period_passed();
        ++steps;
        send_truth();
    }
    send_frame(now);  // paused: the same time and counts again, flagged, to keep clients told
    if (options.time_scale > 0.0) {
        const Clock::duration interval = frame_interval();
        next_step_at += interval;
        // A short delay (the scheduler, at 1 kHz) is caught up by stepping the late periods
        // at once, so simulated time stays locked to real time. Beyond kCatchUpLimit (or a
        // period, if longer) the machine stalled: count it and resume from now rather than
        // firing a long burst of frames.
        if (now - next_step_at > std::max(interval, kCatchUpLimit)) {
            ++counters.overruns;
            next_step_at = now + interval;
        }
    }
}

void SimServer::State::send_truth() {
    // One packet, one sequence number, for every subscriber (and for none).
    latest_truth = encode(comms::TruthPacket{++truth_sequence, simulator.ground_truth()});
    subscribers.for_each([&](const comms::Endpoint& to) {
        truth_socket.send_to(latest_truth, to);
        ++counters.truth_sent;
    });
}

void SimServer::State::send_frame(Clock::time_point now) {
    comms::FramePacket packet;
    packet.frame = simulator.sensor_frame();
    // The server numbers frames itself: the sequence never restarts, not even on reset.
    packet.frame.sequence = ++frame_sequence;
    packet.flags = {session.watchdog_stopped(), paused, reset_flag};
    frame_sent_at = now;
    answered = false;
    if (const auto& client = session.client()) {
        robot_socket.send_to(encode(packet), *client);
        ++counters.frames_sent;
        reset_flag = false;
    }
}

void SimServer::State::on_robot_datagram(const comms::Datagram& datagram, Clock::time_point now) {
    comms::PacketHeader header;
    if (const auto error = decode_header(datagram.bytes, header);
        error != comms::DecodeError::None) {
        count_decode_error(counters, error);
        return;
    }
    switch (header.type) {
        case PacketType::Connect: {
            const bool new_client = !session.is_client(datagram.from);
            const comms::ConnectResult result = session.connect(datagram.from, now);
            if (result == comms::ConnectResult::Busy) {
                ++counters.unexpected_peer;
            }
            comms::ConnectReplyPacket reply;
            reply.sequence = header.sequence;
            reply.time = simulator.time();
            reply.result = result;
            reply.holder = session.client().value_or(datagram.from);
            reply.control_period = simulator.settings().control_period;
            reply.time_scale = options.time_scale;
            robot_socket.send_to(encode(reply), datagram.from);
            if (result == comms::ConnectResult::Accepted && new_client) {
                send_frame(now);  // the newcomer's encoder reference, without waiting a period
            }
            return;
        }
        case PacketType::Disconnect:
        case PacketType::WheelCommand:
            break;
        default:
            ++counters.wrong_stream;
            return;
    }
    if (!session.is_client(datagram.from)) {
        ++counters.unexpected_peer;
        return;
    }
    session.heard_from_client(now);
    if (header.type == PacketType::Disconnect) {
        session.disconnect(datagram.from);
        simulator.set_wheel_command(WheelSpeeds{});
        session.motors_stopped();
        return;
    }
    comms::CommandPacket command;
    if (const auto error = decode(datagram.bytes, command); error != comms::DecodeError::None) {
        count_decode_error(counters, error);
        return;
    }
    if (session.command(command.sequence) != comms::Arrival::New) {
        return;  // duplicate or late: counted by the session's window, never applied
    }
    simulator.set_wheel_command(command.wheels);
    if (comms::to_microseconds(command.answers_time) >= comms::to_microseconds(simulator.time())) {
        answered = true;
    }
}

void SimServer::State::on_truth_datagram(const comms::Datagram& datagram, Clock::time_point now) {
    comms::BarePacket packet;
    // A datagram longer than the receive buffer arrives cut to kMaxPacketSize + 1 bytes,
    // so it decodes as oversized like any other too-long packet.
    const auto error = decode(datagram.bytes, packet);
    if (error != comms::DecodeError::None) {
        count_decode_error(counters, error);
    } else if (packet.type == PacketType::TruthSubscribe) {
        // A newcomer gets the latest packet again at once, so a display knows where the robot
        // is even while time stands still (paused, or lockstep without a client).
        if (subscribers.subscribe(datagram.from, now) == TruthSubscribers::Outcome::Added) {
            truth_socket.send_to(latest_truth, datagram.from);
            ++counters.truth_sent;
        }
    } else if (packet.type == PacketType::TruthUnsubscribe) {
        subscribers.unsubscribe(datagram.from);
    } else {
        ++counters.wrong_stream;
    }
}

void SimServer::State::on_control_datagram(const comms::Datagram& datagram, Clock::time_point now) {
    comms::ControlRequestPacket request;
    // A datagram longer than the receive buffer arrives cut to kMaxPacketSize + 1 bytes,
    // so it decodes as oversized like any other too-long packet.
    const auto error = decode(datagram.bytes, request);
    if (error != comms::DecodeError::None) {
        count_decode_error(counters, error);
        return;
    }
    for (const CachedReply& cached : recent_replies) {
        if (cached.from == datagram.from && cached.request_id == request.request_id) {
            control_socket.send_to(cached.reply, datagram.from);  // a retry: answer, not redo
            return;
        }
    }
    ++counters.control_requests;
    comms::Bytes reply = encode(carry_out(request, now));
    control_socket.send_to(reply, datagram.from);
    recent_replies.push_back({datagram.from, request.request_id, std::move(reply)});
    if (recent_replies.size() > 16) {
        recent_replies.pop_front();
    }
}

void SimServer::State::serve_once(std::chrono::microseconds longest_wait) {
    Clock::time_point now = Clock::now();
    const auto until_deadline =
        std::chrono::duration_cast<std::chrono::microseconds>(next_deadline(now) - now);
    const std::array<comms::UdpSocket*, 3> sockets{&robot_socket, &truth_socket, &control_socket};
    const std::vector<bool> readable = comms::wait_readable(
        sockets, std::clamp(until_deadline, std::chrono::microseconds(0), longest_wait));
    now = Clock::now();
    // Drain each socket that has datagrams: one slow reader would otherwise let the kernel
    // buffer fill and drop what matters (commands) behind what does not.
    for (std::size_t i = 0; i < sockets.size(); ++i) {
        if (!readable[i]) {
            continue;
        }
        while (const auto datagram = sockets[i]->receive(std::chrono::microseconds(0))) {
            if (i == 0) {
                on_robot_datagram(*datagram, now);
            } else if (i == 1) {
                on_truth_datagram(*datagram, now);
            } else {
                on_control_datagram(*datagram, now);
            }
        }
    }
    now = Clock::now();
    session.expire(now);
    subscribers.expire(now);
    if (step_due(now)) {
        advance(now);
    }
    publish_status();
}

comms::ServerStatus SimServer::State::current_status() const {
    comms::ServerStatus status;
    status.steps = steps;
    status.control_period = simulator.settings().control_period;
    status.time_scale = options.time_scale;
    status.seed = seed;
    status.noise = {robot.wheel_diameter_ratio, robot.wheel_base_ratio, robot.slip_noise,
                    robot.ir_noise};
    status.paused = paused;
    status.watchdog_stopped = session.watchdog_stopped();
    status.client_connected = session.client().has_value();
    status.client = session.client().value_or(comms::Endpoint{0, 0});
    status.world_name = simulator.world().name;
    status.counters = counters;
    const comms::SequenceCounts& commands = session.command_counts();
    status.counters.commands_accepted = commands.accepted;
    status.counters.commands_duplicate = commands.duplicate;
    status.counters.commands_late = commands.late;
    status.counters.commands_missing = commands.missing;
    status.counters.watchdog_stops = session.watchdog_stops();
    return status;
}

void SimServer::State::publish_status() {
    comms::ServerStatus status = current_status();
    const std::scoped_lock lock(published_mutex);
    published = std::move(status);
}

SimServer::SimServer(sim::WorldSpec world, sim::RobotSpec robot, sim::SimulatorSettings settings,
                     std::uint64_t seed, SimServerOptions options) {
    if (const auto issues = validate(options); !issues.empty()) {
        throw invalid_configuration("server", issues);
    }
    state_ = std::make_unique<State>(std::move(world), std::move(robot), settings, seed, options);
}

SimServer::~SimServer() {
    stop();
}

BoundPorts SimServer::ports() const {
    return {state_->robot_socket.local_endpoint().port, state_->truth_socket.local_endpoint().port,
            state_->control_socket.local_endpoint().port};
}

void SimServer::run(std::stop_token stop) {
    while (!stop.stop_requested()) {
        state_->serve_once(kLongestWait);
    }
}

void SimServer::start() {
    if (!state_->thread.joinable()) {
        state_->thread = std::jthread([this](std::stop_token stop) { run(std::move(stop)); });
    }
}

void SimServer::stop() {
    if (state_ && state_->thread.joinable()) {
        state_->thread.request_stop();
        state_->thread.join();
    }
}

comms::ServerStatus SimServer::status() const {
    const std::scoped_lock lock(state_->published_mutex);
    return state_->published;
}

}  // namespace legofeup::simserver
