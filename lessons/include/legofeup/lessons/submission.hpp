#pragma once
// A student's submission (docs/lessons.md): who they are, their answers to the lesson's
// questions, and their tuning of the graded step — one TOML file, written by the GUI (or by
// hand) and read by the report and by `legofeup-cli grade`.
//
//   lesson = "legofeup"
//   students = "Ana Silva, Rui Costa"
//   [answers.a]
//   q1 = """The ellipse keeps growing …"""
//   [tuning.filter]          # only what the lesson's [grading] tunable allows
//   q11 = 2e-7

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "legofeup/lessons/lesson.hpp"

namespace legofeup::lessons {

struct Submission {
    std::string lesson;    ///< the lesson id it answers
    std::string students;  ///< names as typed
    /// step id → question id → answer (Markdown as typed).
    std::map<std::string, std::map<std::string, std::string>> answers;
    /// The graded step's configuration: its preset with the [tuning] overlay applied.
    RunConfig tuned;
    /// The [tuning] table's settings as a run-configuration document ("[filter]\nq11 =
    /// 2e-07\n", values in their shortest exact form), to show, to apply over the preset
    /// with apply_config_toml, and to save back. Empty when the submission tunes nothing.
    std::string tuning_toml;
    std::string source;
};

/// Parses a submission for `lesson`. Throws InputError (file:line, key, reason) for a
/// different lesson id, answers to steps or questions the lesson does not have, tuning of
/// settings outside the lesson's tunable list, and bad values.
Submission parse_submission(std::string_view text, const std::string& source, const Lesson& lesson);
Submission load_submission_file(const std::filesystem::path& path, const Lesson& lesson);

/// The TOML document parse_submission reads back to the same students, answers and tuning.
/// `tuning_toml` is written under [tuning] (its [section] headers become [tuning.section]),
/// so it must be a run-configuration document as parse_submission and tuning_to_toml make.
std::string submission_to_toml(const Submission& submission);

/// The settings of `tuned` that the lesson lets students tune and that differ from the graded
/// step's preset, as a run-configuration document ("[filter]\nq11 = 2e-07\n"): what a
/// Submission's tuning_toml holds when the GUI builds one. Empty if nothing changed or the
/// lesson grades no step.
std::string tuning_to_toml(const RunConfig& tuned, const Lesson& lesson);

}  // namespace legofeup::lessons
