#include "calibrate_commands.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <span>

#include "commands.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/calibration/ir_calibration.hpp"
#include "legofeup/lessons/calibration/umbmark.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/robot_profile.hpp"
#include "legofeup/report/figure.hpp"

namespace legofeup::cli {
namespace {

namespace fs = std::filesystem;
using lessons::InputError;
using lessons::RobotProfile;

void report(const InputError& error) {
    for (const lessons::InputProblem& problem : error.problems()) {
        std::cerr << "error: " << problem.message() << '\n';
    }
}

// The profile to start from: the file if it exists, else the nominal robot.
RobotProfile starting_profile(const std::string& path) {
    if (!path.empty() && fs::exists(path)) {
        return lessons::load_robot_profile(path);
    }
    return RobotProfile{};
}

// Saves the updated profile; the exit code.
int write_profile(const std::string& path, const RobotProfile& profile) {
    if (path.empty()) {
        return kExitOk;
    }
    try {
        lessons::save_robot_profile(path, profile);
    } catch (const InputError& error) {
        report(error);
        return kExitBadInput;
    } catch (const std::exception& error) {
        std::cerr << "error: " << error.what() << '\n';
        return kExitOutputFailed;
    }
    std::printf("Profile written: %s\n", path.c_str());
    return kExitOk;
}

// A "+" marker at each point, drawn as two short strokes (the figure draws lines only);
// `dx`, `dy` are half the marker's size in data units.
plot::Line markers(const std::vector<double>& xs, const std::vector<double>& ys, double dx,
                   double dy, plot::Color color, std::string label) {
    constexpr double kGap = std::numeric_limits<double>::quiet_NaN();
    plot::Line line{{}, {}, color, 1.5, false, std::move(label)};
    for (std::size_t i = 0; i < xs.size(); ++i) {
        line.x.insert(line.x.end(), {xs[i] - dx, xs[i] + dx, kGap, xs[i], xs[i], kGap});
        line.y.insert(line.y.end(), {ys[i], ys[i], kGap, ys[i] - dy, ys[i] + dy, kGap});
    }
    return line;
}

double span_of(const std::vector<double>& values) {
    const auto [low, high] = std::minmax_element(values.begin(), values.end());
    return std::max(*high - *low, 1e-9);
}

void write_ir_plot(const std::vector<lessons::IrCalibrationPoint>& points,
                   const lessons::IrFit& fit, const SharpIrCurve& start, const fs::path& base) {
    std::vector<double> adc;
    std::vector<double> measured;
    std::vector<double> residual_mm;
    for (std::size_t i = 0; i < points.size(); ++i) {
        adc.push_back(points[i].adc);
        measured.push_back(points[i].distance);
        residual_mm.push_back(1e3 * fit.residuals[i]);
    }
    const double low = *std::min_element(adc.begin(), adc.end());
    const double high = *std::max_element(adc.begin(), adc.end());
    const double margin = 0.05 * span_of(adc);
    // The curves over the measured A range and a little beyond, short of any pole.
    const double first = std::max({low - margin, -fit.curve.c_r + 1.0, -start.c_r + 1.0, 0.0});
    const double last = high + margin;
    std::vector<double> curve_adc;
    std::vector<double> fitted;
    std::vector<double> nominal;
    constexpr int kSamples = 200;
    for (int k = 0; k <= kSamples; ++k) {
        const double a = first + (last - first) * k / kSamples;
        curve_adc.push_back(a);
        fitted.push_back(distance_from_adc(a, fit.curve).distance);
        nominal.push_back(distance_from_adc(a, start).distance);
    }

    plot::Figure figure("IR sensor calibration (paper eq. 2)", 2, 1200, 1000);
    plot::Panel& curve = figure.panel(0);
    curve.title = "Measured distances and the fitted curve D = a(C_M/(A + C_R) - b)";
    curve.x_label = "A/D value A";
    curve.y_label = "distance D (m)";
    curve.y_min = 0.0;
    curve.y_max = 1.15 * *std::max_element(measured.begin(), measured.end());
    curve.lines.push_back(
        {curve_adc, nominal, plot::colors::kOdometry, 1.2, true, "start curve (before)"});
    curve.lines.push_back({curve_adc, fitted, plot::colors::kEstimate, 2.0, false, "fitted curve"});
    curve.lines.push_back(markers(adc, measured, 0.006 * span_of(curve_adc), 0.012 * *curve.y_max,
                                  plot::colors::kTruth, "measured"));

    plot::Panel& residuals = figure.panel(1);
    char title[160];
    std::snprintf(title, sizeof title,
                  "Residuals, measured - fitted (RMS %.2f mm, largest %.2f mm)",
                  1e3 * fit.rms_residual, 1e3 * fit.max_abs_residual);
    residuals.title = title;
    residuals.x_label = "A/D value A";
    residuals.y_label = "residual (mm)";
    const double extent = std::max(1.2 * 1e3 * fit.max_abs_residual, 0.1);
    residuals.y_min = -extent;
    residuals.y_max = extent;
    residuals.lines.push_back({{first, last}, {0.0, 0.0}, plot::colors::kWall, 1.0, false, ""});
    residuals.lines.push_back(markers(adc, residual_mm, 0.006 * span_of(curve_adc), 0.025 * extent,
                                      plot::colors::kFront, "residual"));
    figure.write(base.string());
}

void print_ir_fit(const std::string& source, const std::vector<lessons::IrCalibrationPoint>& points,
                  const lessons::IrFit& fit) {
    const SharpIrCurve& c = fit.curve;
    std::printf("IR curve fitted to %zu measurements from %s (%s after %d iterations)\n",
                points.size(), source.c_str(), fit.converged ? "converged" : "NOT converged",
                fit.iterations);
    std::printf("  D = a*(C_M/(A + C_R) - b) with a = %g m\n", c.a);
    std::printf("  C_M = %.6g   C_R = %.6g   b = %.6g\n", c.c_m, c.c_r, c.b);
    std::printf("  residuals: RMS %.2f mm, largest %.2f mm\n", 1e3 * fit.rms_residual,
                1e3 * fit.max_abs_residual);
    std::printf("  %5s %8s %14s %12s %14s\n", "point", "A", "measured (m)", "fitted (m)",
                "residual (mm)");
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::printf("  %5zu %8g %14.4f %12.4f %14.2f\n", i + 1, points[i].adc, points[i].distance,
                    points[i].distance - fit.residuals[i], 1e3 * fit.residuals[i]);
    }
}

// A fit that did not converge, or a curve the loop would refuse, is reported: false.
bool usable_fit(const lessons::IrFit& fit, const std::string& name) {
    if (!fit.converged) {
        std::cerr << "error: the fit of " << name << " did not converge; the profile was not "
                  << "changed. Check the measurements (metres, the whole 4-30 cm range)\n";
        return false;
    }
    const auto issues = validate(fit.curve, name);
    for (const ConfigIssue& issue : issues) {
        std::cerr << "error: fitted " << issue.message() << '\n';
    }
    if (!issues.empty()) {
        std::cerr << "The fitted curve is not usable; the profile was not changed.\n";
    }
    return issues.empty();
}

int calibrate_ir(const CalibrateOptions& options) {
    std::vector<lessons::IrCalibrationPoint> points;
    RobotProfile profile;
    // The one curve of both sensors (the paper's) from every point, and each sensor's own
    // from its points when the file says which sensor took them.
    lessons::IrCalibration calibration;
    try {
        points = lessons::read_ir_points_csv(options.points_file);
        profile = starting_profile(options.profile);
        calibration = lessons::fit_ir_calibration(points, profile.ir_curve, options.points_file);
    } catch (const InputError& error) {
        report(error);
        return kExitBadInput;
    }
    print_ir_fit(options.points_file, points, calibration.both);
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        if (const auto& own = calibration.own[static_cast<std::size_t>(sensor)]) {
            print_ir_fit(lessons::sensor_points_source(options.points_file, sensor),
                         lessons::points_of(points, sensor), *own);
        }
    }

