// Which lesson step a configuration is (GoogleTest): every built-in step's preset is its own
// step's, a tuned preset still is, and a step of one lesson is never taken for a step of
// another — the laser lesson's office run is not LegoFeup step f's.

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/ui/lesson/step_membership.hpp"

namespace legofeup::ui {
namespace {

std::vector<const lessons::Lesson*> built_in() {
    std::vector<const lessons::Lesson*> all;
    for (const lessons::BuiltInLesson& lesson : lessons::built_in_lessons()) {
        all.push_back(lessons::find_built_in_lesson(lesson.id));
    }
    return all;
}

const lessons::LessonStep& step(const char* lesson, const char* id) {
    return *lessons::find_built_in_lesson(lesson)->find_step(id);
}

std::set<std::string> as_set(const std::vector<std::string>& keys) {
    return {keys.begin(), keys.end()};
}

TEST(StepMembership, TheExperimentIsTheWorldTheLocalisationAndTheSimulatedSensorsAndEvents) {
    EXPECT_EQ(as_set(experiment_keys()),
              (std::set<std::string>{
                  "world", "localisation.method", "filter.kind", "beacon_scanner.enabled",
                  "gyro.enabled", "accelerometers.enabled", "compass_sensor.enabled",
                  "laser_scanner.enabled", "kidnap.enabled", "displacement.enabled"}));
}

TEST(StepMembership, EveryBuiltInStepsPresetIsItsOwnStepsAndLeadsBackToIt) {
    const std::vector<const lessons::Lesson*> lessons = built_in();
    ASSERT_GE(lessons.size(), 5U);
    for (const lessons::Lesson* lesson : lessons) {
        for (const lessons::LessonStep& own : lesson->steps) {
            EXPECT_TRUE(is_step_configuration(own.config, own)) << lesson->id << ":" << own.id;
            const StepOfConfiguration found = step_of_configuration(own.config, lessons);
            ASSERT_NE(found.step, nullptr) << lesson->id << ":" << own.id;
            // Its own step, or an earlier one with the very same preset.
            EXPECT_EQ(settings_differing(found.step->config, own.config), 0U)
                << lesson->id << ":" << own.id << " led to " << found.lesson->id << ":"
                << found.step->id;
            EXPECT_EQ(found.lesson, lesson) << lesson->id << ":" << own.id;
        }
    }
}

TEST(StepMembership, AStepOfOneLessonIsNoStepOfAnother) {
    const std::vector<const lessons::Lesson*> lessons = built_in();
    int pairs = 0;
    for (const lessons::Lesson* first : lessons) {
        for (const lessons::Lesson* second : lessons) {
            if (first == second) {
                continue;
            }
            for (const lessons::LessonStep& a : first->steps) {
                for (const lessons::LessonStep& b : second->steps) {
                    EXPECT_FALSE(is_step_configuration(a.config, b))
                        << first->id << ":" << a.id << " taken for " << second->id << ":" << b.id;
                    ++pairs;
                }
            }
        }
    }
    EXPECT_GT(pairs, 100);
}

TEST(StepMembership, TunedAsStudentsTuneARunIsStillTheSteps) {
    const lessons::LessonStep& f = step("legofeup", "f");
    lessons::RunConfig tuned = f.config;
    tuned.filter.q11 *= 3.0;
    tuned.filter.r11 *= 10.0;
    tuned.physical.ir_noise = 0.02;  // simulator.ir_noise
    tuned.initial.var_x *= 4.0;
    tuned.routine.kind = lessons::RoutineSpec::Kind::Line;  // a shorter run
    tuned.duration = 3.0;
    tuned.seed = 7;
    EXPECT_TRUE(experiment_differences(tuned, f).empty());
    EXPECT_EQ(settings_differing(tuned, f.config), 7U);
    EXPECT_TRUE(is_step_configuration(tuned, f));
}

TEST(StepMembership, TheLaserLessonsOfficeRunIsNotLegoFeupStepFsButLaserStepAs) {
    const lessons::RunConfig laser = lessons::find_experiment("laser:a")->config;
    const lessons::LessonStep& f = step("legofeup", "f");
    EXPECT_EQ(as_set(experiment_differences(laser, f)),
              (std::set<std::string>{"world", "localisation.method", "laser_scanner.enabled"}));
    EXPECT_FALSE(is_step_configuration(laser, f));
    // Sought in the LegoFeup lesson first, it is still found in its own.
    std::vector<const lessons::Lesson*> lessons = {&lessons::legofeup_lesson()};
    const std::vector<const lessons::Lesson*> all = built_in();
    lessons.insert(lessons.end(), all.begin(), all.end());
    const StepOfConfiguration found = step_of_configuration(laser, lessons);
    ASSERT_NE(found.step, nullptr);
    EXPECT_EQ(found.lesson->id, "laser");
    EXPECT_EQ(found.step->id, "a");
    // And a kidnapping makes it step b's experiment, no longer step a's.
    EXPECT_EQ(experiment_differences(step("laser", "b").config, *found.step),
              std::vector<std::string>{"kidnap.enabled"});
}

TEST(StepMembership, AConfigurationOfNoStepIsFoundInNone) {
    // The laser scanner on the robot, but the walls and the arena: no lesson's experiment.
    lessons::RunConfig own = lessons::find_experiment("laser:a")->config;
    own.world_file.clear();
    own.lesson.localisation = Localisation::Walls;
    const StepOfConfiguration found = step_of_configuration(own, built_in());
    EXPECT_EQ(found.step, nullptr) << found.lesson->id << ":" << found.step->id;
    EXPECT_EQ(found.lesson, nullptr);
    EXPECT_EQ(experiment_differences(own, step("legofeup", "f")),
              std::vector<std::string>{"laser_scanner.enabled"});
}

}  // namespace
}  // namespace legofeup::ui
