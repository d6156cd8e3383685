// The GUI's run on its worker thread, against a simulator server on loopback: it runs, takes
// changes between steps, drives by hand, pauses, and reports a dead link or a connection that
// cannot be made instead of hanging. Against an emulated NXT: test_live_run_on_nxt.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "legofeup/comms/link_error.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/udp_run.hpp"
#include "legofeup/simserver/sim_server.hpp"
#include "legofeup/ui/session/live_run.hpp"
#include "support/live_run_waits.hpp"

namespace legofeup::ui {
namespace {

using testing::collect_until;
using testing::wait_for_end;

using namespace std::chrono_literals;

/// A server with the run's world, robot and timing, on free loopback ports, 10× real time.
struct ServedRun {
    lessons::ResolvedRun run;
    std::unique_ptr<simserver::SimServer> server;
    lessons::UdpTarget target;

    explicit ServedRun(const std::string& experiment, double time_scale = 10.0)
        : ServedRun(lessons::find_experiment(experiment)->config, time_scale) {}

    ServedRun(const lessons::RunConfig& config, double time_scale) : run(lessons::resolve(config)) {
        simserver::SimServerOptions options;
        options.bind = comms::Endpoint{0x7F000001, 0};
        options.time_scale = time_scale;
        server = std::make_unique<simserver::SimServer>(run.world, run.robot, run.config.simulator,
                                                        1, options);
        server->start();
        const simserver::BoundPorts ports = server->ports();
        target = {options.bind.with_port(ports.robot), options.bind.with_port(ports.truth),
                  options.bind.with_port(ports.control)};
    }

    LiveRun::ConnectionFactory connect() const { return udp(run, target); }

