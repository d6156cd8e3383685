// The GUI's error plots and the report's error figure say the same thing about the same run:
// x̃ = x̂ − x, the heading wrapped. A run whose filter believes it starts 20 cm +x, 10 cm −y
// and turned counter-clockwise of where the robot is (odometry only, so nothing corrects it)
// must show positive x and θ errors and a negative y error in both, step for step — and a
// start across ±π a small heading error, not one of nearly 360°.
#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/report/run_plots.hpp"
#include "legofeup/ui/plots/plot_series.hpp"
#include "legofeup/ui/session/run_samples.hpp"

namespace legofeup::ui {
namespace {

/// The simulator's truth passes through Box2D's floats: good to about 1e-7 m and rad.
constexpr double kTruthPrecision = 1e-6;

struct BothViews {
    std::vector<RunSample> gui;                 ///< what the plots panel draws from
    std::array<std::vector<double>, 3> report;  ///< the errors figure's line, per component
};

/// Experiment a (odometry only) for two seconds, the belief and the truth starting apart.
BothViews run_apart(const Pose2& truth, const Pose2& belief) {
    lessons::RunConfig config = lessons::find_experiment("a")->config;
    config.duration = 2.0;
    config.true_start = {truth.x, truth.y, truth.theta};
    config.initial_pose = {belief.x, belief.y, belief.theta};
    const lessons::ResolvedRun run = lessons::resolve(config);
    // The same seed twice gives the same run bit for bit (lockstep).
    SampleCollector samples;
    lessons::run_lockstep(run, &samples);
    report::RunRecording recording;
    lessons::run_lockstep(run, &recording);

    BothViews views;
    views.gui = samples.take();
    for (report::RunFigure& figure : report::run_figures(recording, run.world, "sign")) {
        if (figure.name != "errors") {
            continue;
        }
        for (int row = 0; row < 3; ++row) {
            for (const plot::Line& line : figure.figure.panel(row).lines) {
                if (line.label == "error") {
                    views.report[static_cast<std::size_t>(row)] = line.y;
                }
            }
        }
    }
    return views;
}

double gui_value(Series series, const RunSample& sample) {
    return series_definition(series).value(make_step_record(sample)).value();
}

/// Every step: the GUI's x, y (m) and θ (°) errors equal the report's x, y (m) and θ (rad).
void expect_same_errors(const BothViews& views) {
    ASSERT_GT(views.gui.size(), 20U);
    for (const auto& component : views.report) {
        ASSERT_EQ(component.size(), views.gui.size());
    }
    for (std::size_t k = 0; k < views.gui.size(); ++k) {
        const RunSample& s = views.gui[k];
        EXPECT_NEAR(gui_value(Series::ErrorX, s), views.report[kX][k], 1e-12) << k;
        EXPECT_NEAR(gui_value(Series::ErrorY, s), views.report[kY][k], 1e-12) << k;
        EXPECT_NEAR(gui_value(Series::ErrorTheta, s), radians_to_degrees(views.report[kTheta][k]),
                    1e-9)
            << k;
    }
}

TEST(ErrorSign, GuiAndReportShowEstimateMinusTruth) {
    const Pose2 truth{-1.0, -1.0, 0.0};
    const Pose2 belief{-0.8, -1.1, degrees_to_radians(5.0)};
    const BothViews views = run_apart(truth, belief);
    expect_same_errors(views);
    // The first step, before the robot has moved: x̃ = (+0.2, −0.1, +5°), to the simulator's
    // single-precision truth (Box2D).
    const RunSample& first = views.gui.front();
    EXPECT_NEAR(gui_value(Series::ErrorX, first), 0.2, kTruthPrecision);
    EXPECT_NEAR(gui_value(Series::ErrorY, first), -0.1, kTruthPrecision);
    EXPECT_NEAR(gui_value(Series::ErrorTheta, first), 5.0, radians_to_degrees(kTruthPrecision));
    EXPECT_NEAR(views.report[kX].front(), 0.2, kTruthPrecision);
    EXPECT_NEAR(views.report[kY].front(), -0.1, kTruthPrecision);
}

TEST(ErrorSign, AHeadingErrorAcrossPlusMinusPiIsSmallInBoth) {
    // The robot faces −π + 0.01 rad, the filter believes π − 0.01: 0.02 rad clockwise.
    const Pose2 truth{-1.0, -1.0, -kPi + 0.01};
    const Pose2 belief{-1.0, -1.0, kPi - 0.01};
    const BothViews views = run_apart(truth, belief);
    expect_same_errors(views);
    EXPECT_NEAR(views.report[kTheta].front(), -0.02, kTruthPrecision);
    EXPECT_NEAR(gui_value(Series::ErrorTheta, views.gui.front()), radians_to_degrees(-0.02),
                radians_to_degrees(kTruthPrecision));
}

}  // namespace
}  // namespace legofeup::ui
