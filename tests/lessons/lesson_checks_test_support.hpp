#pragma once
// What the lesson tests share: a step's run metrics on a seed, and the failed checks as text.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::lessons {

/// A built-in lesson's step, "lesson:id" (a test failure and a crash-free abort when absent).
inline const LessonStep& built_in_step(const std::string& lesson_id, const std::string& id) {
    const Lesson* lesson = find_built_in_lesson(lesson_id);
    if (lesson == nullptr) {
        ADD_FAILURE() << "no built-in lesson " << lesson_id;
        std::abort();
    }
    const LessonStep* step = lesson->find_step(id);
    if (step == nullptr) {
        ADD_FAILURE() << "no step " << lesson_id << ":" << id;
        std::abort();
    }
    return *step;
}

/// The metrics summary.json would hold for `config` run in lockstep on `seed`.
inline nlohmann::json metrics_of(RunConfig config, std::uint64_t seed) {
    config.seed = seed;
    return result_metrics_to_json(run_lockstep(resolve(config)));
}

/// The messages of the failed checks, one per line; empty when all passed.
inline std::string failures(const std::vector<CheckResult>& results) {
    std::string text;
    for (const CheckResult& result : results) {
        text += result.passed ? "" : result.message + "\n";
    }
    return text;
}

}  // namespace legofeup::lessons
