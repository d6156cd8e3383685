#include "legofeup/lessons/experiments.hpp"

#include "legofeup/lessons/lesson.hpp"

namespace legofeup::lessons {

const std::vector<Experiment>& legofeup_experiments() {
    static const std::vector<Experiment> experiments = [] {
        std::vector<Experiment> list;
        for (const LessonStep& step : legofeup_lesson().steps) {
            list.push_back({step.id, step.title, step.instructions, step.expectation, step.config});
        }
        return list;
    }();
    return experiments;
}

const std::vector<Experiment>& all_experiments() {
    static const std::vector<Experiment> experiments = [] {
        std::vector<Experiment> list = legofeup_experiments();
        for (const BuiltInLesson& built_in : built_in_lessons()) {
            const Lesson& lesson = *find_built_in_lesson(built_in.id);
            if (&lesson == &legofeup_lesson()) {
                continue;
            }
            for (const LessonStep& step : lesson.steps) {
                list.push_back({lesson.id + ":" + step.id, step.title, step.instructions,
                                step.expectation, step.config});
            }
        }
        return list;
    }();
    return experiments;
}

const Experiment* find_experiment(std::string_view id) {
    for (const Experiment& experiment : all_experiments()) {
        if (experiment.id == id) {
            return &experiment;
        }
    }
    return nullptr;
}

}  // namespace legofeup::lessons
