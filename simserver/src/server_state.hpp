#pragma once
// Everything the server owns, shared by its loop (sim_server.cpp) and its control requests
// (control_requests.cpp). Only the server's own thread touches it, except `published`.

#include <deque>
#include <mutex>
#include <thread>

#include "legofeup/comms/udp_socket.hpp"
#include "legofeup/simserver/sim_server.hpp"
#include "robot_session.hpp"
#include "truth_subscribers.hpp"

namespace legofeup::simserver {

struct SimServer::State {
    State(sim::WorldSpec world, sim::RobotSpec robot, sim::SimulatorSettings settings,
          std::uint64_t seed, SimServerOptions options);

    // --- the loop (sim_server.cpp)
    void serve_once(std::chrono::microseconds longest_wait);
    Clock::time_point next_deadline(Clock::time_point now) const;
    bool step_due(Clock::time_point now) const;
    void advance(Clock::time_point now);
    void send_frame(Clock::time_point now);
    void send_truth();
    void on_robot_datagram(const comms::Datagram& datagram, Clock::time_point now);
    void on_truth_datagram(const comms::Datagram& datagram, Clock::time_point now);
    void on_control_datagram(const comms::Datagram& datagram, Clock::time_point now);
    void publish_status();
    comms::ServerStatus current_status() const;
    /// Real time between frames; meaningless in lockstep.
    Clock::duration frame_interval() const;

    // --- control requests (control_requests.cpp)
    comms::ControlReplyPacket carry_out(const comms::ControlRequestPacket& request,
                                        Clock::time_point now);
    void restart_clock(Clock::time_point now);

    sim::Simulator simulator;
    sim::RobotSpec robot;
    SimServerOptions options;
    std::uint64_t seed;

    comms::UdpSocket robot_socket;
    comms::UdpSocket truth_socket;
    comms::UdpSocket control_socket;

    RobotSession session;
    TruthSubscribers subscribers;
    comms::ServerCounters counters;

    std::uint64_t steps = 0;
    bool paused = false;
    bool reset_flag = false;  ///< the next frame is the first since a Reset request
    std::uint32_t frame_sequence = 0;
    std::uint32_t truth_sequence = 0;
    comms::Bytes latest_truth;  ///< the last GroundTruth sent, for a new subscriber
    std::uint32_t reply_sequence = 0;

    Clock::time_point next_step_at;   ///< scaled time: when the next period is due
    Clock::time_point frame_sent_at;  ///< lockstep: when the last frame went out
    bool answered = false;            ///< lockstep: a command answered the last frame

    /// Replies to the last requests, so a retried request is answered, not redone.
    struct CachedReply {
        comms::Endpoint from;
        std::uint32_t request_id = 0;
        comms::Bytes reply;
    };
    std::deque<CachedReply> recent_replies;

    mutable std::mutex published_mutex;
    comms::ServerStatus published;
    std::jthread thread;
};

}  // namespace legofeup::simserver
