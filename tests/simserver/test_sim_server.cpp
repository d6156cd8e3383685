// The simulator server over loopback: frames, commands, the watchdog, who holds the robot,
// control requests and malformed input (docs/protocol.md).

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "legofeup/comms/control_client.hpp"
#include "legofeup/comms/link_error.hpp"
#include "legofeup/comms/truth_receiver.hpp"
#include "legofeup/comms/udp_link.hpp"
#include "support/test_server.hpp"

namespace legofeup {
namespace {

using namespace std::chrono_literals;
using comms::ControlClient;
using comms::UdpLinkOptions;
using comms::UdpSimulatorLink;
using testing::loopback;
using testing::start_test_server;

std::unique_ptr<UdpSimulatorLink> connected_link(const simserver::SimServer& server) {
    UdpLinkOptions options;
    options.server = loopback(server.ports().robot);
    options.frame_timeout = 500ms;
    auto link = std::make_unique<UdpSimulatorLink>(options);
    link->connect();
    return link;
}

/// Waits (up to 2 s) until the server's status satisfies `ready`.
template <typename Predicate>
comms::ServerStatus wait_for_status(const simserver::SimServer& server, Predicate ready) {
    for (int i = 0; i < 200; ++i) {
        const comms::ServerStatus status = server.status();
        if (ready(status)) {
            return status;
        }
        std::this_thread::sleep_for(10ms);
    }
    return server.status();
}

TEST(SimServer, SendsAFrameEveryControlPeriodToItsClient) {
    const auto server = start_test_server(10.0);
    auto link_owner = connected_link(*server);
    UdpSimulatorLink& link = *link_owner;
    EXPECT_DOUBLE_EQ(link.control_period(), 0.05);
    EXPECT_DOUBLE_EQ(link.time_scale(), 10.0);

    auto previous = link.next_frame();
    ASSERT_TRUE(previous);
    for (int i = 0; i < 10; ++i) {
        const auto frame = link.next_frame();
        ASSERT_TRUE(frame);
        EXPECT_EQ(frame->sequence, previous->sequence + 1);
        EXPECT_NEAR(frame->time - previous->time, 0.05, 1e-6);
        previous = frame;
    }
}

TEST(SimServer, PacesSimulatedTimeToRealTimeTimesTheScale) {
    const auto started = std::chrono::steady_clock::now();
    const auto server = start_test_server(10.0);  // 200 periods of 0.05 s per real second
    std::this_thread::sleep_for(1s);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const comms::ServerStatus status = server->status();
    const double expected = elapsed * 10.0 / 0.05;
    // Late periods are caught up (up to 50 ms behind), so only a stalled machine lags.
    EXPECT_LE(static_cast<double>(status.steps), expected + 1.0);
    EXPECT_GE(static_cast<double>(status.steps), 0.9 * expected);
}

TEST(SimServer, CommandsDriveTheRobotAndTheTruthStreamShowsIt) {
    const auto server = start_test_server(0.0);  // lockstep: every command advances a period
    comms::TruthReceiver truth(loopback(server->ports().truth));
    ControlClient control(loopback(server->ports().control));
    auto link_owner = connected_link(*server);
    UdpSimulatorLink& link = *link_owner;
    control.reset(3);
    ASSERT_TRUE(link.await_reset(1s));

    const Pose2 start = lessons::built_in_world().start;
    double last_time = 0.0;
    for (int i = 0; i < 40; ++i) {  // 2 s at 0.1 m/s
        const auto frame = link.next_frame();
        ASSERT_TRUE(frame);
        last_time = frame->time;
        link.send_command({0.1, 0.1});
    }
    truth.poll(200ms);
    const auto seen = truth.truth_at(last_time);
    ASSERT_TRUE(seen);
    EXPECT_NEAR(seen->time, last_time, 1e-6);
    EXPECT_GT(seen->pose.x - start.x, 0.15);  // ≈ 0.2 m less the motors' spin-up
    EXPECT_LT(seen->pose.x - start.x, 0.21);
    EXPECT_NEAR(seen->pose.y, start.y, 0.01);
    EXPECT_NEAR(seen->velocity.v, 0.1, 0.01);
    const auto status = wait_for_status(
        *server, [](const comms::ServerStatus& s) { return s.counters.commands_accepted >= 40; });
    EXPECT_EQ(status.counters.commands_accepted, 40U);
}

TEST(SimServer, WatchdogStopsTheMotorsWhenCommandsCeaseForTwoPeriods) {
    const auto server = start_test_server(0.0);
    comms::TruthReceiver truth(loopback(server->ports().truth));
    auto link_owner = connected_link(*server);
    UdpSimulatorLink& link = *link_owner;
    for (int i = 0; i < 20; ++i) {
        ASSERT_TRUE(link.next_frame());
        link.send_command({0.1, 0.1});
    }
    EXPECT_FALSE(link.last_flags().watchdog_stopped);
    // No more commands. The period after the last command keeps it (one lost command is
    // tolerated); after two silent periods the motors stop, flagged in the frame.
    for (int silent = 1; silent <= 2; ++silent) {
        const auto frame = link.next_frame();
        ASSERT_TRUE(frame);
        EXPECT_FALSE(link.last_flags().watchdog_stopped) << "silent period " << silent;
    }
    ASSERT_TRUE(link.next_frame());
    EXPECT_TRUE(link.last_flags().watchdog_stopped);
    double time = 0.0;
    for (int i = 0; i < 5; ++i) {  // the motors spin down (time constant 0.05 s)
        const auto frame = link.next_frame();
        ASSERT_TRUE(frame);
        time = frame->time;
    }
    truth.poll(200ms);
    const auto seen = truth.truth_at(time);
    ASSERT_TRUE(seen);
    EXPECT_LT(std::abs(seen->velocity.v), 0.005);
    EXPECT_EQ(server->status().counters.watchdog_stops, 1U);

    link.send_command({0.1, 0.1});  // a command lifts the stop
    ASSERT_TRUE(link.next_frame());
    EXPECT_FALSE(link.last_flags().watchdog_stopped);
}

TEST(SimServer, OneClientHoldsTheRobotOthersAreRefusedAndCounted) {
    const auto server = start_test_server(10.0);
    auto holder_owner = connected_link(*server);
    UdpSimulatorLink& holder = *holder_owner;

    UdpLinkOptions options;
    options.server = loopback(server->ports().robot);
    UdpSimulatorLink second(options);
    try {
        second.connect();
        FAIL() << "a second client was accepted";
    } catch (const comms::LinkError& error) {
        EXPECT_NE(std::string(error.what()).find(holder.local_endpoint().to_string()),
                  std::string::npos)
            << error.what();
    }
    for (int i = 0; i < 7; ++i) {
        second.send_command({0.3, -0.3});  // not its robot: dropped and counted
    }
    const auto status = wait_for_status(
        *server, [](const comms::ServerStatus& s) { return s.counters.unexpected_peer >= 8; });
    EXPECT_EQ(status.counters.unexpected_peer, 8U);  // the refused connect and 7 commands
    EXPECT_EQ(status.client, holder.local_endpoint());

    holder.disconnect();  // released: now the second one gets it
    EXPECT_NO_THROW(second.connect());
}

TEST(SimServer, ReleasesTheRobotWhenItsClientFallsSilent) {
    simserver::SimServerOptions options;
    options.peer_timeout = 300ms;
    const auto server = start_test_server(10.0, options);
    const auto first = connected_link(*server);  // connects, then says nothing more
    ASSERT_TRUE(first->connected());
    std::this_thread::sleep_for(450ms);
    UdpLinkOptions link_options;
    link_options.server = loopback(server->ports().robot);
    UdpSimulatorLink second(link_options);
    EXPECT_NO_THROW(second.connect());
}

TEST(SimServer, RefusesANonLoopbackBindUnlessAllowed) {
    simserver::SimServerOptions options;
    options.bind = comms::Endpoint{0, 0};  // 0.0.0.0: every interface
    try {
        simserver::SimServer server(lessons::built_in_world(), sim::RobotSpec{},
                                    sim::SimulatorSettings{}, 1, options);
        FAIL() << "bound 0.0.0.0 without allow_remote";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("--allow-remote"), std::string::npos);
    }
    options.allow_remote = true;
    EXPECT_NO_THROW(simserver::SimServer(lessons::built_in_world(), sim::RobotSpec{},
                                         sim::SimulatorSettings{}, 1, options));
}

TEST(SimServer, ResetPauseResumeTeleportAndNoiseRequests) {
    const auto server = start_test_server(20.0);
    ControlClient control(loopback(server->ports().control));
    comms::TruthReceiver truth(loopback(server->ports().truth));
    auto link_owner = connected_link(*server);
    UdpSimulatorLink& link = *link_owner;

    const comms::ServerStatus reset = control.reset(42, Pose2{0.5, 0.25, 1.0});
    EXPECT_EQ(reset.seed, 42U);
    EXPECT_EQ(reset.steps, 0U);
    ASSERT_TRUE(link.await_reset(1s));
    const auto first = link.next_frame();
    ASSERT_TRUE(first);
    EXPECT_EQ(first->time, 0.0);
    EXPECT_EQ(first->encoder_counts, (std::array<std::int32_t, 2>{0, 0}));
    truth.poll(100ms);
    const auto at_start = truth.truth_at(0.0);
    ASSERT_TRUE(at_start);
    EXPECT_NEAR(at_start->pose.x, 0.5, 1e-6);
    EXPECT_NEAR(at_start->pose.theta, 1.0, 1e-6);

    // Paused: frames keep coming, flagged, and time stands still.
    EXPECT_TRUE(control.pause().paused);
    // (Frames that left before the request may still be queued: skip those.)
    std::optional<SensorFrame> paused_frame;
    for (int i = 0; i < 50 && !(paused_frame && link.last_flags().paused); ++i) {
        paused_frame = link.next_frame();
        ASSERT_TRUE(paused_frame);
    }
    EXPECT_TRUE(link.last_flags().paused);
    const auto still = link.next_frame();
    ASSERT_TRUE(still);
    EXPECT_EQ(still->time, paused_frame->time);
    EXPECT_FALSE(control.resume().paused);
    std::optional<SensorFrame> moving;
    for (int i = 0; i < 50 && !(moving && !link.last_flags().paused); ++i) {
        moving = link.next_frame();
        ASSERT_TRUE(moving);
    }
    moving = link.next_frame();
    ASSERT_TRUE(moving);
    EXPECT_GT(moving->time, still->time);
    EXPECT_FALSE(link.last_flags().paused);

    // Teleport: inside the arena it moves the robot; outside it is refused with the reason.
    const comms::ServerStatus teleported = control.teleport(Pose2{-0.5, 0.75, -2.0});
    const double teleport_time = static_cast<double>(teleported.steps) * teleported.control_period;
    auto after = link.next_frame();  // skip frames that left before the teleport
    while (after && after->time <= teleport_time) {
        after = link.next_frame();
    }
    ASSERT_TRUE(after);
    truth.poll(100ms);
    const auto moved = truth.truth_at(after->time);
    ASSERT_TRUE(moved);
    EXPECT_NEAR(moved->pose.x, -0.5, 0.01);
    EXPECT_NEAR(moved->pose.y, 0.75, 0.01);
    // (test_placement.cpp checks the limits.)
    try {
        control.teleport(Pose2{5.0, 0.0, 0.0});
        FAIL() << "teleported outside the arena";
    } catch (const comms::LinkError& error) {
        EXPECT_NE(std::string(error.what()).find("x = 5 m: the chassis fits in"), std::string::npos)
            << error.what();
    }

    // Noise: validated by the simulator's own rules, with the field named.
    comms::NoiseSettings noise{1.01, 1.02, 0.001, 0.004};
    EXPECT_DOUBLE_EQ(control.set_noise(noise).noise.ir_noise, 0.004);
    noise.slip_noise = -1.0;
    try {
        control.set_noise(noise);
        FAIL() << "accepted a negative slip noise";
    } catch (const comms::LinkError& error) {
        EXPECT_NE(std::string(error.what()).find("slip_noise"), std::string::npos) << error.what();
    }
    EXPECT_DOUBLE_EQ(control.status().noise.slip_noise, 0.001);  // unchanged

    EXPECT_THROW(control.set_time_scale(5000.0), comms::LinkError);
    EXPECT_DOUBLE_EQ(control.set_time_scale(0.0).time_scale, 0.0);
    EXPECT_DOUBLE_EQ(control.set_time_scale(20.0).time_scale, 20.0);

    comms::ControlRequestPacket unknown;
    unknown.op = 99;
    EXPECT_EQ(control.request(unknown).result, comms::ControlResult::UnknownOp);
}

TEST(SimServer, ARetriedRequestIsAnsweredAgainButCarriedOutOnce) {
    const auto server = start_test_server(20.0);
    comms::UdpSocket socket(loopback(0));
    comms::ControlRequestPacket reset;
    reset.request_id = 77;
    reset.op = static_cast<std::uint8_t>(comms::ControlOp::Reset);
    reset.seed = 5;
    const comms::Bytes bytes = encode(reset);
    std::vector<comms::ControlReplyPacket> replies;
    for (int i = 0; i < 2; ++i) {
        socket.send_to(bytes, loopback(server->ports().control));
        const auto datagram = socket.receive(1s);
        ASSERT_TRUE(datagram);
        comms::ControlReplyPacket reply;
        ASSERT_EQ(decode(datagram->bytes, reply), comms::DecodeError::None);
        replies.push_back(reply);
        std::this_thread::sleep_for(100ms);  // time goes on between the two
    }
    EXPECT_EQ(replies[0].request_id, 77U);
    EXPECT_EQ(replies[1].sequence, replies[0].sequence);  // the very same reply
    EXPECT_EQ(server->status().counters.control_requests, 1U);
    EXPECT_GT(server->status().steps, 0U);  // not reset a second time
}

TEST(SimServer, DropsAndCountsEveryKindOfMalformedPacketAndKeepsServing) {
    const auto server = start_test_server(20.0);
    auto link_owner = connected_link(*server);
    UdpSimulatorLink& link = *link_owner;
    comms::UdpSocket stranger(loopback(0));
    const simserver::BoundPorts ports = server->ports();

    comms::CommandPacket command{1, 0.0, {0.1, 0.1}};
    const comms::Bytes good = encode(command);
    const auto altered = [&](std::size_t offset, std::uint8_t value) {
        comms::Bytes bytes = good;
        bytes.at(offset) = value;
        return bytes;
    };
    comms::Bytes oversized = good;
    oversized.resize(700, 0xAB);
    comms::Bytes nan_command = good;
    for (std::size_t i = 20; i < 28; ++i) {
        nan_command[i] = 0xFF;  // all ones: a NaN
    }
    comms::Bytes late_time = good;
    late_time[19] = 0x7F;  // time_us far beyond 2^50
    const comms::Bytes frame_to_control = encode(comms::FramePacket{});

    const auto send = [&](const comms::Bytes& bytes, std::uint16_t port, int times) {
        for (int i = 0; i < times; ++i) {
            stranger.send_to(bytes, loopback(port));
        }
    };
    send(comms::Bytes(good.begin(), good.begin() + 11), ports.robot, 1);  // truncated
    send(altered(0, 'X'), ports.truth, 2);                                // bad magic
    send(altered(4, 9), ports.control, 3);                                // bad version
    send(altered(5, 0x7E), ports.robot, 4);                               // unknown type
    send(altered(6, 99), ports.truth, 5);                                 // bad length
    send(oversized, ports.control, 6);
    send(nan_command, ports.control, 7);       // a command on the control port: wrong stream
    send(late_time, ports.robot, 8);           // bad time
    send(frame_to_control, ports.control, 9);  // wrong stream
    send(frame_to_control, ports.truth, 2);    // wrong stream: a frame to the truth port
    send(encode(comms::BarePacket{comms::PacketType::Connect, 1, 0.0}), ports.truth,
         3);  // wrong stream: a valid header-only packet of the robot stream
    send(encode(comms::BarePacket{comms::PacketType::TruthSubscribe, 1, 0.0}), ports.robot,
         4);  // wrong stream: a truth subscription to the robot port
    for (int i = 0; i < 10; ++i) {
        stranger.send_to(encode(comms::CommandPacket{static_cast<std::uint32_t>(i), 0.0, {}}),
                         loopback(ports.robot));  // a valid command from a stranger
    }

    const auto status = wait_for_status(*server, [](const comms::ServerStatus& s) {
        return s.counters.unexpected_peer >= 10 && s.counters.wrong_stream >= 25;
    });
    const comms::ServerCounters& c = status.counters;
    EXPECT_EQ(c.truncated, 1U);
    EXPECT_EQ(c.bad_magic, 2U);
    EXPECT_EQ(c.bad_version, 3U);
    EXPECT_EQ(c.unknown_type, 4U);
    EXPECT_EQ(c.bad_length, 5U);
    EXPECT_EQ(c.oversized, 6U);
    EXPECT_EQ(c.bad_time, 8U);
    EXPECT_EQ(c.wrong_stream, 25U);  // 16 to control, 5 to truth, 4 to robot
    EXPECT_EQ(c.unexpected_peer, 10U);
    EXPECT_EQ(c.non_finite, 0U);

    // None of it disturbed the client: frames still flow.
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(link.next_frame());
    }
    EXPECT_TRUE(link.connected());
}

TEST(SimServer, CountsANonFiniteCommandFromItsClient) {
    const auto server = start_test_server(20.0);
    comms::UdpSocket socket(loopback(0));
    const comms::Endpoint robot = loopback(server->ports().robot);
    socket.send_to(encode(comms::BarePacket{comms::PacketType::Connect, 1, 0.0}), robot);
    ASSERT_TRUE(socket.receive(1s));  // the connect reply
    const comms::Bytes command =
        encode(comms::CommandPacket{1, 0.0, {std::nan(""), 0.1}});  // sent as is
    socket.send_to(command, robot);
    const auto status = wait_for_status(
        *server, [](const comms::ServerStatus& s) { return s.counters.non_finite >= 1; });
    EXPECT_EQ(status.counters.non_finite, 1U);
    EXPECT_EQ(status.counters.commands_accepted, 0U);
}

}  // namespace
}  // namespace legofeup
