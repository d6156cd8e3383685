#pragma once
// summary.json: the full configuration of a run (with its seed and world) and its metrics.

#include <nlohmann/json.hpp>
#include <string_view>

#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

/// Every setting, nested by section as in the TOML files.
nlohmann::json config_to_json(const RunConfig& config);

/// The metrics as summary.json names them. Those that need the ground truth
/// (is_truth_metric) are null when the run had none: absent, never a 0 that reads as
/// measured.
nlohmann::json metrics_to_json(const RunMetrics& metrics);

/// Whether the metric `name` of summary.json needs the ground truth (an error, the NEES, a
/// kidnapping): null in a run without one, such as a real robot.
bool is_truth_metric(std::string_view name);

/// summary.json's "metrics" object: metrics_to_json of the run's metrics plus how the run
/// went (routine_finished, frames_missing, wall time, …). Lesson checks name its keys.
nlohmann::json result_metrics_to_json(const RunResult& result);

/// The metrics of that object that measure the machine, not the run (wall time, real-time
/// factor): left out wherever results must be reproducible (grading, reports).
bool is_machine_dependent_metric(std::string_view name);

nlohmann::json run_summary(const ResolvedRun& run, const RunResult& result,
                           std::string_view experiment, std::string_view title);

}  // namespace legofeup::lessons
