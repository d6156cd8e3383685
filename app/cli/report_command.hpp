#pragma once
// legofeup-cli report: runs steps of a lesson and writes the student report (report.html and
// report.pdf, docs/lessons.md). Exit codes as in commands.hpp.

#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace legofeup::cli {

struct ReportOptions {
    std::string lesson = "legofeup";  ///< the built-in lesson's id or a lesson file
    std::string submission;           ///< students, answers and tuning; "" = none
    std::string steps;                ///< "a,b,…"; "" = every step
    std::optional<std::uint64_t> seed;
    std::string out_directory;
    bool quiet = false;
};

/// Adds the report subcommand to `app`, filling `options`.
void add_report_subcommand(CLI::App& app, ReportOptions& options);

int report_command(const ReportOptions& options);

}  // namespace legofeup::cli
