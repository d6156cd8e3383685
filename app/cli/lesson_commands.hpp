#pragma once
// legofeup-cli lesson check and lesson show: for teachers writing lessons (docs/lessons.md).
// Exit codes as in commands.hpp.

#include <string>

namespace CLI {
class App;
}

namespace legofeup::cli {

struct LessonOptions {
    std::string check_file;          ///< lesson check FILE
    std::string shown = "legofeup";  ///< lesson show --lesson: "legofeup" or a file

    CLI::App* check_command = nullptr;
    CLI::App* show_command = nullptr;

    /// True when the command line chose `lesson check` or `lesson show`.
    bool requested() const;
};

/// Adds `lesson` with its subcommands `check` and `show` to `app`, filling `options`.
void add_lesson_subcommands(CLI::App& app, LessonOptions& options);

/// Runs the lesson subcommand the command line chose.
int lesson_command(const LessonOptions& options);

}  // namespace legofeup::cli
