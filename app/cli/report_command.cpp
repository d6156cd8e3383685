#include "report_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <set>
#include <sstream>

#include "commands.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/submission.hpp"
#include "legofeup/report/student_report.hpp"

namespace legofeup::cli {
namespace {

using lessons::InputError;
using lessons::InputProblem;

// "a,b" → the steps chosen, checked against the lesson; empty: every step.
std::set<std::string> chosen_steps(const std::string& list, const lessons::Lesson& lesson) {
    std::set<std::string> chosen;
    std::vector<InputProblem> problems;
    std::stringstream items(list);
    for (std::string id; std::getline(items, id, ',');) {
        if (lesson.find_step(id) == nullptr) {
            std::string known;
            for (const lessons::LessonStep& step : lesson.steps) {
                known += (known.empty() ? "" : ", ") + step.id;
            }
            problems.push_back(
                {"", 0, "--steps", id,
                 "the lesson \"" + lesson.id + "\" has no such step (it has " + known + ")"});
        }
        chosen.insert(id);
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
    if (chosen.empty()) {
        for (const lessons::LessonStep& step : lesson.steps) {
            chosen.insert(step.id);
        }
    }
    return chosen;
}

std::string now_text() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M", &local);
    return text;
}

// "step a  Dead reckoning: 2 of 2 checks passed [pass …] [FAIL …]"
void print_step(const lessons::LessonStep& step, const report::StepOutcome& outcome) {
    std::size_t passed = 0;
    std::string marks;
    for (const lessons::CheckResult& check : outcome.checks) {
        passed += check.passed ? 1 : 0;
        marks += std::string(" [") + (check.passed ? "pass" : "FAIL") + " " + check.check.expression
                 + "]";
    }
    std::printf("step %s  %s: %zu of %zu checks passed%s\n", step.id.c_str(), step.title.c_str(),
                passed, outcome.checks.size(), marks.c_str());
}

report::StudentReport build_report(const ReportOptions& options) {
    report::StudentReport report;
    report.lesson = lessons::find_lesson(options.lesson);
    std::optional<lessons::Submission> submission;
    if (!options.submission.empty()) {
        submission = lessons::load_submission_file(options.submission, report.lesson);
        report.students = submission->students;
    }
    const std::set<std::string> chosen = chosen_steps(options.steps, report.lesson);
    report.created = now_text();
    const std::string graded = report.lesson.grading ? report.lesson.grading->step : std::string();
    for (const lessons::LessonStep& step : report.lesson.steps) {
        report::StepOutcome outcome;
        outcome.step_id = step.id;
        if (chosen.count(step.id) != 0) {
            // The graded step runs with the students' tuning.
            lessons::RunConfig config =
                submission && step.id == graded ? submission->tuned : step.config;
            if (options.seed) {
                config.seed = *options.seed;
            }
            outcome = report::run_step(step, config);
            if (!options.quiet) {
                print_step(step, outcome);
            }
        }
        if (submission) {
            const auto answers = submission->answers.find(step.id);
            if (answers != submission->answers.end()) {
                outcome.answers = answers->second;
            }
        }
        report.steps.push_back(std::move(outcome));
    }
    return report;
}

}  // namespace

void add_report_subcommand(CLI::App& app, ReportOptions& options) {
    CLI::App* command = app.add_subcommand(
        "report", "Run steps of a lesson and write the student report (report.html, report.pdf)");
    command
        ->add_option("--lesson", options.lesson,
                     "\"legofeup\" (the built-in lesson, steps a … h) or a lesson file")
        ->capture_default_str();
    command
        ->add_option("--submission", options.submission,
                     "Submission TOML: the students' names, answers and tuning of the graded "
                     "step (docs/lessons.md)")
        ->check(CLI::ExistingFile);
    command->add_option("--steps", options.steps, "Steps to run, e.g. a,b,f (default: all)");
    command->add_option("--seed,-s", options.seed, "Seed of every run (default: each step's)");
    command->add_option("--out,-o", options.out_directory, "Directory for the report")->required();
    command->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
}

int report_command(const ReportOptions& options) {
    report::StudentReport report;
    try {
        report = build_report(options);
    } catch (const InputError& error) {
        for (const InputProblem& problem : error.problems()) {
            std::cerr << "error: " << problem.message() << '\n';
        }
        return kExitBadInput;
    }
    try {
        report::write_report(report, options.out_directory);
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kExitOutputFailed;
    }
    if (!options.quiet) {
        std::printf("Report written: %s/report.html and report.pdf\n",
                    options.out_directory.c_str());
    }
    return kExitOk;
}

}  // namespace legofeup::cli
