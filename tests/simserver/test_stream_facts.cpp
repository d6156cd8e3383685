// What docs/protocol.md says about the truth and control streams' numbering, checked over
// loopback with raw datagrams: a new subscriber gets the latest GroundTruth at once (a renewal
// does not), every subscriber sees the same sequence number for the same period, and the
// control reply's sequence and the control_requests counter count refused requests too.

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <thread>

#include "legofeup/comms/control_client.hpp"
#include "support/test_server.hpp"

namespace legofeup {
namespace {

using namespace std::chrono_literals;
using comms::PacketType;
using testing::loopback;

void send_bare(comms::UdpSocket& socket, PacketType type, std::uint32_t sequence,
               const comms::Endpoint& to) {
    socket.send_to(encode(comms::BarePacket{type, sequence, 0.0}), to);
}

/// The GroundTruth packets that arrive within `wait`.
std::vector<comms::TruthPacket> receive_truth(comms::UdpSocket& socket,
                                              std::chrono::milliseconds wait) {
    std::vector<comms::TruthPacket> packets;
    const auto until = std::chrono::steady_clock::now() + wait;
    while (std::chrono::steady_clock::now() < until) {
        const auto datagram = socket.receive(5ms);
        comms::TruthPacket packet;
        if (datagram && decode(datagram->bytes, packet) == comms::DecodeError::None) {
            packets.push_back(packet);
        }
    }
    return packets;
}

// Lockstep without a client: time stands still, so the packet sent at once is the only one.
TEST(TruthStream, ANewSubscriberGetsTheLatestGroundTruthAtOnceARenewalDoesNot) {
    const auto server = testing::start_test_server(0.0);
    const comms::Endpoint truth_port = loopback(server->ports().truth);
    comms::UdpSocket first(loopback(0));
    comms::UdpSocket second(loopback(0));

    send_bare(first, PacketType::TruthSubscribe, 1, truth_port);
    const auto at_once = receive_truth(first, 300ms);
    ASSERT_EQ(at_once.size(), 1U);
    EXPECT_EQ(at_once[0].truth.time, 0.0);
    EXPECT_EQ(at_once[0].truth.pose.x, lessons::built_in_world().start.x);
    EXPECT_EQ(at_once[0].truth.pose.y, lessons::built_in_world().start.y);

    send_bare(first, PacketType::TruthSubscribe, 2, truth_port);  // a renewal
    EXPECT_TRUE(receive_truth(first, 300ms).empty());

    send_bare(second, PacketType::TruthSubscribe, 1, truth_port);
    const auto again = receive_truth(second, 300ms);
    ASSERT_EQ(again.size(), 1U);
    EXPECT_EQ(again[0].sequence, at_once[0].sequence);  // the same packet: same number
    EXPECT_EQ(server->status().counters.truth_sent, 2U);

    // Unsubscribed, then subscribed again: a new subscription, so a packet at once again.
    send_bare(first, PacketType::TruthUnsubscribe, 3, truth_port);
    send_bare(first, PacketType::TruthSubscribe, 4, truth_port);
    EXPECT_EQ(receive_truth(first, 300ms).size(), 1U);
}

TEST(TruthStream, OneSequenceNumberPerPeriodSharedByEverySubscriber) {
    const auto server = testing::start_test_server(10.0);  // a period every 5 ms
    const comms::Endpoint truth_port = loopback(server->ports().truth);
    comms::UdpSocket first(loopback(0));
    send_bare(first, PacketType::TruthSubscribe, 1, truth_port);
    std::this_thread::sleep_for(100ms);  // periods pass with one subscriber only
    comms::UdpSocket second(loopback(0));
    send_bare(second, PacketType::TruthSubscribe, 1, truth_port);
    const std::vector<comms::TruthPacket> firsts = receive_truth(first, 300ms);
    const std::vector<comms::TruthPacket> seconds = receive_truth(second, 50ms);
    ASSERT_GT(firsts.size(), 20U);
    ASSERT_GT(seconds.size(), 20U);
    // The second subscriber's first packet, sent at once, is one the first one got as well.
    EXPECT_TRUE(std::any_of(firsts.begin(), firsts.end(), [&](const comms::TruthPacket& p) {
        return p.sequence == seconds.front().sequence && p.truth.time == seconds.front().truth.time;
    }));
    std::vector<comms::TruthPacket> packets = firsts;
    packets.insert(packets.end(), seconds.begin(), seconds.end());

    // sequence − period index is one constant for both: one number per period, whoever
    // receives it, and numbers go on whether or not anyone listens.
    constexpr std::uint64_t kPeriodUs = 50'000;
    const std::uint32_t offset =
        packets.front().sequence
        - static_cast<std::uint32_t>(comms::to_microseconds(packets.front().truth.time)
                                     / kPeriodUs);
    std::map<std::uint32_t, std::uint64_t> time_of_sequence;
    for (const comms::TruthPacket& packet : packets) {
        const std::uint64_t time_us = comms::to_microseconds(packet.truth.time);
        ASSERT_EQ(time_us % kPeriodUs, 0U);
        EXPECT_EQ(packet.sequence - static_cast<std::uint32_t>(time_us / kPeriodUs), offset)
            << "sequence " << packet.sequence << " at " << time_us << " µs";
        const auto [it, added] = time_of_sequence.emplace(packet.sequence, time_us);
        EXPECT_EQ(it->second, time_us) << "one number, two times";
    }
}

TEST(ControlStream, TheReplySequenceAndTheCounterCountRefusedRequestsToo) {
    const auto server = testing::start_test_server(20.0);
    comms::ControlClient control(loopback(server->ports().control));
    comms::ControlRequestPacket status;
    status.op = static_cast<std::uint8_t>(comms::ControlOp::Status);
    const comms::ControlReplyPacket before = control.request(status);
    EXPECT_EQ(before.sequence, before.status.counters.control_requests);

    comms::ControlRequestPacket outside;
    outside.op = static_cast<std::uint8_t>(comms::ControlOp::Teleport);
    outside.pose = {5.0, 0.0, 0.0};
    const comms::ControlReplyPacket refused = control.request(outside);
    EXPECT_EQ(refused.result, comms::ControlResult::Rejected);
    EXPECT_EQ(refused.sequence, before.sequence + 1);
    EXPECT_EQ(refused.status.counters.control_requests,
              before.status.counters.control_requests + 1);

    comms::ControlRequestPacket unknown;
    unknown.op = 42;
    const comms::ControlReplyPacket unknown_reply = control.request(unknown);
    EXPECT_EQ(unknown_reply.result, comms::ControlResult::UnknownOp);
    EXPECT_EQ(unknown_reply.sequence, before.sequence + 2);
    EXPECT_EQ(unknown_reply.status.counters.control_requests,
              before.status.counters.control_requests + 2);
}

}  // namespace
}  // namespace legofeup
