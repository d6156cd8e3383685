#pragma once
// Teacher grading (docs/lessons.md): a submission's tuning of the graded step, run on seeds
// the student never saw, judged against the lesson's [grading] checks. The result is a pure
// function of the lesson, the submission, the seeds and the code — no wall-clock numbers — so
// the same command gives the same JSON on any machine and with any number of jobs.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "legofeup/lessons/analysis/batch_run.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/submission.hpp"

namespace legofeup::lessons {

struct GradingRequest {
    int seeds = 0;                            ///< 0: the lesson's default
    std::optional<std::uint64_t> first_seed;  ///< unset: the lesson's
    int jobs = 0;                             ///< 0: all cores
    std::optional<int> laps;                  ///< unset: the graded step's
};

/// The seeds a grading run uses: first_seed, first_seed + 1, … (request over lesson).
std::vector<std::uint64_t> grading_seeds(const GradingSpec& spec, const GradingRequest& request);

/// Grades one submission. The JSON has: lesson, step, submission, students, seeds, per_seed
/// (seed and metrics), aggregate (per metric: mean, std, min, max), checks (evaluated on the
/// means, each with its expression, description, value and outcome), passed, summary.
/// Throws InputError when the lesson has no [grading] section or a run cannot be resolved.
nlohmann::json grade_submission(const Lesson& lesson, const Submission& submission,
                                const GradingRequest& request,
                                const analysis::BatchProgress& progress = {});

/// One line for people: "PASS — 3/3 checks on 20 seeds (rms_position_error_m = 0.034 < 0.06 …)".
std::string grading_summary(const nlohmann::json& grade);

}  // namespace legofeup::lessons
