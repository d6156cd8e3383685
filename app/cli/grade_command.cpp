#include "grade_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "commands.hpp"
#include "input_problems.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/grading.hpp"
#include "progress_bar.hpp"

namespace legofeup::cli {
namespace fs = std::filesystem;
namespace {

using lessons::InputError;

lessons::GradingRequest request_of(const GradeOptions& options) {
    lessons::GradingRequest request;
    request.seeds = options.seeds;
    request.first_seed = options.first_seed;
    request.jobs = options.jobs;
    request.laps = options.laps;
    return request;
}

/// A CSV field: quoted, with inner quotes doubled, when it holds a comma, quote or newline.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) {
        return text;
    }
    std::string quoted = "\"";
    for (const char c : text) {
        quoted += c;
        if (c == '"') {
            quoted += '"';
        }
    }
    return quoted + "\"";
}

std::string number_text(const nlohmann::json& value) {
    if (!value.is_number()) {
        return "";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value.get<double>());
    return text;
}

/// The aggregate metrics a teacher reads in the CSV, besides pass/fail.
constexpr const char* kCsvMetrics[] = {"rms_position_error_m",  "final_position_error_m",
                                       "rms_heading_error_rad", "mean_nees",
                                       "nees_inside_fraction",  "mean_nis"};

std::string csv_header() {
    std::string header = "submission,students,status,passed,checks_passed,checks_total";
    for (const char* metric : kCsvMetrics) {
        header += std::string(",mean_") + metric;
    }
    return header + ",summary";
}

std::string csv_row(const fs::path& file, const nlohmann::json& grade) {
    std::string row = csv_field(file.filename().string()) + ","
                      + csv_field(grade.value("students", std::string{})) + ",graded,"
                      + (grade.value("passed", false) ? "yes" : "no") + ","
                      + std::to_string(grade.value("checks_passed", 0)) + ","
                      + std::to_string(grade.value("checks_total", 0));
    for (const char* metric : kCsvMetrics) {
        const nlohmann::json& aggregate = grade["aggregate"];
        row += ",";
        if (aggregate.contains(metric)) {
            row += number_text(aggregate[metric]["mean"]);
        }
    }
    return row + "," + csv_field(grade.value("summary", std::string{}));
}

std::string csv_error_row(const fs::path& file, const std::string& message) {
    std::string row = csv_field(file.filename().string()) + ",,error,,,";
    for (std::size_t i = 0; i < std::size(kCsvMetrics); ++i) {
        row += ",";
    }
    return row + "," + csv_field(message);
}

std::string problems_text(const InputError& error) {
    std::string text;
    for (const lessons::InputProblem& problem : error.problems()) {
        text += (text.empty() ? "" : "; ") + problem.message();
    }
    return text;
}

int grade_one(const GradeOptions& options, const lessons::Lesson& lesson) {
    nlohmann::json grade;
    try {
        const lessons::Submission submission =
            lessons::load_submission_file(options.submission, lesson);
        ProgressBar progress("grade " + fs::path(options.submission).filename().string());
        grade = lessons::grade_submission(
            lesson, submission, request_of(options), [&](std::size_t done, std::size_t total) {
                progress.update(static_cast<double>(done) / static_cast<double>(total),
                                std::to_string(done) + " / " + std::to_string(total) + " seeds");
            });
        progress.finish();
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    const std::string text = grade.dump(2) + "\n";
    if (options.out.empty()) {
        std::cout << text;
        std::cerr << grade["summary"].get<std::string>() << '\n';
        return kExitOk;
    }
    try {
        fileio::AtomicFile file(options.out);
        file.stream() << text;
        file.commit();
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kExitOutputFailed;
    }
    if (!options.quiet) {
        std::cout << grade["summary"].get<std::string>() << '\n';
    }
    return kExitOk;
}

std::vector<fs::path> submission_files(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
        if (entry.is_regular_file() && entry.path().extension() == ".toml") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());  // the rows' order does not depend on the disk
    return files;
}

void write_details(const fs::path& folder, const fs::path& submission,
                   const nlohmann::json& grade) {
    fileio::AtomicFile file(folder / (submission.stem().string() + ".json"));
    file.stream() << grade.dump(2) << '\n';
    file.commit();
}

