#pragma once
// A submission's tuning: which settings a lesson lets students tune, and writing some
// settings of a configuration as a run-configuration TOML document. Private to lessons/.

#include <set>
#include <string>

#include "legofeup/lessons/run_config.hpp"

#include "legofeup/lessons/lesson.hpp"

namespace legofeup::lessons {

/// Whether `key` ("filter.q11") is in `grading.tunable`, itself or by its section.
bool is_tunable(const std::string& key, const GradingSpec& grading);

/// The settings `keys` of `config` (top-level keys first, then one [section] each), values in
/// their shortest exact form; unset optional settings are left out.
std::string settings_to_toml(const RunConfig& config, const std::set<std::string>& keys);

}  // namespace legofeup::lessons
