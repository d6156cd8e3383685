// The runner over a link that loses frames, times out and repeats paused frames: one
// predict-only step per missed period, none for a paused one, and the run still finishes.

#include <gtest/gtest.h>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/link_run.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

/// The in-process simulator behind a link that misbehaves on a fixed schedule.
class FlakyLink final : public RobotLink {
  public:
    explicit FlakyLink(sim::Simulator& simulator) : inner_(simulator) {}

    // Like a server in real time: every period the simulator moves on and sends a frame
    // numbered in turn, which may be lost (noticed by a timeout, or only by the next
    // frame's sequence gap); while paused it repeats its latest frame under a new number.
    std::optional<SensorFrame> next_frame() override {
        ++calls_;
        // (Never right after a timeout: that repeat would be the lost frame's time, a frame
        // the runner rightly takes as the late arrival of the period it predicted over.)
        if (calls_ > 1 && calls_ % 13 == 0 && (calls_ - 1) % 11 != 0) {
            ++repeated;
            SensorFrame again = latest_;
            again.sequence = ++sequence_;
            return again;
        }
        SensorFrame frame = send_next();
        if (calls_ > 1 && calls_ % 11 == 0) {
            ++timeouts;  // lost, and nothing else came in time
            return std::nullopt;
        }
        if (calls_ > 1 && calls_ % 7 == 3) {
            ++lost;  // lost, but the next one came at once
            frame = send_next();
        }
        return frame;
    }
    void send_command(const WheelSpeeds& command) override { inner_.send_command(command); }

    int timeouts = 0;
    int lost = 0;
    int repeated = 0;
    int periods = 0;  ///< control periods the simulator ran (frames sent)

  private:
    SensorFrame send_next() {
        ++periods;
        latest_ = *inner_.next_frame();
        latest_.sequence = ++sequence_;
        return latest_;
    }

    sim::LockstepLink inner_;
    int calls_ = 0;
    std::uint32_t sequence_ = 100;
    SensorFrame latest_;
};

class SimulatorTruth final : public TruthSource {
  public:
    explicit SimulatorTruth(const sim::Simulator& simulator) : simulator_(simulator) {}
    std::optional<GroundTruth> truth_at(double) override { return simulator_.ground_truth(); }

  private:
    const sim::Simulator& simulator_;
};

class MissingCounter final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth&) override {
        ++steps;
        missing += snapshot.frame_missing ? 1 : 0;
    }
    int steps = 0;
    int missing = 0;
};

TEST(LinkRun, OnePredictOnlyStepPerMissedPeriodAndNoneForAPausedFrame) {
    RunConfig config = find_experiment("f")->config;
    config.laps = 1;
    const ResolvedRun run = resolve(config);
    sim::WorldSpec world = run.world;
    world.start = run.true_start;
    sim::Simulator simulator(world, run.robot, run.config.simulator, run.config.seed);
    FlakyLink link(simulator);
    SimulatorTruth truth(simulator);
    MissingCounter counter;

    const RunResult result = run_with_link(run, link, truth, &counter);

    EXPECT_TRUE(result.routine_finished);
    EXPECT_GT(link.lost, 100);
    EXPECT_GT(link.timeouts, 100);
    EXPECT_GT(link.repeated, 50);
    // Every lost frame and every timeout is one period run without a frame; a repeated
    // (paused) frame is not a period at all.
    EXPECT_EQ(result.frames_missing, static_cast<std::uint64_t>(link.lost + link.timeouts));
    EXPECT_EQ(counter.missing, link.lost + link.timeouts);
    // One loop step per control period (the run may stop just before the last frame).
    EXPECT_NEAR(counter.steps, link.periods, 1);
    // Still localised: the frames that did come carry all the motion (cumulative counts).
    EXPECT_LT(result.metrics.truth.value().final_position_error, 0.1);
}

}  // namespace
}  // namespace legofeup::lessons
