#include "config_choice.hpp"

#include <CLI/CLI.hpp>
#include <filesystem>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/experiments.hpp"

namespace legofeup::cli {

void add_config_options(CLI::App& command, ConfigChoice& choice, bool seed_option) {
    command.add_option("--experiment,-e", choice.experiment,
                       "Guided experiment a … h (its preset is applied first)");
    command
        .add_option("--config,-c", choice.config_file,
                    "TOML configuration applied over the experiment's preset")
        ->check(CLI::ExistingFile);
    if (seed_option) {
        command.add_option("--seed,-s", choice.seed, "Seed of every random stream");
    }
    command.add_option("--laps,-l", choice.laps, "Laps of the square path")
        ->check(CLI::Range(1, 1000));
}

lessons::RunConfig compose_cli_config(const ConfigChoice& choice, std::string& title) {
    lessons::RunConfig config =
        lessons::compose_config({choice.experiment, choice.config_file, choice.seed});
    title = "default configuration";
    if (const lessons::Experiment* experiment = lessons::find_experiment(choice.experiment)) {
        title = "experiment " + experiment->id + ": " + experiment->title;
    }
    if (!choice.config_file.empty()) {
        title += " + " + std::filesystem::path(choice.config_file).filename().string();
    }
    if (choice.laps) {
        config.laps = *choice.laps;
        config.origins["laps"] = {"--laps", 0, "laps"};
    }
    return config;
}

}  // namespace legofeup::cli
