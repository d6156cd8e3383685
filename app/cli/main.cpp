// legofeup-cli: runs the LegoFeup experiments headless and deterministically, for grading,
// scripting and machines without a display.

#include <CLI/CLI.hpp>

#include "calibrate_commands.hpp"
#include "commands.hpp"
#include "legofeup/version.hpp"

int main(int argc, char** argv) {
    using namespace legofeup::cli;
    CLI::App app{"LegoFeup Lab command line: run the EKF localisation experiments headless."};
    app.set_version_flag("--version", std::string("legofeup-cli ") + legofeup::kVersion);
    app.require_subcommand(1);

    RunOptions options;
    const auto add_config_options = [&](CLI::App* command) {
        command->add_option("--experiment,-e", options.experiment,
                            "Guided experiment a … f (its preset is applied first)");
        command
            ->add_option("--config,-c", options.config_file,
                         "TOML configuration applied over the experiment's preset")
            ->check(CLI::ExistingFile);
        command->add_option("--seed,-s", options.seed, "Seed of every random stream");
        command->add_option("--laps,-l", options.laps, "Laps of the square path")
            ->check(CLI::Range(1, 1000));
    };

    CLI::App* run = app.add_subcommand("run", "Run one experiment and write its results");
    add_config_options(run);
    run->add_option("--out,-o", options.out_directory,
                    "Directory for trace.csv, summary.json and the plots")
        ->required();
    run->add_flag("!--no-plots", options.plots, "Skip the PNG and SVG plots");
    run->add_flag("--quiet,-q", options.quiet, "Print nothing on success");
    run->add_option("--link", options.link,
                    "lockstep (the in-process simulator, deterministic), udp://HOST:PORT (a "
                    "running legofeup-sim, docs/protocol.md), or an NXT: bt:XX:XX:XX:XX:XX:XX, "
                    "serial:/dev/rfcomm0 or tcp:HOST:PORT (docs/nxt.md)");
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

    app.add_subcommand("experiments", "List the guided experiments a … f");

    CLI::App* config = app.add_subcommand(
        "config", "Print the configuration a run would use, as a TOML file to edit");
    add_config_options(config);

    CalibrateOptions calibrate;
    add_calibrate_subcommands(app, calibrate);

    CLI11_PARSE(app, argc, argv);

    if (app.got_subcommand("run")) {
        return run_command(options);
    }
    if (calibrate.requested()) {
        return calibrate_command(calibrate);
    }
    if (app.got_subcommand("experiments")) {
        return experiments_command();
    }
    return config_command(options);
}
