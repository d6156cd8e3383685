#pragma once
// The student report (docs/lessons.md): one file to hand in, as HTML (self-contained: plots
// inline) and PDF, with per step the parameters, the plots, the metrics, the automatic checks
// with their outcome, the step's conclusion and the students' answers. The CLI
// (`legofeup-cli report`) and the GUI (File ▸ Export report) both write it with this code.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "legofeup/lessons/lesson.hpp"
#include "legofeup/report/run_plots.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::report {

/// What one step of the lesson produced.
struct StepOutcome {
    std::string step_id;        ///< a step of the report's lesson
    bool ran = false;           ///< false: listed as "not run" with its questions
    lessons::RunConfig config;  ///< as run (with the seed)
    nlohmann::json metrics;     ///< summary.json's "metrics" object
    std::vector<lessons::CheckResult> checks;
    RunRecording recording;                      ///< the run's steps, for the plots
    sim::WorldSpec world;                        ///< the arena it ran in
    std::map<std::string, std::string> answers;  ///< question id → answer
};

struct StudentReport {
    lessons::Lesson lesson;
    std::string students;
    std::string created;             ///< date and time shown on the report, as text
    std::vector<StepOutcome> steps;  ///< in lesson order
};

/// Runs `step` in lockstep with `config` (the step's preset, or a student's tuning of it) and
/// fills the outcome: metrics, checks, recording, world. The answers are left empty.
StepOutcome run_step(const lessons::LessonStep& step, const lessons::RunConfig& config);

/// The report as one self-contained HTML document (plots as inline SVG).
std::string report_html(const StudentReport& report);

/// Writes `report.html` and `report.pdf` (A4, cairo + pango) into `directory`, atomically
/// (a failed write leaves no half file). Throws std::runtime_error saying which file failed.
void write_report(const StudentReport& report, const std::filesystem::path& directory);

/// Markdown (paragraphs, headings, lists, emphasis, code, links) to HTML, text escaped.
std::string markdown_to_html(const std::string& markdown);

}  // namespace legofeup::report
