#pragma once
// What the lesson tests share: a step's run metrics on a seed, and the failed checks as text.
#include <string>
#include <vector>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::lessons {

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
