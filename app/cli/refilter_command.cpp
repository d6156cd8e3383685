#include "refilter_command.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "commands.hpp"
#include "input_problems.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/report/refilter_plots.hpp"

namespace legofeup::cli {
namespace {

namespace fs = std::filesystem;
using lessons::RefilterResult;
using lessons::RunConfig;
using lessons::RunLog;

/// The settings `changed` sets differently from `recorded`, as "key = value" lines of the
/// configuration file (both documents list every setting in the same order).
std::vector<std::string> changed_settings(const RunConfig& recorded, const RunConfig& changed) {
    std::istringstream old_lines(lessons::config_to_toml(recorded, ""));
    std::istringstream new_lines(lessons::config_to_toml(changed, ""));
    std::vector<std::string> changes;
    std::string section;
    for (std::string a, b; std::getline(old_lines, a) && std::getline(new_lines, b);) {
        if (b.rfind('[', 0) == 0) {
            section = b.substr(1, b.find(']') - 1) + ".";
        }
        if (a != b) {
            const std::size_t comment = b.find("  # ");
            changes.push_back(section + b.substr(0, comment));
        }
    }
    return changes;
}

std::string number(double x) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
    return {buffer, result.ptr};
}

void write_csv(const RefilterResult& result, const fs::path& path) {
    fileio::AtomicFile file(path);
    std::ostream& out = file.stream();
    out << "t,frame_missing,x_true,y_true,th_true,"
           "x_old,y_old,th_old,sx_old,sy_old,sth_old,"
           "x_new,y_new,th_new,sx_new,sy_new,sth_new\n";
    for (const lessons::RefilterStep& step : result.steps) {
        out << number(step.time) << ',' << (step.frame_missing ? 1 : 0);
        if (step.truth) {
            out << ',' << number(step.truth->x) << ',' << number(step.truth->y) << ','
                << number(step.truth->theta);
        } else {
            out << ",,,";
        }
        for (const auto& [x, p] : {std::pair(&step.old_estimate, &step.old_covariance),
                                   std::pair(&step.new_estimate, &step.new_covariance)}) {
            for (int i = 0; i < kStateSize; ++i) {
                out << ',' << number((*x)(i));
            }
            for (int i = 0; i < kStateSize; ++i) {
                out << ',' << number(std::sqrt(std::max(0.0, (*p)(i, i))));
            }
        }
        out << '\n';
    }
    file.commit();
}

nlohmann::json summary_json(const RefilterOptions& options, const RunLog& log,
                            const RefilterResult& result, const std::vector<std::string>& changes) {
    nlohmann::json json = {
        {"log", options.log_file},
        {"config", options.config_file},
        {"title", log.header.title},
        {"program", log.header.program},
        {"link", log.header.link},
        {"seed", log.header.seed},
        {"world", log.header.world},
        {"steps", result.steps.size()},
        {"log_ended", log.ended},
        {"log_truncated", log.truncated},
        {"log_notes", log.notes},
        {"changed_settings", changes},
        {"recorded_replay_reproduces_run", result.reproduces_recording()},
        {"recorded_replay_max_deviation", result.old_replay_deviation},
    };
    // Without a truth (a real robot) the counts stand and the errors and NEES are null.
    json["metrics"] = {{"recorded", lessons::metrics_to_json(result.old_metrics)},
                       {"new", lessons::metrics_to_json(result.new_metrics)}};
    return json;
}

void print_comparison(const RunLog& log, const RefilterResult& result,
                      const std::vector<std::string>& changes) {
    std::printf("Re-filtered %s (seed %llu, %zu steps, %s)\n", log.header.title.c_str(),
                static_cast<unsigned long long>(log.header.seed), result.steps.size(),
                log.header.link.empty() ? "link unknown" : log.header.link.c_str());
    if (changes.empty()) {
        std::printf("  new configuration: the recorded one (no setting changed)\n");
    }
    for (const std::string& change : changes) {
        std::printf("  changed: %s\n", change.c_str());
    }
    if (result.reproduces_recording()) {
        std::printf("  the replay with the recorded configuration reproduces the run exactly\n");
    } else {
        std::printf(
            "  warning: the replay with the recorded configuration differs from the "
            "recorded estimates by up to %g (recorded by another version?)\n",
            result.old_replay_deviation);
    }
    const RunMetrics& a = result.old_metrics;
    const RunMetrics& b = result.new_metrics;
    std::printf("  %-30s %12s %12s\n", "", "recorded", "new");
    // Both replays read the same records, so they have a truth on the same steps or none.
    const auto row = [](const char* label, double old_value, double new_value) {
        std::printf("  %-30s %12.4f %12.4f\n", label, old_value, new_value);
    };
    using Of = double (*)(const TruthMetrics&);
    const auto truth_row = [&](const char* label, Of of) {
        if (a.truth && b.truth) {
            row(label, of(*a.truth), of(*b.truth));
        } else {
            // "—" is three bytes and one column: padded by hand to the numbers' 12 columns.
            std::printf("  %-30s %s %s\n", label, "           —", "           —");
        }
    };
    truth_row("RMS position error (m)", [](const TruthMetrics& t) { return t.rms_position_error; });
    truth_row("max position error (m)", [](const TruthMetrics& t) { return t.max_position_error; });
    truth_row("final position error (m)",
              [](const TruthMetrics& t) { return t.final_position_error; });
    truth_row("RMS heading error (deg)",
              [](const TruthMetrics& t) { return radians_to_degrees(t.rms_heading_error); });
    truth_row("final heading error (deg)",
              [](const TruthMetrics& t) { return radians_to_degrees(t.final_heading_error); });
    row("wall updates applied", static_cast<double>(a.updates_applied),
        static_cast<double>(b.updates_applied));
    row("updates rejected by the filter", static_cast<double>(a.updates_rejected),
        static_cast<double>(b.updates_rejected));
    truth_row("mean NEES", [](const TruthMetrics& t) { return t.mean_nees; });
    truth_row("mean NEES 95% bounds, lower",
              [](const TruthMetrics& t) { return t.time_average_nees_bounds.lower; });
    truth_row("mean NEES 95% bounds, upper",
              [](const TruthMetrics& t) { return t.time_average_nees_bounds.upper; });
    truth_row("NEES inside 95% bounds (%)",
              [](const TruthMetrics& t) { return 100.0 * t.nees_inside_fraction; });
    row("mean NIS", a.mean_nis, b.mean_nis);
    std::printf(
        "  (mean NEES bounds: of a time average of that many effective samples; NEES inside: "
        "of one step, [%.3f, %.3f])\n",
        a.nees_bounds.lower, a.nees_bounds.upper);
    if (!a.truth) {
        std::printf(
            "  — : no ground truth in the log (a real robot), so no errors or NEES; see the "
            "estimates in refilter.csv\n");
    }
}

// Writes refilter.csv, summary.json and the plots; returns the plots' base names.
std::vector<std::string> write_outputs(const RefilterOptions& options, const RunLog& log,
                                       const RunConfig& config, const RefilterResult& result,
                                       const std::vector<std::string>& changes) {
    const fs::path out(options.out_directory);
    fs::create_directories(out);
    write_csv(result, out / "refilter.csv");
    fileio::AtomicFile summary(out / "summary.json");
    summary.stream() << summary_json(options, log, result, changes).dump(2) << '\n';
    summary.commit();
    if (!options.plots) {
        return {};
    }
    return report::write_refilter_plots(result, lessons::resolve(config).world, out,
                                        "LegoFeup " + log.header.title);
}

}  // namespace

