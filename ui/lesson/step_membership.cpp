#include "legofeup/ui/lesson/step_membership.hpp"

#include <algorithm>

#include "legofeup/lessons/config_schema.hpp"

namespace legofeup::ui {
namespace {

/// Whether `setting` has the same value in both (an optional one: unset in both, or set to
/// the same value).
bool same_value(const lessons::Setting& setting, const lessons::RunConfig& first,
                const lessons::RunConfig& second) {
    if (setting.is_set) {
        const bool set = setting.is_set(first);
        if (set != setting.is_set(second)) {
            return false;
        }
        if (!set) {
            return true;
        }
    }
    return setting.get(first) == setting.get(second);
}

}  // namespace

const std::vector<std::string>& experiment_keys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> found;
        for (const lessons::Setting& setting : lessons::run_settings()) {
            if (setting.key == "world" || setting.key == "localisation.method"
                || setting.key == "filter.kind" || setting.key.ends_with(".enabled")) {
                found.push_back(setting.key);
            }
        }
        return found;
    }();
    return keys;
}

std::vector<std::string> experiment_differences(const lessons::RunConfig& config,
                                                const lessons::LessonStep& step) {
    std::vector<std::string> differing;
    for (const std::string& key : experiment_keys()) {
        if (!same_value(*lessons::find_setting_by_key(key), config, step.config)) {
            differing.push_back(key);
        }
    }
    return differing;
}

bool is_step_configuration(const lessons::RunConfig& config, const lessons::LessonStep& step) {
    return experiment_differences(config, step).empty();
}

std::size_t settings_differing(const lessons::RunConfig& first, const lessons::RunConfig& second) {
    const auto& settings = lessons::run_settings();
    return static_cast<std::size_t>(std::count_if(
        settings.begin(), settings.end(),
        [&](const lessons::Setting& setting) { return !same_value(setting, first, second); }));
}

StepOfConfiguration step_of_configuration(const lessons::RunConfig& config,
                                          const std::vector<const lessons::Lesson*>& lessons) {
    StepOfConfiguration nearest;
    std::size_t fewest = 0;
    for (const lessons::Lesson* lesson : lessons) {
        for (const lessons::LessonStep& step : lesson->steps) {
            if (!is_step_configuration(config, step)) {
                continue;
            }
            const std::size_t differing = settings_differing(config, step.config);
            if (nearest.step == nullptr || differing < fewest) {
                nearest = {lesson, &step};
                fewest = differing;
            }
        }
    }
    return nearest;
}

}  // namespace legofeup::ui
