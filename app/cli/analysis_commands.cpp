#include "analysis_commands.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "input_problems.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/analysis/shard_file.hpp"
#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/report/analysis_plots.hpp"
#include "output_directory.hpp"
#include "progress_bar.hpp"

namespace legofeup::cli {
namespace {

namespace fs = std::filesystem;
using namespace lessons::analysis;
using lessons::InputError;

Shard shard_of(const AnalysisOptions& options) {
    return options.shard.empty() ? Shard{} : parse_shard(options.shard);
}

int jobs_of(const AnalysisOptions& options) {
    return options.jobs > 0 ? options.jobs : available_jobs();
}

void write_text(const fs::path& path, const std::string& text) {
    fileio::AtomicFile file(path);
    file.stream() << text;
    file.commit();
}

std::string shard_file_name(const std::string& kind, const Shard& shard) {
    return kind + "-shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count)
           + ".json";
}

/// Runs done out of the total and the rate, on a progress bar, timing the whole batch.
class BatchClock {
  public:
    explicit BatchClock(const std::string& label) : bar_(label) {}
    BatchProgress progress() {
        return [this](std::size_t finished, std::size_t total) {
            char detail[80];
            std::snprintf(detail, sizeof detail, "%zu/%zu runs, %.1f runs/s", finished, total,
                          static_cast<double>(finished) / std::max(seconds(), 1e-9));
            bar_.update(static_cast<double>(finished) / static_cast<double>(total), detail);
        };
    }
    double seconds() const {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    }
    void finish() { bar_.finish(); }

