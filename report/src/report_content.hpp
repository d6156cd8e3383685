#pragma once
// What the HTML and the PDF report both show, computed once so the two say the same: the
// settings of a step worth listing, the metrics as text, the checks' marks.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "legofeup/report/student_report.hpp"

namespace legofeup::report::content {

struct ParameterRow {
    std::string key;            ///< as in configuration files, e.g. "filter.q11"
    std::string value;          ///< as the step ran
    std::string default_value;  ///< the program's default
    std::string meaning;        ///< meaning and unit
};

/// The settings that differ from the defaults, and always the seed, Q, R and P0: what a
/// reader needs to repeat the run.
std::vector<ParameterRow> parameter_rows(const lessons::RunConfig& config);

struct MetricRow {
    std::string name;
    std::string value;
};

/// Every metric of the run except the machine-dependent timings (the report of the same
/// runs is the same document on every machine). A metric that needs the ground truth, in a
/// run without one, reads "— (no ground truth on this link)", never 0.
std::vector<MetricRow> metric_rows(const nlohmann::json& metrics);

/// A number in at most four significant digits ("0.0123", "1.2e-07").
std::string format_number(double value);

/// "✔ passed" / "✘ failed".
const char* check_mark(bool passed);

/// "3 of 4 checks passed", "no checks".
std::string checks_summary(const std::vector<lessons::CheckResult>& checks);

/// The step's outcome in `report`, or nullptr when the report has none.
const StepOutcome* find_outcome(const StudentReport& report, const std::string& step_id);

/// The answer to a question, or nullptr when it is missing or blank.
const std::string* find_answer(const StepOutcome* outcome, const std::string& question_id);

/// The width in pixels the report's figures are drawn at (their text then reads well at
/// the width of an A4 page and of a browser column).
inline constexpr int kFigureWidth = 900;

}  // namespace legofeup::report::content
