#include "lesson_commands.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/lesson.hpp"

namespace legofeup::cli {
namespace {

using lessons::InputError;
using lessons::Lesson;

// A Markdown text without the line breaks that end it, its later lines indented by
// `indent` spaces.
std::string trimmed(const std::string& text, std::size_t indent = 0) {
    const auto end = text.find_last_not_of(" \t\r\n");
    std::string out;
    for (std::size_t i = 0; end != std::string::npos && i <= end; ++i) {
        out += text[i];
        if (text[i] == '\n') {
            out.append(indent, ' ');
        }
    }
    return out;
}

int check_lesson(const std::string& file) {
    try {
        const Lesson lesson = lessons::load_lesson_file(file);
        std::size_t checks = lesson.grading ? lesson.grading->checks.size() : 0;
        for (const lessons::LessonStep& step : lesson.steps) {
            checks += step.checks.size();
        }
        std::printf("%s: ok — %zu steps, %zu checks\n", file.c_str(), lesson.steps.size(), checks);
        return kExitOk;
    } catch (const InputError& error) {
        for (const lessons::InputProblem& problem : error.problems()) {
            std::cerr << "error: " << problem.message() << '\n';
        }
        std::cerr << file << ": " << error.problems().size()
                  << (error.problems().size() == 1 ? " problem\n" : " problems\n");
        return kExitBadInput;
    }
}

// The student's view: instructions, what to observe and the questions — not the
// expectations (shown only once a step has run) nor the checks that give them away.
void print_lesson(const Lesson& lesson) {
    std::printf("%s\n\n%s\n", lesson.title.c_str(), trimmed(lesson.goals).c_str());
    for (const lessons::LessonStep& step : lesson.steps) {
        std::printf("\n── Step %s: %s ──\n\n%s\n\nObserve: %s\n", step.id.c_str(),
                    step.title.c_str(), trimmed(step.instructions).c_str(),
                    trimmed(step.observe).c_str());
        if (!step.questions.empty()) {
            std::printf("\nQuestions for the report:\n");
        }
        for (const lessons::LessonQuestion& question : step.questions) {
            std::printf("  %s. %s\n", question.id.c_str(),
                        trimmed(question.text, question.id.size() + 4).c_str());
        }
    }
    if (lesson.grading) {
        std::printf("\nGraded: step %s, on %d runs you have not seen.\n",
                    lesson.grading->step.c_str(), lesson.grading->seeds);
    }
}

int show_lesson(const std::string& name) {
    try {
        print_lesson(lessons::find_lesson(name));
        return kExitOk;
    } catch (const InputError& error) {
        for (const lessons::InputProblem& problem : error.problems()) {
            std::cerr << "error: " << problem.message() << '\n';
        }
        return kExitBadInput;
    }
}

}  // namespace

bool LessonOptions::requested() const {
    return (check_command != nullptr && check_command->parsed())
           || (show_command != nullptr && show_command->parsed());
}

void add_lesson_subcommands(CLI::App& app, LessonOptions& options) {
    CLI::App* lesson =
        app.add_subcommand("lesson", "Check or show a lesson file (docs/lessons.md)");
    lesson->require_subcommand(1);
    options.check_command = lesson->add_subcommand(
        "check", "Validate a lesson file: every problem with its line, or a summary if it is ok");
    options.check_command->add_option("FILE", options.check_file, "The lesson file (TOML)")
        ->required();
    options.show_command = lesson->add_subcommand(
        "show", "Print a lesson as students see it: steps, instructions and questions");
    options.show_command->add_option("--lesson", options.shown,
                                     "\"legofeup\" (the built-in lesson) or a lesson file");
}

int lesson_command(const LessonOptions& options) {
    if (options.check_command->parsed()) {
        return check_lesson(options.check_file);
    }
    return show_lesson(options.shown);
}

}  // namespace legofeup::cli
