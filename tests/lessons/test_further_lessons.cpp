// The built-in lessons of the related papers (beacons, speeds, compass; laser in
// test_laser_lesson.cpp): each is registered,
// reachable as "<lesson>:<step>" experiments, and each step's checks pass for its own preset
// and fail on the run of the step they must tell it from (the papers' findings, reproduced).
#include <gtest/gtest.h>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "lesson_checks_test_support.hpp"

namespace legofeup::lessons {
namespace {

const LessonStep& step(const char* lesson, const char* id) {
    const Lesson* found = find_built_in_lesson(lesson);
    EXPECT_NE(found, nullptr) << lesson;
    const LessonStep* s = found->find_step(id);
    EXPECT_NE(s, nullptr) << lesson << ":" << id;
    return *s;
}

TEST(FurtherLessons, AreRegisteredInOrderAndReachableAsExperiments) {
    const std::vector<BuiltInLesson>& list = built_in_lessons();
    ASSERT_EQ(list.size(), 6U);
    EXPECT_EQ(list[0].id, "legofeup");
    EXPECT_EQ(list[1].id, "beacons");
    EXPECT_EQ(list[2].id, "speeds");
    EXPECT_EQ(list[3].id, "compass");
    EXPECT_EQ(list[4].id, "laser");
    EXPECT_EQ(list[5].id, "mcl");
    const Experiment* experiment = find_experiment("beacons:b");
    ASSERT_NE(experiment, nullptr);
    EXPECT_EQ(experiment->config.lesson.localisation, Localisation::Beacons);
    EXPECT_TRUE(experiment->config.simulator.displacement.enabled);
    EXPECT_EQ(find_experiment("compass:c")->config.routine.kind, RoutineSpec::Kind::Random);
    EXPECT_EQ(find_experiment("speeds:d")->config.lesson.localisation, Localisation::GyroFusion);
    EXPECT_EQ(find_experiment("nowhere:a"), nullptr);
    EXPECT_EQ(find_lesson("compass").id, "compass");
}

struct StepCase {
    const char* lesson;
    const char* step;
    std::uint64_t seed;
};

void PrintTo(const StepCase& c, std::ostream* out) {
    *out << c.lesson << ":" << c.step << " seed " << c.seed;
}

class FurtherStepChecksPass : public testing::TestWithParam<StepCase> {};

TEST_P(FurtherStepChecksPass, OnItsOwnPreset) {
    const StepCase& c = GetParam();
    const LessonStep& s = step(c.lesson, c.step);
    EXPECT_EQ(failures(evaluate_checks(s.checks, metrics_of(s.config, c.seed))), "");
}

INSTANTIATE_TEST_SUITE_P(Further, FurtherStepChecksPass,
                         testing::Values(StepCase{"beacons", "a", 1}, StepCase{"beacons", "b", 2},
                                         StepCase{"beacons", "c", 3}, StepCase{"speeds", "a", 1},
                                         StepCase{"speeds", "b", 2}, StepCase{"speeds", "c", 1},
                                         StepCase{"speeds", "d", 4}, StepCase{"compass", "a", 1},
                                         StepCase{"compass", "b", 2}, StepCase{"compass", "c", 3},
                                         StepCase{"compass", "d", 1}));

struct Discrimination {
    const char* lesson;
    const char* checks;  ///< whose checks
    const char* run;     ///< on whose run: they must fail
};

void PrintTo(const Discrimination& d, std::ostream* out) {
    *out << d.lesson << ": " << d.checks << "'s checks on " << d.run << "'s run";
}

class FurtherStepChecksDiscriminate : public testing::TestWithParam<Discrimination> {};

TEST_P(FurtherStepChecksDiscriminate, FailOnTheRunOfAnotherStep) {
    const Discrimination& d = GetParam();
    const auto results = evaluate_checks(step(d.lesson, d.checks).checks,
                                         metrics_of(step(d.lesson, d.run).config, 1));
    EXPECT_NE(failures(results), "");
}

// b (displacement) vs a (none); encoders only vs the gyro's step (the other way round only
// over seeds, test_speeds_lesson.cpp: on a seed where odometry is lucky the gyro is no
// better); the compass against odometry alone and back.
INSTANTIATE_TEST_SUITE_P(Further, FurtherStepChecksDiscriminate,
                         testing::Values(Discrimination{"beacons", "b", "a"},
                                         Discrimination{"speeds", "c", "d"},
                                         Discrimination{"compass", "b", "a"},
                                         Discrimination{"compass", "a", "b"}));

}  // namespace
}  // namespace legofeup::lessons
