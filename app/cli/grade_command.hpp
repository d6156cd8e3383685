#pragma once
// legofeup-cli grade: a teacher runs students' submissions on seeds they never saw and judges
// them against the lesson's thresholds (docs/lessons.md). One submission gives JSON; a folder
// of submissions gives one CSV row each. Exit codes as in commands.hpp.

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace legofeup::cli {

struct GradeOptions {
    std::string lesson = "legofeup";
    std::string submission;   ///< one file: JSON out
    std::string submissions;  ///< a folder of *.toml: CSV out
    int seeds = 0;            ///< 0: the lesson's
    std::optional<std::uint64_t> first_seed;
    std::optional<int> laps;
    int jobs = 0;
    std::string out;      ///< JSON file (one) or CSV file (folder); one: "" = stdout
    std::string details;  ///< folder: also each submission's JSON here
    std::string shard;    ///< folder: "i/n"
    bool quiet = false;

    CLI::App* command = nullptr;
};

void add_grade_subcommand(CLI::App& app, GradeOptions& options);

/// Runs `grade` when the command line chose it; returns the exit code.
int grade_command(const GradeOptions& options);

}  // namespace legofeup::cli
