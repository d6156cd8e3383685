// The built-in lesson and finding lessons by name.
#include "legofeup/lessons/lesson.hpp"

#include "legofeup/lessons/input_error.hpp"
#include "legofeup_lesson_resource.hpp"

namespace legofeup::lessons {

const LessonStep* Lesson::find_step(std::string_view step_id) const {
    for (const LessonStep& step : steps) {
        if (step.id == step_id) {
            return &step;
        }
    }
    return nullptr;
}

const Lesson& legofeup_lesson() {
    static const Lesson lesson =
        parse_lesson(resources::kLegoFeupLesson, "lessons/legofeup.toml (built in)");
    return lesson;
}

Lesson find_lesson(const std::string& name_or_path) {
    if (name_or_path == legofeup_lesson().id) {
        return legofeup_lesson();
    }
    if (!std::filesystem::is_regular_file(name_or_path)) {
        throw InputError(
            {{"", 0, "--lesson", name_or_path,
              "no such lesson file (the built-in lesson is \"" + legofeup_lesson().id + "\")"}});
    }
    return load_lesson_file(name_or_path);
}

}  // namespace legofeup::lessons
