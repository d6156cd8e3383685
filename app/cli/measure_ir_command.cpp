#include "measure_ir_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "commands.hpp"
#include "input_problems.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/calibration/simulated_ir_points.hpp"

namespace legofeup::cli {

namespace {

// Front sensor's points first, then the rear's (measure_simulated_ir_points' order), each
// line naming its sensor, so that calibrate-ir fits each sensor's own curve.
void write_points(std::ostream& out, const std::vector<lessons::IrCalibrationPoint>& points,
                  const std::string& title, std::uint64_t seed, sim::IrSensorModel model,
                  int readings) {
    out << "# IR calibration points taken on the simulated robot of " << title << ", seed " << seed
        << " (IR model " << sim::to_string(model) << "), each the mean of " << readings
        << " readings\n";
    out << "adc,distance_m,sensor\n";
    for (const lessons::IrCalibrationPoint& point : points) {
        char line[64];
        std::snprintf(line, sizeof line, "%.2f,%.2f,%s\n", point.adc, point.distance,
                      point.sensor == kFrontSensor ? "front" : "rear");
        out << line;
    }
}

}  // namespace

bool MeasureIrOptions::requested() const {
    return command != nullptr && command->parsed();
}

void add_measure_ir_subcommand(CLI::App& app, MeasureIrOptions& options) {
    CLI::App* command = app.add_subcommand(
        "measure-ir",
        "Take IR calibration points on the simulated robot (a target at 4-30 cm) for "
        "calibrate-ir");
    add_config_options(*command, options);
    command->add_option("--out,-o", options.out_file, "CSV file to write (adc,distance_m,sensor)")
        ->required();
    command->add_option("--readings", options.readings, "Readings averaged at each distance")
        ->check(CLI::Range(1, 1000));
    options.command = command;
}

int measure_ir_command(const MeasureIrOptions& options) {
    std::string title;
    lessons::ResolvedRun run;
    try {
        run = lessons::resolve(compose_cli_config(options, title));
    } catch (const lessons::InputError& error) {
        report_problems(error);
        return kExitBadInput;
    }
    const std::vector<double> distances = lessons::advised_ir_calibration_distances();
    const std::uint64_t seed = run.config.seed;
    const auto points =
        lessons::measure_simulated_ir_points(run.robot, seed, distances, options.readings);
    try {
        fileio::AtomicFile file(options.out_file);
        write_points(file.stream(), points, title, seed, run.robot.ir_model, options.readings);
        file.commit();
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kExitOutputFailed;
    }
    std::printf("%zu points written to %s\n", points.size(), options.out_file.c_str());
    return kExitOk;
}

}  // namespace legofeup::cli
