// The built-in lessons and finding lessons by name.
#include "legofeup/lessons/lesson.hpp"

#include <array>

#include "legofeup/lessons/input_error.hpp"
#include "legofeup_beacons_lesson_resource.hpp"
#include "legofeup_compass_lesson_resource.hpp"
#include "legofeup_laser_lesson_resource.hpp"
#include "legofeup_lesson_resource.hpp"
#include "legofeup_mcl_lesson_resource.hpp"
#include "legofeup_speeds_lesson_resource.hpp"

namespace legofeup::lessons {
namespace {

struct EmbeddedLesson {
    std::string_view text;
    const char* file;
};

// The explicit registry: the LegoFeup lesson first, then the related papers' lessons.
const std::array<EmbeddedLesson, 6> kEmbeddedLessons{{
    {resources::kLegoFeupLesson, "lessons/legofeup.toml"},
    {resources::kBeaconsLesson, "lessons/beacons.toml"},
    {resources::kSpeedsLesson, "lessons/speeds.toml"},
    {resources::kCompassLesson, "lessons/compass.toml"},
    {resources::kLaserLesson, "lessons/laser.toml"},
    {resources::kMclLesson, "lessons/mcl.toml"},
}};

const std::vector<Lesson>& parsed_built_in_lessons() {
    static const std::vector<Lesson> lessons = [] {
        std::vector<Lesson> list;
        for (const EmbeddedLesson& embedded : kEmbeddedLessons) {
            list.push_back(parse_lesson(embedded.text, std::string(embedded.file) + " (built in)"));
        }
        return list;
    }();
    return lessons;
}

}  // namespace

const LessonStep* Lesson::find_step(std::string_view step_id) const {
    for (const LessonStep& step : steps) {
        if (step.id == step_id) {
            return &step;
        }
    }
    return nullptr;
}

const Lesson& legofeup_lesson() {
    return parsed_built_in_lessons().front();
}

const std::vector<BuiltInLesson>& built_in_lessons() {
    static const std::vector<BuiltInLesson> list = [] {
        std::vector<BuiltInLesson> out;
        for (std::size_t i = 0; i < kEmbeddedLessons.size(); ++i) {
            const Lesson& lesson = parsed_built_in_lessons()[i];
            out.push_back(
                {lesson.id, lesson.title, std::string("resources/") + kEmbeddedLessons[i].file});
        }
        return out;
    }();
    return list;
}

const Lesson* find_built_in_lesson(std::string_view id) {
    for (const Lesson& lesson : parsed_built_in_lessons()) {
        if (lesson.id == id) {
            return &lesson;
        }
    }
    return nullptr;
}

Lesson find_lesson(const std::string& name_or_path) {
    if (const Lesson* lesson = find_built_in_lesson(name_or_path)) {
        return *lesson;
    }
    if (!std::filesystem::is_regular_file(name_or_path)) {
        std::string ids;
        for (const BuiltInLesson& lesson : built_in_lessons()) {
            ids += (ids.empty() ? "\"" : ", \"") + lesson.id + "\"";
        }
        throw InputError({{"", 0, "--lesson", name_or_path,
                           "no such lesson file (the built-in lessons are " + ids + ")"}});
    }
    return load_lesson_file(name_or_path);
}

}  // namespace legofeup::lessons