bool RefilterOptions::requested() const {
    return command != nullptr && command->parsed();
}

void add_refilter_subcommand(CLI::App& app, RefilterOptions& options) {
    CLI::App* command = app.add_subcommand(
        "refilter",
        "Replay a recorded run (run --record) with a new configuration: the same raw readings, "
        "other Q, R, gate or P0; compares the recorded and the new estimates (open loop: the "
        "robot drives as recorded)");
    command->add_option("--log", options.log_file, "The run log written by run --record")
        ->required();
    command->add_option("--config,-c", options.config_file,
                        "TOML applied over the recorded configuration (default: none, which "
                        "checks that the replay reproduces the run)");
    command->add_option("--out,-o", options.out_directory,
                        "Directory for refilter.csv, summary.json and the overlay plots "
                        "(default: print the comparison only)");
    command->add_flag("!--no-plots", options.plots, "Skip the PNG and SVG plots");
    command->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
    options.command = command;
}

int refilter_command(const RefilterOptions& options) {
    RunLog log;
    RunConfig config;
    RefilterResult result;
    try {
        log = lessons::load_run_log(options.log_file);
        config = options.config_file.empty()
                     ? log.config
                     : lessons::load_config_file(options.config_file, log.config);
        result = lessons::refilter(log, config);
    } catch (const lessons::InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    for (const std::string& note : log.notes) {
        std::cerr << "note: " << options.log_file << ": " << note << '\n';
    }
    const std::vector<std::string> changes = changed_settings(log.config, config);
    std::vector<std::string> plots;
    if (!options.out_directory.empty()) {
        try {
            plots = write_outputs(options, log, config, result, changes);
        } catch (const std::exception& failure) {
            std::cerr << "error: " << failure.what() << '\n';
            return kExitOutputFailed;
        }
    }
    if (!options.quiet) {
        print_comparison(log, result, changes);
        if (!options.out_directory.empty()) {
            std::printf(
                "Results in %s: refilter.csv, summary.json%s\n", options.out_directory.c_str(),
                options.plots ? ", refilter_trajectory and refilter_errors (.png and .svg)" : "");
        }
    }
    return kExitOk;
}

}  // namespace legofeup::cli