    static LiveRun::ConnectionFactory udp(lessons::ResolvedRun run, lessons::UdpTarget target) {
        return [run = std::move(run), target]() -> std::unique_ptr<lessons::RobotConnection> {
            return std::make_unique<lessons::UdpRobotConnection>(run, target);
        };
    }
};

TEST(LiveRun, RunsTheLoopAgainstTheServerWithTruthAndConsecutiveSteps) {
    ServedRun served("f");
    std::vector<RunSample> samples;
    LiveRun live(served.run, served.connect(), [] {});
    collect_until(live, samples, [](const auto& s) { return s.size() >= 100; });
    ASSERT_GE(samples.size(), 100U);
    EXPECT_EQ(live.status().phase, RunPhase::Running);
    for (std::size_t i = 1; i < samples.size(); ++i) {
        EXPECT_EQ(samples[i].snapshot.step, samples[i - 1].snapshot.step + 1);
    }
    const RunSample& last = samples.back();
    ASSERT_TRUE(last.truth.has_value());
    // Five seconds in, the tuned filter is within a few centimetres of the truth.
    EXPECT_LT(std::hypot(last.snapshot.estimate.x() - last.truth->pose.x,
                         last.snapshot.estimate.y() - last.truth->pose.y),
              0.05);
    EXPECT_TRUE(std::isfinite(last.nees));
    EXPECT_EQ(last.particles, nullptr);  // an EKF has no cloud to draw
    // The connection says what a simulator can do, and its stream's health.
    const LiveRunStatus status = live.status();
    EXPECT_TRUE(status.capabilities.ground_truth);
    EXPECT_TRUE(status.capabilities.teleport);
    EXPECT_TRUE(status.capabilities.live_noise);
    EXPECT_TRUE(status.capabilities.stops_clock);
    EXPECT_FALSE(status.capabilities.robot_health);
    EXPECT_EQ(status.robot_health(), nullptr);
    ASSERT_TRUE(status.health.has_value());
    EXPECT_EQ(status.health->state, lessons::LinkState::Connected);
    EXPECT_EQ(status.health->address, status.link);
    EXPECT_GE(status.health->frames, 100U);
    EXPECT_FALSE(status.health->battery_millivolts.has_value());
}

TEST(LiveRun, TheParticleFilterSendsItsThinnedCloudWithEverySample) {
    lessons::RunConfig config = lessons::find_experiment("f")->config;
    config.lesson.kind = FilterKind::Pf;
    config.lesson.particles.particle_count = 3000;
    ServedRun served(config, 10.0);
    std::vector<RunSample> samples;
    LiveRun live(served.run, served.connect(), [] {});
    collect_until(live, samples, [](const auto& s) { return s.size() >= 40; });
    ASSERT_GE(samples.size(), 40U);
    for (const RunSample& sample : samples) {
        ASSERT_NE(sample.particles, nullptr) << sample.snapshot.step;
        EXPECT_EQ(sample.snapshot.particles.count, 3000);
        // Every third particle: 1,000 points, each weighted relative to the heaviest.
        ASSERT_EQ(sample.particles->size(), kParticlesShown);
        double total = 0.0;
        Vector2 mean = Vector2::Zero();
        float heaviest = 0.0F;
        for (const ParticlePoint& p : *sample.particles) {
            ASSERT_GT(p.weight, 0.0F);
            heaviest = std::max(heaviest, p.weight);
            total += widen(p.weight);
            mean += widen(p.weight) * Vector2(widen(p.x), widen(p.y));
        }
        EXPECT_FLOAT_EQ(heaviest, 1.0F);
        // The points' weighted mean is the estimate's, to within a small share of σ: a third
        // of the cloud, so about 0.03 σ off (and metres off for a wrong column).
        mean /= total;
        const StateVector& x = sample.snapshot.estimate;
        const StateCovariance& P = sample.snapshot.covariance;
        EXPECT_NEAR(mean.x(), x(kX), 0.5 * std::sqrt(P(kX, kX)) + 1e-3);
        EXPECT_NEAR(mean.y(), x(kY), 0.5 * std::sqrt(P(kY, kY)) + 1e-3);
    }
    // The samples of one run carry clouds of their own, not one shared and overwritten.
    EXPECT_NE(samples.front().particles.get(), samples.back().particles.get());
}

TEST(LiveRun, NotifiesOncePerBatchNotOncePerSample) {
    ServedRun served("f");
    std::atomic<int> notifications{0};
    LiveRun live(served.run, served.connect(), [&] { ++notifications; });
    std::this_thread::sleep_for(1s);  // ~200 steps at 10×, none taken
    const int before = notifications.load();
    const std::size_t taken = live.take_samples().size();
    EXPECT_GE(taken, 50U);
    EXPECT_LE(before, 3);  // the connection, the first batch (and perhaps Running)
}

TEST(LiveRun, KeyboardDrivingTakesOverFromThePathAndMovesTheRobotAtTheCommandedSpeed) {
    ServedRun served("f");
    std::vector<RunSample> samples;
    LiveRun live(served.run, served.connect(), [] {});
    live.set_manual_driving(true);
    live.set_manual_command({0.0, 0.5});  // turn on the spot
    collect_until(live, samples, [](const auto& s) { return s.size() >= 60; });
    ASSERT_GE(samples.size(), 60U);
    const RunSample& last = samples.back();
    EXPECT_NEAR(last.snapshot.velocity.v, 0.0, 1e-12);
    EXPECT_NEAR(last.snapshot.velocity.w, 0.5, 1e-12);
    ASSERT_TRUE(last.truth.has_value());
    EXPECT_NEAR(last.truth->velocity.w, 0.5, 0.1);  // the simulated robot really turns
    EXPECT_LT(std::abs(last.truth->velocity.v), 0.02);
}

TEST(LiveRun, ANewConfigurationTakesEffectAtTheNextStep) {
    ServedRun served("f");
    std::vector<RunSample> samples;
    LiveRun live(served.run, served.connect(), [] {});
    collect_until(live, samples, [](const auto& s) { return s.size() >= 20; });
    lessons::RunConfig config = served.run.config;
    config.motion.v_ref = 0.05;
    live.reconfigure(lessons::resolve(config));
    const std::size_t changed_at = samples.size();
    collect_until(live, samples, [&](const auto& s) { return s.size() >= changed_at + 40; });
    ASSERT_GE(samples.size(), changed_at + 40);
    EXPECT_GT(samples[changed_at - 1].snapshot.velocity.v, 0.09);  // V_ref = 0.1 m/s before
    EXPECT_LE(samples.back().snapshot.velocity.v, 0.05 + 1e-12);
}

TEST(LiveRun, PauseFreezesSimulatedTimeAndResumeContinues) {
    ServedRun served("f");
    std::vector<RunSample> samples;
    LiveRun live(served.run, served.connect(), [] {});
    collect_until(live, samples, [](const auto& s) { return s.size() >= 20; });
    live.set_paused(true);
    // The worker takes the request at its next step; wait for it (a loaded machine is slow).
    for (int i = 0; i < 500 && live.status().phase != RunPhase::Paused; ++i) {
        std::this_thread::sleep_for(10ms);
    }
    ASSERT_EQ(live.status().phase, RunPhase::Paused);
    std::this_thread::sleep_for(300ms);  // frames already under way are still taken
    for (RunSample& sample : live.take_samples()) {
        samples.push_back(std::move(sample));
    }
    const std::size_t paused_count = samples.size();
    std::this_thread::sleep_for(300ms);
    EXPECT_TRUE(live.take_samples().empty());  // no steps while paused
    live.set_paused(false);
    collect_until(live, samples, [&](const auto& s) { return s.size() >= paused_count + 20; });
    EXPECT_EQ(live.status().phase, RunPhase::Running);
    EXPECT_GE(samples.size(), paused_count + 20);
}

TEST(LiveRun, ANoServerAddressFailsWithAMessageInsteadOfHanging) {
    const lessons::ResolvedRun run = lessons::resolve(lessons::find_experiment("f")->config);
    // A port nobody serves on (the server picks free ports; this one was just released).
    std::uint16_t port = 0;
    {
        ServedRun served("f");
        port = served.server->ports().robot;
    }
    const comms::Endpoint nowhere{0x7F000001, port};
    LiveRun live(
        run,
        ServedRun::udp(run, {nowhere, nowhere.with_port(static_cast<std::uint16_t>(port + 1)),
                             nowhere.with_port(static_cast<std::uint16_t>(port + 2))}),
        [] {});
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (live.status().phase == RunPhase::Connecting
           && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(20ms);
    }
    const LiveRunStatus status = live.status();
    EXPECT_EQ(status.phase, RunPhase::Failed);
    EXPECT_NE(status.message.find("no reply"), std::string::npos) << status.message;
}

TEST(LiveRunOnNxt, AConnectionThatCannotBeMadeFailsWithItsReason) {
    LiveRun live(
        lessons::resolve(lessons::find_experiment("f")->config),
        []() -> std::unique_ptr<lessons::RobotConnection> {
            throw comms::LinkError("tcp:127.0.0.1:9: connection refused");
        },
        [] {});
    const LiveRunStatus status = wait_for_end(live, 5s);
    EXPECT_EQ(status.phase, RunPhase::Failed);
    EXPECT_EQ(status.message, "tcp:127.0.0.1:9: connection refused");
}

}  // namespace
}  // namespace legofeup::ui