  private:
    ProgressBar bar_;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

void print_timing(std::size_t runs, int jobs, double seconds) {
    std::printf("  %zu runs on %d job%s in %.2f s (%.1f runs/s)\n", runs, jobs,
                jobs == 1 ? "" : "s", seconds, static_cast<double>(runs) / std::max(seconds, 1e-9));
}

MonteCarloSummary write_monte_carlo_outputs(const BatchHeader& header, const MonteCarloSums& sums,
                                            const fs::path& out, bool plots) {
    const MonteCarloSummary summary = summarize(sums, header.control_period);
    write_text(out / "summary.json", monte_carlo_summary_json(header, summary).dump(2) + "\n");
    write_text(out / "steps.csv", monte_carlo_steps_csv(summary));
    write_text(out / "runs.csv", monte_carlo_runs_csv(summary.runs));
    if (plots) {
        report::write_monte_carlo_plots(summary, out, "LegoFeup " + header.title);
    }
    return summary;
}

void print_monte_carlo(const BatchHeader& header, const MonteCarloSummary& s, const fs::path& out,
                       bool plots) {
    std::printf("Monte Carlo of %s: %zu runs, seeds %llu … %llu\n", header.title.c_str(),
                s.runs.size(), static_cast<unsigned long long>(header.first_seed),
                static_cast<unsigned long long>(header.first_seed + header.runs - 1));
    // mean_nees averages over runs and time: its bounds come from the runs' effective samples
    // (docs/experiments.md), not from the bounds of one step's average over the runs.
    const ChiSquareInterval& average = s.time_average_nees_bounds;
    std::printf(
        "  mean NEES %.2f (a consistent filter's lies in [%.2f, %.2f] at 95%%, the runs' "
        "dispersion %.2f taken in); each run's mean NEES inside its own bounds in %.0f%% of the "
        "runs; the NEES averaged over the runs inside its bounds at %.0f%% of the steps\n",
        s.mean_nees, average.lower, average.upper, s.nees_dispersion,
        100.0 * s.runs_nees_inside_time_average_fraction, 100.0 * s.nees_inside_fraction);
    std::printf(
        "  mean NIS %.2f (2 if consistent); averaged NIS inside its bounds at %.0f%% of "
        "the steps with updates\n",
        s.mean_nis, 100.0 * s.nis_inside_fraction);
    std::printf(
        "  RMS position error %.3f ± %.3f m (min %.3f, max %.3f); final error median "
        "%.3f m, 95th percentile %.3f m\n",
        s.rms_position_error.mean, s.rms_position_error.stddev, s.rms_position_error.min,
        s.rms_position_error.max, s.final_position_error.median, s.final_position_error.p95);
    if (s.runs_finished < s.runs.size()) {
        std::printf("  %zu runs stopped at the time limit before the routine finished\n",
                    s.runs.size() - s.runs_finished);
    }
    std::printf("Results in %s: summary.json, steps.csv, runs.csv%s\n", out.string().c_str(),
                plots ? ", nees, nis, rms_errors and final_errors (.png and .svg)" : "");
}

void write_sweep_outputs(const BatchHeader& header, const std::vector<SweepCell>& cells,
                         const fs::path& out, bool plots) {
    write_text(out / "summary.json", sweep_summary_json(header, cells).dump(2) + "\n");
    write_text(out / "cells.csv", sweep_cells_csv(cells));
    if (plots) {
        report::write_sweep_plots(cells, header.q_scales, header.r_scales, out,
                                  "LegoFeup " + header.title);
    }
}

void print_sweep(const BatchHeader& header, const std::vector<SweepCell>& cells,
                 const fs::path& out, bool plots) {
    std::printf("Sweep of %s: %zu Q × %zu R scales, %zu runs per cell\n", header.title.c_str(),
                header.q_scales.size(), header.r_scales.size(), header.runs);
    std::printf("  %8s %8s %12s %10s %8s\n", "Q ×", "R ×", "RMS err (m)", "mean NEES", "inside");
    for (const SweepCell& c : cells) {
        std::printf("  %8g %8g %12.3f %10.3g %7.0f%%\n", c.q_scale, c.r_scale, c.rms_position_error,
                    c.mean_nees, 100.0 * c.nees_inside_fraction);
    }
    std::printf("Results in %s: summary.json, cells.csv%s\n", out.string().c_str(),
                plots ? ", sweep_rms_error and sweep_nees_consistency (.png and .svg)" : "");
}

/// Writes a shard file into --out and says what it holds.
void write_shard(const AnalysisOptions& options, const BatchHeader& header, const Shard& shard,
                 const nlohmann::json& document, const std::string& part, std::size_t runs,
                 double seconds) {
    const fs::path file = fs::path(options.out) / shard_file_name(header.kind, shard);
    write_text(file, document.dump() + "\n");
    if (!options.quiet) {
        std::printf("%s shard %s of %s: %s\n", header.kind.c_str(), options.shard.c_str(),
                    header.title.c_str(), part.c_str());
        print_timing(runs, jobs_of(options), seconds);
        std::printf("Shard in %s; join the shards with legofeup-cli merge\n",
                    file.string().c_str());
    }
}

int montecarlo_command(const AnalysisOptions& options) {
    MonteCarloSpec spec;
    BatchHeader header;
    Shard shard;
    try {
        std::string title;
        spec = {compose_cli_config(options, title), static_cast<std::size_t>(options.runs),
                options.first_seed};
        lessons::resolve(spec.config);  // refuse a configuration that would not run
        shard = shard_of(options);
        header = monte_carlo_header(spec, options.experiment, title);
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    const fs::path out(options.out);
    if (!create_output_directory(out)) {
        return kExitOutputFailed;
    }
    BatchClock clock("montecarlo");
    const MonteCarloSums sums = run_monte_carlo(spec, options.jobs, shard, clock.progress());
    clock.finish();
    const double seconds = clock.seconds();
    if (!options.shard.empty()) {
        write_shard(
            options, header, shard, monte_carlo_shard(header, shard, sums),
            std::to_string(sums.runs.size()) + " of " + std::to_string(header.runs) + " runs",
            sums.runs.size(), seconds);
        return kExitOk;
    }
    const MonteCarloSummary summary = write_monte_carlo_outputs(header, sums, out, options.plots);
    if (!options.quiet) {
        print_monte_carlo(header, summary, out, options.plots);
        print_timing(summary.runs.size(), jobs_of(options), seconds);
    }
    return kExitOk;
}

int sweep_command(const AnalysisOptions& options) {
    SweepSpec spec;
    BatchHeader header;
    Shard shard;
    try {
        std::string title;
        spec.config = compose_cli_config(options, title);
        spec.q_scales = parse_scales(options.q, "--q");
        spec.r_scales = parse_scales(options.r, "--r");
        spec.runs = static_cast<std::size_t>(options.runs);
        spec.first_seed = options.first_seed;
        lessons::resolve(spec.config);
        shard = shard_of(options);
        header = sweep_header(spec, options.experiment, title);
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    const fs::path out(options.out);
    if (!create_output_directory(out)) {
        return kExitOutputFailed;
    }
    BatchClock clock("sweep");
    std::vector<SweepCell> cells;
    try {
        cells = run_sweep(spec, options.jobs, shard, clock.progress());
    } catch (const InputError& error) {  // Q or R scaled out of the valid range
        clock.finish();
        report_problems(error);
        return kExitBadInput;
    }
    clock.finish();
    const double seconds = clock.seconds();
    const std::size_t runs = cells.size() * spec.runs;
    if (!options.shard.empty()) {
        write_shard(
            options, header, shard, sweep_shard(header, shard, cells),
            std::to_string(cells.size()) + " of " + std::to_string(spec.cell_count()) + " cells",
            runs, seconds);
        return kExitOk;
    }
    write_sweep_outputs(header, cells, out, options.plots);
    if (!options.quiet) {
        print_sweep(header, cells, out, options.plots);
        print_timing(runs, jobs_of(options), seconds);
    }
    return kExitOk;
}

int merge_command(const AnalysisOptions& options) {
    MergedBatch merged;
    try {
        std::vector<ShardFile> shards;
        for (const std::string& file : options.shard_files) {
            shards.push_back(read_shard_file(file));
        }
        merged = merge_shards(shards);
    } catch (const InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    const fs::path out(options.out);
    if (!create_output_directory(out)) {
        return kExitOutputFailed;
    }
    if (merged.header.kind == "montecarlo") {
        const MonteCarloSummary summary =
            write_monte_carlo_outputs(merged.header, merged.sums, out, options.plots);
        if (!options.quiet) {
            print_monte_carlo(merged.header, summary, out, options.plots);
        }
    } else {
        write_sweep_outputs(merged.header, merged.cells, out, options.plots);
        if (!options.quiet) {
            print_sweep(merged.header, merged.cells, out, options.plots);
        }
    }
    return kExitOk;
}

void add_output_options(CLI::App* command, AnalysisOptions& options) {
    command->add_option("--out,-o", options.out, "Directory for the results")->required();
    command->add_flag("!--no-plots", options.plots, "Skip the PNG and SVG plots");
    command->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
}

void add_batch_options(CLI::App* command, AnalysisOptions& options, const char* runs_help) {
    add_config_options(*command, options, false);
    command->add_option("--runs,-n", options.runs, runs_help)
        ->required()
        ->check(CLI::Range(1, 10000000));
    command
        ->add_option("--first-seed", options.first_seed,
                     "Seed of the first run; run k uses first seed + k")
        ->capture_default_str();
    command->add_option("--jobs,-j", options.jobs, "Runs in parallel (0: all cores)")
        ->capture_default_str()
        ->check(CLI::Range(0, 4096));
    command->add_option("--shard", options.shard,
                        "i/n: run only part i of n (a cluster job array) and write a shard "
                        "file into --out for legofeup-cli merge");
    add_output_options(command, options);
}

}  // namespace

bool AnalysisOptions::requested() const {
    for (const CLI::App* command : {montecarlo_command, sweep_command, merge_command}) {
        if (command != nullptr && command->parsed()) {
            return true;
        }
    }
    return false;
}

void add_analysis_subcommands(CLI::App& app, AnalysisOptions& options) {
    options.montecarlo_command =
        app.add_subcommand("montecarlo",
                           "Many seeded runs of one configuration: averaged NEES and NIS against "
                           "their χ² bounds, error statistics and plots");
    add_batch_options(options.montecarlo_command, options, "Number of runs (seeds)");

    options.sweep_command = app.add_subcommand(
        "sweep",
        "A grid of Q × R scales, each cell a Monte Carlo: heat maps of the RMS error "
        "and of the NEES consistency");
    add_batch_options(options.sweep_command, options, "Runs (seeds) per cell");
    options.sweep_command
        ->add_option("--q", options.q,
                     "Factors for q11 and q22: a list 0.1,1,10 or LOW:HIGH:COUNT log-spaced")
        ->required();
    options.sweep_command
        ->add_option("--r", options.r,
                     "Factors for r11 and r22: a list 0.1,1,10 or LOW:HIGH:COUNT log-spaced")
        ->required();

    options.merge_command = app.add_subcommand(
        "merge",
        "Join the shard files of a montecarlo or sweep run with --shard i/n and write "
        "what the unsharded command writes");
    options.merge_command->add_option("shards", options.shard_files, "The shard files (all n)")
        ->required()
        ->check(CLI::ExistingFile);
    add_output_options(options.merge_command, options);
}

int analysis_command(const AnalysisOptions& options) {
    try {
        if (options.montecarlo_command->parsed()) {
            return montecarlo_command(options);
        }
        if (options.sweep_command->parsed()) {
            return sweep_command(options);
        }
        return merge_command(options);
    } catch (const std::exception& failure) {
        std::cerr << "error: " << failure.what() << '\n';
        return kExitOutputFailed;
    }
}

}  // namespace legofeup::cli
