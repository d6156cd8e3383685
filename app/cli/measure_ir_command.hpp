#pragma once
// legofeup-cli measure-ir: IR calibration points taken on the simulated robot of a
// configuration, as a student takes them on a real one (docs/calibration.md), written as the
// CSV calibrate-ir reads. Exit codes as in commands.hpp.

#include <string>

#include "config_choice.hpp"

namespace CLI {
class App;
}

namespace legofeup::cli {

struct MeasureIrOptions : ConfigChoice {
    std::string out_file;  ///< the CSV written: adc,distance_m
    int readings = 20;     ///< readings averaged at each distance

    CLI::App* command = nullptr;
    bool requested() const;
};

void add_measure_ir_subcommand(CLI::App& app, MeasureIrOptions& options);
int measure_ir_command(const MeasureIrOptions& options);

}  // namespace legofeup::cli