    if (!options.plot_directory.empty()) {
        try {
            fs::create_directories(options.plot_directory);
            const fs::path base = fs::path(options.plot_directory) / "ir_calibration";
            write_ir_plot(points, calibration.both, profile.ir_curve, base);
            std::printf("Plot written: %s.png and .svg\n", base.string().c_str());
        } catch (const std::exception& error) {
            std::cerr << "error: " << error.what() << '\n';
            return kExitOutputFailed;
        }
    }
    bool usable = usable_fit(calibration.both, "ir_curve");
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        if (const auto& own = calibration.own[static_cast<std::size_t>(sensor)]) {
            usable = usable_fit(*own, ir_sensor_curve_name(sensor)) && usable;
        }
    }
    if (!usable) {
        return kExitBadInput;
    }
    // A file without the sensor column fits one curve for both: it replaces any own one.
    lessons::apply_ir_calibration(profile, calibration);
    return write_profile(options.profile, profile);
}

void print_umbmark(const lessons::UmbmarkInput& in, const lessons::UmbmarkResult& r) {
    const auto degrees = [](double radians) { return radians_to_degrees(radians) + 0.0; };  // no -0
    std::printf("UMBmark on a %.3f m square: %zu clockwise and %zu counter-clockwise run%s\n",
                in.side, in.clockwise.size(), in.counter_clockwise.size(),
                in.counter_clockwise.size() == 1 ? "" : "s");
    std::printf("  centres of gravity: cw (%.4f, %.4f) m, ccw (%.4f, %.4f) m\n", r.centre_cw.x(),
                r.centre_cw.y(), r.centre_ccw.x(), r.centre_ccw.y());
    std::printf("  E_max,syst = %.4f m (r_cw %.4f m, r_ccw %.4f m)\n", r.e_max_syst, r.r_cw,
                r.r_ccw);
    std::printf("  alpha = %.3f deg (from x %.3f, from y %.3f)\n", degrees(r.alpha),
                degrees(r.alpha_from_x), degrees(r.alpha_from_y));
    std::printf("  beta  = %.3f deg (from x %.3f, from y %.3f)\n", degrees(r.beta),
                degrees(r.beta_from_x), degrees(r.beta_from_y));
    std::printf("  E_d = D_R/D_L = %.6f   E_b = b_actual/b = %.6f\n", r.e_d, r.e_b);
    std::printf("  wheel base:  %.6f m (was %.6f m)\n", r.wheel_base, in.wheel_base);
    std::printf("  right wheel: %.4f mm, Codo %.2f counts/m (was %.4f mm)\n",
                1e3 * r.right_wheel_diameter, r.codo_right, 1e3 * in.right_wheel_diameter);
    std::printf("  left wheel:  %.4f mm, Codo %.2f counts/m (was %.4f mm)\n",
                1e3 * r.left_wheel_diameter, r.codo_left, 1e3 * in.left_wheel_diameter);
    const auto differ = [](double a, double b) {
        return std::abs(a - b) > 0.25 * std::max(std::abs(a), std::abs(b)) + 1e-3;
    };
    if (differ(r.alpha_from_x, r.alpha_from_y) || differ(r.beta_from_x, r.beta_from_y)) {
        std::printf(
            "  note: the x and y estimates disagree (large errors or scattered runs): "
            "repeat UMBmark with the corrected profile\n");
    }
}

