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
    /// The [tuning] table as written (TOML text), to show and to save back.
    std::string tuning_toml;
    std::string source;
};

/// Parses a submission for `lesson`. Throws InputError (file:line, key, reason) for a
/// different lesson id, answers to steps or questions the lesson does not have, tuning of
/// settings outside the lesson's tunable list, and bad values.
Submission parse_submission(std::string_view text, const std::string& source, const Lesson& lesson);
Submission load_submission_file(const std::filesystem::path& path, const Lesson& lesson);

/// The TOML document parse_submission reads back to the same students, answers and tuning.
std::string submission_to_toml(const Submission& submission);

}  // namespace legofeup::lessons
