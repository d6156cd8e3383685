// Issue 20's bar for the association gates: a robot bumped 15 cm sideways, towards the wall
// it follows (the LegoFeup lesson's step g), re-acquires that wall with the Mahalanobis gate
// (step h) and not with the paper's fixed gates — the same bump on the same seed, only the
// gate differs.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kBumpTime = 5.0;  // s: step g's [step.config.displacement] time
constexpr int kFirstWall = 0;      // wall_y-, the wall the robot follows when it is bumped

struct StepRecord {
    double time = 0.0;
    AssociationResult association;
    StepStatus update = StepStatus::NotAttempted;
    double position_error = 0.0;
};

class Recorder : public RunObserver {
  public:
    void on_step(const LoopSnapshot& s, const GroundTruth& truth) override {
        records.push_back(
            {s.time, s.association, s.update.status,
             std::hypot(s.estimate(kX) - truth.pose.x, s.estimate(kY) - truth.pose.y)});
    }
    std::vector<StepRecord> records;
};

std::vector<StepRecord> run_with_gate(AssociationGate gate, std::uint64_t seed) {
    const LessonStep* g = legofeup_lesson().find_step("g");
    EXPECT_NE(g, nullptr);
    RunConfig config = g->config;
    config.association.gate = gate;
    config.seed = seed;
    Recorder recorder;
    const RunResult result = run_lockstep(resolve(config), &recorder);
    EXPECT_TRUE(result.routine_finished);
    return recorder.records;
}

/// The steps after the bump at which the first wall was used by an update.
int first_wall_updates_after_bump(const std::vector<StepRecord>& records) {
    int count = 0;
    for (const StepRecord& r : records) {
        count += r.time > kBumpTime + 0.05 && r.association.wall == kFirstWall
                         && r.association.associated() && r.update == StepStatus::Applied
                     ? 1
                     : 0;
    }
    return count;
}

TEST(AssociationGateBump, StepsGAndHDifferOnlyInTheGate) {
    const LessonStep* g = legofeup_lesson().find_step("g");
    const LessonStep* h = legofeup_lesson().find_step("h");
    ASSERT_NE(g, nullptr);
    ASSERT_NE(h, nullptr);
    EXPECT_EQ(g->config.association.gate, AssociationGate::Fixed);
    EXPECT_EQ(h->config.association.gate, AssociationGate::Mahalanobis);
    EXPECT_TRUE(g->config.simulator.displacement.enabled);
    EXPECT_DOUBLE_EQ(g->config.simulator.displacement.time, kBumpTime);
    EXPECT_DOUBLE_EQ(
        std::hypot(g->config.simulator.displacement.dx, g->config.simulator.displacement.dy), 0.15);
    EXPECT_DOUBLE_EQ(h->config.simulator.displacement.dy, g->config.simulator.displacement.dy);
    EXPECT_EQ(h->config.filter.q11, g->config.filter.q11);
    EXPECT_EQ(h->config.filter.r11, g->config.filter.r11);
    EXPECT_EQ(h->config.routine.rectangle_corner, g->config.routine.rectangle_corner);
}

TEST(AssociationGateBump, OnlyTheMahalanobisGateFindsTheBumpedRobotAgain) {
    constexpr std::uint64_t kSeed = 1;
    const auto fixed = run_with_gate(AssociationGate::Fixed, kSeed);
    const auto mahalanobis = run_with_gate(AssociationGate::Mahalanobis, kSeed);
    ASSERT_FALSE(fixed.empty());
    ASSERT_FALSE(mahalanobis.empty());

    // Both see the first wall right after the bump and refuse it: the fixed gates for its
    // 15 cm distance error, the Mahalanobis gate because P is still small (d² several times
    // χ²₂(0.99) = 9.21; 52 on this seed).
    const auto first_refusal = [](const std::vector<StepRecord>& records) -> const StepRecord* {
        for (const StepRecord& r : records) {
            if (r.time > kBumpTime + 0.05 && r.association.wall == kFirstWall) {
                return &r;
            }
        }
        return nullptr;
    };
    const StepRecord* fixed_first = first_refusal(fixed);
    const StepRecord* gated_first = first_refusal(mahalanobis);
    ASSERT_NE(fixed_first, nullptr);
    ASSERT_NE(gated_first, nullptr);
    EXPECT_EQ(fixed_first->association.outcome, AssociationOutcome::DistanceMismatch);
    EXPECT_NEAR(fixed_first->association.distance_error, -0.15, 0.04);
    EXPECT_EQ(gated_first->association.outcome, AssociationOutcome::MahalanobisMismatch);
    EXPECT_GT(gated_first->association.mahalanobis_d2, 3.0 * 9.21);
    EXPECT_NEAR(gated_first->association.mahalanobis_threshold, 9.2103, 1e-4);

    // The fixed gates never take the first wall; the estimate stays off.
    EXPECT_EQ(first_wall_updates_after_bump(fixed), 0);
    EXPECT_GT(fixed.back().position_error, 0.1);

    // The Mahalanobis gate takes it again once P has grown, and the robot is found.
    EXPECT_GT(first_wall_updates_after_bump(mahalanobis), 20);
    EXPECT_LT(mahalanobis.back().position_error, 0.05);
}

}  // namespace
}  // namespace legofeup::lessons
