// RunRecording keeps every step for the run's plots and thins them for documents.
#include <gtest/gtest.h>

#include "legofeup/report/run_plots.hpp"

namespace legofeup::report {
namespace {

RunRecording recording_of(std::size_t steps) {
    RunRecording recording;
    LoopSnapshot snapshot;
    GroundTruth truth;
    for (std::size_t i = 0; i < steps; ++i) {
        snapshot.time = 0.05 * static_cast<double>(i);
        recording.on_step(snapshot, truth);
    }
    return recording;
}

TEST(RunRecording, ThinningKeepsEveryKthStepTheFirstAndTheLast) {
    const RunRecording full = recording_of(3400);
    const RunRecording thin = full.thinned(700);
    const auto& kept = thin.steps();
    ASSERT_LE(kept.size(), 700u);
    EXPECT_GE(kept.size(), 680u);  // stride ⌈3400/700⌉ = 5: 680 steps
    EXPECT_DOUBLE_EQ(kept.front().time, 0.0);
    EXPECT_DOUBLE_EQ(kept.back().time, full.steps().back().time);
    EXPECT_DOUBLE_EQ(kept[1].time, 0.25);  // every 5th step of 50 ms
}

TEST(RunRecording, ThinningAShortRunKeepsItWhole) {
    const RunRecording full = recording_of(10);
    EXPECT_EQ(full.thinned(700).steps().size(), 10u);
    EXPECT_TRUE(recording_of(0).thinned(700).steps().empty());
    const RunRecording three = recording_of(10).thinned(3);  // stride 4: 0, 4, 8 → last is 9
    ASSERT_EQ(three.steps().size(), 3u);
    EXPECT_DOUBLE_EQ(three.steps().back().time, 0.45);
}

}  // namespace
}  // namespace legofeup::report
