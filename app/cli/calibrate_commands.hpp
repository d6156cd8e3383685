#pragma once
// legofeup-cli calibrate-ir and calibrate-odometry: calibrating a real robot and writing the
// results to its profile (docs/calibration.md). Exit codes as in commands.hpp.

#include <string>

namespace CLI {
class App;
}

namespace legofeup::cli {

struct CalibrateOptions {
    // calibrate-ir
    std::string points_file;     ///< CSV: adc,distance_m
    std::string plot_directory;  ///< "" = no plot
    // calibrate-odometry
    double side = 0.0;              ///< L, m
    std::string clockwise;          ///< "x,y;x,y;…" return errors, m
    std::string counter_clockwise;  ///< "x,y;x,y;…"
    // both
    std::string profile;  ///< robot profile to update (created if missing); "" = none

    CLI::App* ir_command = nullptr;
    CLI::App* odometry_command = nullptr;

    /// True when the command line chose one of the calibrate subcommands.
    bool requested() const;
};

/// Adds calibrate-ir and calibrate-odometry to `app`, filling `options`.
void add_calibrate_subcommands(CLI::App& app, CalibrateOptions& options);

/// Runs the calibrate subcommand the command line chose.
int calibrate_command(const CalibrateOptions& options);

}  // namespace legofeup::cli
