#pragma once
// A lesson as data (docs/lessons.md): a TOML file with Markdown texts — title, goals and
// steps. Each step has instructions, a parameter preset in the run-configuration format,
// what to observe, questions for the report, automatic checks on the run's metrics, and the
// conclusion the step should lead to (hidden from students until they have run the step).
// An optional [grading] section says which step a teacher grades, on which seeds, which
// settings a student may tune, and the thresholds a submission must meet.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// One automatic check on a metric of summary.json's "metrics" object, written in a lesson
/// as "final_position_error_m > 0.2", "mean_nees within nees_95_bounds", or "routine_finished"
/// (a true/false metric that must be true: read as GreaterOrEqual 1).
struct MetricCheck {
    enum class Op : std::uint8_t { Less, LessOrEqual, Greater, GreaterOrEqual, Within };
    std::string metric;  ///< e.g. "final_position_error_m"
    Op op = Op::Less;
    double threshold = 0.0;     ///< the right-hand number (not for Within)
    std::string bounds_metric;  ///< Within: a metric holding [lower, upper]
    std::string expression;     ///< as written in the lesson
    std::string description;    ///< what it means, for students ("the estimate drifted away")
    std::string source;         ///< file and line it was written on, for messages
    int line = 0;
};

struct CheckResult {
    MetricCheck check;
    bool passed = false;
    double actual = 0.0;  ///< the metric's value (NaN if it was missing or not a number)
    std::string message;  ///< e.g. "final_position_error_m = 0.412 > 0.2: passed"
};

/// Evaluates checks against a metrics object (summary.json's "metrics"; booleans count as
/// 0/1). A missing or non-numeric metric fails its check with a message saying so — a null
/// one that needs the ground truth (is_truth_metric) says that the run had none.
std::vector<CheckResult> evaluate_checks(const std::vector<MetricCheck>& checks,
                                         const nlohmann::json& metrics);

struct LessonQuestion {
    std::string id;    ///< unique within the step, e.g. "q1"
    std::string text;  ///< Markdown
};

struct LessonStep {
    std::string id;  ///< unique within the lesson, e.g. "a"
    std::string title;
    std::string instructions;  ///< Markdown
    std::string observe;       ///< Markdown: what to watch while it runs
    std::string expectation;   ///< Markdown: the conclusion; shown once the step has run
    std::vector<LessonQuestion> questions;
    std::vector<MetricCheck> checks;
    RunConfig config;  ///< the defaults, the lesson's [base], then this step's [step.config]
};

struct GradingSpec {
    std::string step;              ///< the step whose configuration the student tunes
    int seeds = 20;                ///< default number of grading seeds
    std::uint64_t first_seed = 1;  ///< grading seeds are first_seed, first_seed + 1, …
    /// Configuration sections (e.g. "filter") or keys ("initial.pxx") a submission may set.
    std::vector<std::string> tunable;
    /// Checked on the mean of each metric over the seeds (the bounds metric of a Within
    /// check comes from the first seed: it depends on the configuration, not the noise).
    std::vector<MetricCheck> checks;
};

struct Lesson {
    std::string id;  ///< e.g. "legofeup"
    std::string title;
    std::string goals;  ///< Markdown
    std::vector<LessonStep> steps;
    std::optional<GradingSpec> grading;
    std::string source;  ///< the file it came from

    const LessonStep* find_step(std::string_view step_id) const;
};

/// Parses a lesson document. `base_directory` anchors relative paths (world files). Throws
/// InputError listing every problem with file:line, key and reason (unknown keys, missing
/// texts, duplicate ids, checks that do not parse or name no metric, bad presets, a grading
/// step that does not exist, …).
Lesson parse_lesson(std::string_view text, const std::string& source,
                    const std::filesystem::path& base_directory = {});

/// Reads and parses a lesson file.
Lesson load_lesson_file(const std::filesystem::path& path);

/// The built-in LegoFeup lesson (resources/lessons/legofeup.toml, steps a–h), parsed once.
const Lesson& legofeup_lesson();

/// The lessons that ship with the program, in the order menus list them (an explicit list:
/// no self-registration).
struct BuiltInLesson {
    std::string id;  ///< "legofeup", "beacons", "speeds", "compass", "laser"
    std::string title;
    std::string resource_path;  ///< where it lives in the source tree, for the record
};
const std::vector<BuiltInLesson>& built_in_lessons();

/// A built-in lesson by id, parsed once; nullptr if there is none.
const Lesson* find_built_in_lesson(std::string_view id);

/// A built-in lesson's id or the path of a lesson file.
Lesson find_lesson(const std::string& name_or_path);

/// The metric names a check may refer to (those of summary.json's "metrics").
const std::vector<std::string>& known_metrics();

}  // namespace legofeup::lessons
