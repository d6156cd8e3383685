// The GUI's run against an emulated NXT over TCP, as the real robot is driven: the link's
// quality is reported, a brick that goes away fails the run with the link's reason, and a new
// run connects again. Built with the NXT (LEGOFEUP_WITH_NXT) only.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/nxt_run.hpp"
#include "legofeup/nxtemu/emulated_nxt.hpp"
#include "legofeup/ui/session/live_run.hpp"
#include "support/live_run_waits.hpp"

namespace legofeup::ui {
namespace {

using namespace std::chrono_literals;
using testing::collect_until;
using testing::wait_for_end;

/// An emulated NXT on the run's simulator, served on a free loopback TCP port with
/// Bluetooth's latency (30 ms each way), and the factory that connects to it as the GUI does.
struct ServedBrick {
    lessons::ResolvedRun run;
    std::unique_ptr<nxtemu::EmulatedNxt> brick;
    lessons::NxtTarget target;

    explicit ServedBrick(const std::string& experiment)
        : run(lessons::resolve(lessons::find_experiment(experiment)->config)) {
        nxtemu::EmulatorOptions options;
        options.run = run.config;
        options.link.latency_up = 30ms;
        options.link.latency_down = 30ms;
        brick = std::make_unique<nxtemu::EmulatedNxt>(std::move(options));
        const std::uint16_t port = brick->serve_tcp();
        target.link.address = {comms::nxt::TransportKind::Tcp, "127.0.0.1", port};
        target.truth = brick->truth_endpoint();
    }

    LiveRun::ConnectionFactory connect() const {
        return [target = target] { return lessons::connect_nxt(target); };
    }
};

TEST(LiveRunOnNxt, AnEmulatedBrickOverTcpRunsTheLoopWithTheLinksQualityAndTruth) {
    ServedBrick emulated("f");
    std::vector<RunSample> samples;
    LiveRun live(emulated.run, emulated.connect(), [] {});
    // 30 ms each way: a cycle is one round trip (≈ 60 ms), so 40 frames take ~2.5 s.
    collect_until(live, samples, [](const auto& s) { return s.size() >= 40; });
    ASSERT_GE(samples.size(), 40U) << live.status().message;
    const LiveRunStatus status = live.status();
    EXPECT_EQ(status.phase, RunPhase::Running);
    EXPECT_NE(status.link.find("tcp:127.0.0.1:"), std::string::npos) << status.link;
    ASSERT_NE(status.robot_health(), nullptr);  // a robot's own health: the brick's
    ASSERT_TRUE(status.health.has_value());
    EXPECT_EQ(status.health->state, lessons::LinkState::Connected);
    EXPECT_GT(status.health->rate_hz(), 5.0);
    EXPECT_LT(status.health->rate_hz(),
              25.0);  // the latency is felt: not the simulator's pace
    EXPECT_GE(status.health->frames, 40U);
    ASSERT_TRUE(status.health->battery_millivolts.has_value());
    EXPECT_EQ(*status.health->battery_millivolts, 7800);  // the emulated firmware's default
    // A brick: its own health, truth only through the emulator's simulator, nothing else.
    EXPECT_TRUE(status.capabilities.robot_health);
    EXPECT_TRUE(status.capabilities.ground_truth);
    EXPECT_FALSE(status.capabilities.teleport);
    EXPECT_FALSE(status.capabilities.live_noise);
    EXPECT_FALSE(status.capabilities.stops_clock);
    EXPECT_NE(status.link.find(status.health->address), std::string::npos);
    const RunSample& last = samples.back();
    ASSERT_TRUE(last.truth.has_value());  // the emulator's simulator tells the truth
    EXPECT_TRUE(std::isfinite(last.nees));
    // The robot moves along the path, and the estimate follows the truth.
    const auto first = std::find_if(samples.begin(), samples.end(),
                                    [](const RunSample& s) { return s.truth.has_value(); });
    ASSERT_NE(first, samples.end());
    EXPECT_GT(std::hypot(last.truth->pose.x - first->truth->pose.x,
                         last.truth->pose.y - first->truth->pose.y),
              0.05);
    EXPECT_LT(std::hypot(last.snapshot.estimate.x() - last.truth->pose.x,
                         last.snapshot.estimate.y() - last.truth->pose.y),
              0.1);
}

TEST(LiveRunOnNxt, ABrickThatGoesAwayFailsTheRunNamingTheLinkAndANewRunReconnects) {
    auto emulated = std::make_unique<ServedBrick>("f");
    const std::string address = emulated->target.link.address.to_string();
    std::vector<RunSample> samples;
    {
        LiveRun live(emulated->run, emulated->connect(), [] {});
        collect_until(live, samples, [](const auto& s) { return s.size() >= 10; });
        ASSERT_GE(samples.size(), 10U) << live.status().message;
        emulated->brick->stop();  // the brick is switched off mid-run
        const LiveRunStatus status = wait_for_end(live, 10s);
        EXPECT_EQ(status.phase, RunPhase::Failed);
        EXPECT_NE(status.message.find(address), std::string::npos) << status.message;
        ASSERT_NE(status.robot_health(), nullptr);
        ASSERT_TRUE(status.health.has_value());
        EXPECT_EQ(status.health->state, lessons::LinkState::Failed);
    }
    // Reconnecting: a new run on a new brick, in the same process, works.
    emulated = std::make_unique<ServedBrick>("f");
    samples.clear();
    LiveRun again(emulated->run, emulated->connect(), [] {});
    collect_until(again, samples, [](const auto& s) { return s.size() >= 10; });
    ASSERT_GE(samples.size(), 10U) << again.status().message;
    EXPECT_EQ(again.status().phase, RunPhase::Running);
    EXPECT_EQ(again.status().health->state, lessons::LinkState::Connected);
}

}  // namespace
}  // namespace legofeup::ui
