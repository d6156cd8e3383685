// The link registry (lessons/links/link_registry.hpp): every address goes to the one kind
// that takes it, a malformed one or a foreign option is refused naming the option and value,
// and a planned udp link runs a lap against a real server, as lockstep does, and says what
// it can do and how it went.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/lessons/links/link_registry.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "support/test_server.hpp"

namespace legofeup {
namespace {

/// The problem `request` is refused with, or "" when it is planned.
std::string refusal(const lessons::LinkRequest& request) {
    try {
        lessons::plan_link(request);
    } catch (const lessons::InputError& error) {
        return error.what();
    }
    return {};
}

lessons::LinkRequest address(std::string text) {
    lessons::LinkRequest request;
    request.address = std::move(text);
    return request;
}

TEST(LinkRegistry, EachKindHasItsOwnNameAndEveryAddressAtMostOneKind) {
    std::set<std::string_view> names;
    for (const lessons::LinkKind* kind : lessons::built_in_links()) {
        EXPECT_TRUE(names.insert(kind->name).second) << kind->name;
        EXPECT_FALSE(kind->forms.empty()) << kind->name;
    }
    EXPECT_EQ(names, (std::set<std::string_view>{"udp", "nxt"}));
    for (const char* text : {"udp://127.0.0.1:5600", "bt:00:16:53:01:02:03", "serial:/dev/rfcomm0",
                             "tcp:127.0.0.1:7000", "lockstep", "http://x", ""}) {
        int takers = 0;
        for (const lessons::LinkKind* kind : lessons::built_in_links()) {
            takers += kind->takes(text) ? 1 : 0;
        }
        EXPECT_LE(takers, 1) << text;
        EXPECT_EQ(lessons::link_kind_for(text) != nullptr, takers == 1) << text;
    }
    EXPECT_EQ(lessons::link_kind_for("udp://127.0.0.1:5600")->name, "udp");
    EXPECT_EQ(lessons::link_kind_for("tcp:127.0.0.1:7000")->name, "nxt");
    EXPECT_EQ(lessons::link_kind_for("lockstep"), nullptr);
}

TEST(LinkRegistry, LockstepIsNoLinkAndAnUnknownAddressListsEveryForm) {
    EXPECT_EQ(lessons::plan_link(address("lockstep")), nullptr);
    const std::string unknown = refusal(address("127.0.0.1:5600"));
    EXPECT_NE(unknown.find("--link"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("127.0.0.1:5600"), std::string::npos) << unknown;
    for (const lessons::LinkKind* kind : lessons::built_in_links()) {
        EXPECT_NE(unknown.find(kind->forms), std::string::npos) << unknown;
    }
    EXPECT_NE(unknown.find("lockstep"), std::string::npos) << unknown;
    EXPECT_EQ(lessons::link_forms().find("lockstep"), 0U);
}

TEST(LinkRegistry, AMalformedAddressIsRefusedByItsKind) {
    for (const char* text : {"udp://127.0.0.1:0", "udp://localhost:5600", "udp://1.2.3.4:99999"}) {
        const std::string why = refusal(address(text));
        EXPECT_NE(why.find(text), std::string::npos) << text << ": " << why;
        EXPECT_NE(why.find("udp://a.b.c.d:port"), std::string::npos) << text << ": " << why;
    }
    const std::string bt = refusal(address("bt:00:16:53:0G:00:01"));
    EXPECT_NE(bt.find("bt:00:16:53:0G:00:01"), std::string::npos) << bt;
}

TEST(LinkRegistry, AnOptionOfAnotherKindIsRefusedNamingIt) {
    lessons::LinkRequest relay = address("udp://127.0.0.1:5600");
    relay.relay = true;
    EXPECT_NE(refusal(relay).find("--relay"), std::string::npos) << refusal(relay);
    lessons::LinkRequest truth = address("lockstep");
    truth.truth_url = "udp://127.0.0.1:5601";
    EXPECT_NE(refusal(truth).find("--truth"), std::string::npos) << refusal(truth);
    EXPECT_NE(refusal(truth).find("udp://127.0.0.1:5601"), std::string::npos) << refusal(truth);
}

TEST(LinkRegistry, APlannedUdpLinkRunsALapAsLockstepDoesAndReportsItself) {
    lessons::RunConfig config = lessons::find_experiment("f")->config;
    config.laps = 1;
    const lessons::ResolvedRun run = lessons::resolve(config);
    const auto server = testing::start_test_server(0.0);  // lockstep time: deterministic
    const simserver::BoundPorts ports = server->ports();
    lessons::LinkRequest request = address("udp://127.0.0.1:" + std::to_string(ports.robot));
    request.truth_port = ports.truth;
    request.control_port = ports.control;
    const std::unique_ptr<lessons::LinkPlan> plan = lessons::plan_link(request);
    ASSERT_NE(plan, nullptr);
    EXPECT_EQ(plan->describe(), request.address);

    const std::unique_ptr<lessons::RobotConnection> connection = plan->connect(run);
    const lessons::LinkCapabilities can = connection->capabilities();
    EXPECT_TRUE(can.ground_truth && can.teleport && can.live_noise && can.stops_clock);
    EXPECT_FALSE(can.robot_health);
    ASSERT_NE(connection->truth_source(), nullptr);
    const lessons::RunResult over_link = lessons::run_with_link(
        run, connection->robot_link(), *connection->truth_source(), nullptr, {});
    connection->close();
    const lessons::RunResult in_process = lessons::run_lockstep(run, nullptr);
    EXPECT_EQ(over_link.metrics.steps, in_process.metrics.steps);
    ASSERT_TRUE(over_link.metrics.truth && in_process.metrics.truth);
    EXPECT_EQ(over_link.metrics.truth->final_position_error,
              in_process.metrics.truth->final_position_error);

    const lessons::LinkHealth health = connection->health();
    EXPECT_EQ(health.frames, over_link.metrics.steps + 1);  // and the reset's frame
    const nlohmann::json summary = connection->summary();
    EXPECT_EQ(summary["kind"], "udp");
    EXPECT_EQ(summary["robot"], "127.0.0.1:" + std::to_string(ports.robot));
    EXPECT_EQ(summary["truth"], "127.0.0.1:" + std::to_string(ports.truth));
    EXPECT_EQ(summary["frames_received"].get<std::uint64_t>(), health.frames);
    EXPECT_EQ(summary["server_commands_accepted"].get<std::uint64_t>(), over_link.metrics.steps)
        << summary.dump(2);
}

}  // namespace
}  // namespace legofeup
