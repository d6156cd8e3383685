// legofeup-cli: runs the LegoFeup experiments headless and deterministically, for grading,
// scripting and machines without a display.

#include <CLI/CLI.hpp>

#include "analysis_commands.hpp"
#include "calibrate_commands.hpp"
#include "commands.hpp"
#include "grade_command.hpp"
#include "legofeup/lessons/links/link_registry.hpp"
#include "legofeup/version.hpp"
#include "lesson_commands.hpp"
#include "measure_ir_command.hpp"
#include "refilter_command.hpp"
#include "report_command.hpp"

int main(int argc, char** argv) {
    using namespace legofeup::cli;
    CLI::App app{"LegoFeup Lab command line: run the EKF localisation experiments headless."};
    app.set_version_flag("--version", std::string("legofeup-cli ") + legofeup::kVersion);
    app.require_subcommand(1);

    RunOptions options;

    CLI::App* run = app.add_subcommand("run", "Run one experiment and write its results");
    add_config_options(*run, options);
    run->add_option("--out,-o", options.out_directory,
                    "Directory for trace.csv, summary.json and the plots")
        ->required();
    run->add_flag("!--no-plots", options.plots, "Skip the PNG and SVG plots");
    run->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
    run->add_option("--link", options.link,
                    "Where the robot is, one of: " + legofeup::lessons::link_forms()
                        + " (docs/protocol.md, docs/nxt.md)");
    run->add_flag("--relay", options.relay,
                  "NXT: read the brick through the relay program legofeup.rxe (docs/nxt.md)");
    run->add_option("--profile", options.profile,
                    "Robot profile (TOML, docs/calibration.md): the filter's wheel geometry and "
                    "IR curve, and for an NXT its wiring and motor constant")
        ->check(CLI::ExistingFile);
    run->add_option("--truth", options.truth_url,
                    "NXT: an emulated brick's ground truth, udp://HOST:PORT (printed by "
                    "legofeup-nxt-emu); a real robot has none");
    run->add_option("--truth-port", options.truth_port,
                    "The simulator's ground-truth port (default: link port + 1)")
        ->check(CLI::Range(1, 65535));
    run->add_option("--control-port", options.control_port,
                    "The simulator's control port (default: link port + 2)")
        ->check(CLI::Range(1, 65535));
    run->add_option("--record", options.record_file,
                    "Also record every step (raw frames, commands, truth, configuration) to this "
                    "run log, flushed as it goes, for refilter (docs/recording.md)");

    app.add_subcommand("experiments", "List the guided experiments a … h");

    CLI::App* config = app.add_subcommand(
        "config", "Print the configuration a run would use, as a TOML file to edit");
    add_config_options(*config, options);

    CalibrateOptions calibrate;
    add_calibrate_subcommands(app, calibrate);
    MeasureIrOptions measure_ir;
    add_measure_ir_subcommand(app, measure_ir);
    LessonOptions lesson;
    add_lesson_subcommands(app, lesson);
    AnalysisOptions analysis;
    add_analysis_subcommands(app, analysis);
    RefilterOptions refilter;
    add_refilter_subcommand(app, refilter);

    GradeOptions grade;
    add_grade_subcommand(app, grade);

    ReportOptions report;
    add_report_subcommand(app, report);

    CLI11_PARSE(app, argc, argv);

    if (app.got_subcommand("run")) {
        return run_command(options);
    }
    if (calibrate.requested()) {
        return calibrate_command(calibrate);
    }
    if (measure_ir.requested()) {
        return measure_ir_command(measure_ir);
    }
    if (lesson.requested()) {
        return lesson_command(lesson);
    }
    if (analysis.requested()) {
        return analysis_command(analysis);
    }
    if (refilter.requested()) {
        return refilter_command(refilter);
    }
    if (app.got_subcommand("grade")) {
        return grade_command(grade);
    }
    if (app.got_subcommand("report")) {
        return report_command(report);
    }
    if (app.got_subcommand("experiments")) {
        return experiments_command();
    }
    return config_command(options);
}