int calibrate_odometry(const CalibrateOptions& options) {
    lessons::UmbmarkInput input;
    lessons::UmbmarkResult result;
    RobotProfile profile;
    try {
        profile = starting_profile(options.profile);
        input.side = options.side;
        input.clockwise = lessons::parse_return_errors(options.clockwise, "--cw");
        input.counter_clockwise = lessons::parse_return_errors(options.counter_clockwise, "--ccw");
        // What the odometry used during the runs: its wheel base and the diameters its Codo
        // stand for (the same as the profile's diameters unless Codo is overridden).
        input.wheel_base = profile.wheel_base;
        input.counts_per_turn = lessons::kNxtCountsPerTurn;
        const lessons::WheelDiameters used = lessons::odometry_wheel_diameters(profile);
        input.right_wheel_diameter = used.right;
        input.left_wheel_diameter = used.left;
        result = lessons::umbmark(input);
    } catch (const InputError& error) {
        report(error);
        return kExitBadInput;
    }
    print_umbmark(input, result);
    profile.right_wheel_diameter = result.right_wheel_diameter;
    profile.left_wheel_diameter = result.left_wheel_diameter;
    profile.wheel_base = result.wheel_base;
    lessons::derive_codo(profile);
    return write_profile(options.profile, profile);
}

}  // namespace

bool CalibrateOptions::requested() const {
    return (ir_command != nullptr && ir_command->parsed())
           || (odometry_command != nullptr && odometry_command->parsed());
}

void add_calibrate_subcommands(CLI::App& app, CalibrateOptions& options) {
    CLI::App* ir = app.add_subcommand(
        "calibrate-ir", "Fit the IR sensor's curve (eq. 2) to measured A/D values and distances");
    ir->add_option("--points", options.points_file, "CSV file with the header adc,distance_m")
        ->required();
    ir->add_option("--profile", options.profile,
                   "Robot profile (TOML) to update with C_M, C_R and b; created if missing");
    ir->add_option("--plot", options.plot_directory,
                   "Directory for ir_calibration.png and .svg (the fit and its residuals)");
    options.ir_command = ir;

    CLI::App* odometry = app.add_subcommand(
        "calibrate-odometry",
        "UMBmark: wheel diameters and wheel base from the return errors of square runs");
    odometry->add_option("--side", options.side, "Side L of the square driven, m")
        ->required()
        ->check(CLI::PositiveNumber);
    odometry
        ->add_option("--cw", options.clockwise,
                     "Return errors of the clockwise runs, \"x,y;x,y;...\" in metres (end − start, "
                     "x along the first leg, y to its left)")
        ->required();
    odometry
        ->add_option("--ccw", options.counter_clockwise,
                     "Return errors of the counter-clockwise runs, \"x,y;x,y;...\" in metres")
        ->required();
    odometry->add_option("--profile", options.profile,
                         "Robot profile (TOML) whose odometry was used and that is updated; "
                         "created if missing");
    options.odometry_command = odometry;
}

int calibrate_command(const CalibrateOptions& options) {
    if (options.ir_command != nullptr && options.ir_command->parsed()) {
        return calibrate_ir(options);
    }
    return calibrate_odometry(options);
}

}  // namespace legofeup::cli
