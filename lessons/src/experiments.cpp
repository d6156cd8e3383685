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

const Experiment* find_experiment(std::string_view id) {
    for (const Experiment& experiment : legofeup_experiments()) {
        if (experiment.id == id) {
            return &experiment;
        }
    }
    return nullptr;
}

}  // namespace legofeup::lessons