int grade_folder(const GradeOptions& options, const lessons::Lesson& lesson) {
    lessons::analysis::Shard shard;
    std::vector<fs::path> files;
    try {
        if (!options.shard.empty()) {
            shard = lessons::analysis::parse_shard(options.shard);
        }
        if (!fs::is_directory(options.submissions)) {
            throw InputError({{"--submissions", 0, "", options.submissions, "not a folder"}});
        }
        const std::vector<fs::path> all = submission_files(options.submissions);
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (shard.takes(i)) {
                files.push_back(all[i]);
            }
        }
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    if (options.out.empty()) {
        std::cerr << "error: --out: grading a folder writes a CSV file; name it with --out\n";
        return kExitBadInput;
    }

    std::size_t graded = 0;
    std::size_t errors = 0;
    std::size_t passed = 0;
    try {
        if (!options.details.empty()) {
            fs::create_directories(options.details);
        }
        fileio::AtomicFile csv(options.out);
        csv.stream() << csv_header() << '\n';
        ProgressBar progress("grade");
        for (std::size_t i = 0; i < files.size(); ++i) {
            const auto show = [&](std::size_t done, std::size_t total) {
                const double fraction = (static_cast<double>(i)
                                         + static_cast<double>(done) / static_cast<double>(total))
                                        / static_cast<double>(files.size());
                progress.update(fraction, std::to_string(i) + " / " + std::to_string(files.size())
                                              + " submissions · " + files[i].filename().string());
            };
            try {
                const lessons::Submission submission =
                    lessons::load_submission_file(files[i], lesson);
                const nlohmann::json grade =
                    lessons::grade_submission(lesson, submission, request_of(options), show);
                csv.stream() << csv_row(files[i], grade) << '\n';
                if (!options.details.empty()) {
                    write_details(options.details, files[i], grade);
                }
                ++graded;
                if (grade.value("passed", false)) {
                    ++passed;
                }
            } catch (const InputError& error) {
                // A malformed submission is that student's row, not the end of the batch.
                csv.stream() << csv_error_row(files[i], problems_text(error)) << '\n';
                ++errors;
            }
        }
        progress.finish();
        csv.commit();
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kExitOutputFailed;
    }
    if (!options.quiet) {
        std::printf("%zu submissions: %zu graded (%zu passed), %zu with errors → %s\n",
                    files.size(), graded, passed, errors, options.out.c_str());
    }
    return kExitOk;
}

}  // namespace

void add_grade_subcommand(CLI::App& app, GradeOptions& options) {
    CLI::App* grade = app.add_subcommand(
        "grade", "Grade students' submissions on seeds they never saw (docs/lessons.md)");
    options.command = grade;
    grade->add_option("--lesson", options.lesson, "legofeup (built in) or a lesson file")
        ->capture_default_str();
    auto* one = grade
                    ->add_option("--submission", options.submission,
                                 "One submission (TOML): JSON on stdout or to --out")
                    ->check(CLI::ExistingFile);
    auto* folder = grade->add_option("--submissions", options.submissions,
                                     "A folder of submissions (*.toml): one CSV row each");
    one->excludes(folder);
    grade->add_option("--seeds", options.seeds, "Number of grading seeds (default: the lesson's)")
        ->check(CLI::Range(1, 100000));
    grade->add_option("--first-seed", options.first_seed,
                      "First grading seed (default: the lesson's; keep yours private)");
    grade->add_option("--laps", options.laps, "Laps of the square path")->check(CLI::Range(1, 100));
    grade->add_option("--jobs,-j", options.jobs, "Worker threads (default: all cores)")
        ->check(CLI::Range(0, 1024));
    grade->add_option("--out,-o", options.out, "JSON file (one submission) or CSV file (folder)");
    grade->add_option("--details", options.details,
                      "Folder: also write each submission's JSON result here");
    grade->add_option("--shard", options.shard,
                      "Folder: grade only shard i of n (1-based), for cluster job arrays");
    grade->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
}

int grade_command(const GradeOptions& options) {
    if (options.submission.empty() == options.submissions.empty()) {
        std::cerr << "error: grade: give --submission FILE or --submissions FOLDER\n";
        return kExitBadInput;
    }
    lessons::Lesson lesson;
    try {
        lesson = lessons::find_lesson(options.lesson);
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    return options.submission.empty() ? grade_folder(options, lesson) : grade_one(options, lesson);
}

}  // namespace legofeup::cli
