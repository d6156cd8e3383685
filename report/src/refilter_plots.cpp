#include "legofeup/report/refilter_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "legofeup/core/pose_error.hpp"

namespace legofeup::report {
namespace {

using lessons::RefilterStep;
using plot::Figure;
namespace colors = plot::colors;

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
// The recorded estimate in orange, the new one in the usual estimate blue.
constexpr plot::Color kRecorded{0.90, 0.45, 0.05};
constexpr plot::Color kRecordedBand{0.90, 0.45, 0.05, 0.18};
constexpr plot::Color kNew = colors::kEstimate;
constexpr plot::Color kNewBand = colors::kBand;

template <class Pick>
std::vector<double> column(const std::vector<RefilterStep>& steps, Pick pick) {
    std::vector<double> values;
    values.reserve(steps.size());
    for (const RefilterStep& step : steps) {
        values.push_back(pick(step));
    }
    return values;
}

bool any_truth(const lessons::RefilterResult& result) {
    return std::any_of(result.steps.begin(), result.steps.end(),
                       [](const RefilterStep& step) { return step.truth.has_value(); });
}

Figure trajectory(const lessons::RefilterResult& result, const sim::WorldSpec& world,
                  const std::string& title, int width) {
    Figure figure(title + " — re-filtered trajectory", 1, width,
                  static_cast<int>(std::lround(width * (1100.0 / 1200.0))));
    plot::Panel& p = figure.panel(0);
    p.title = "True path, recorded estimate and new estimate (same raw readings)";
    p.x_label = "x (m)";
    p.y_label = "y (m)";
    p.equal_aspect = true;
    for (const Wall& wall : world.walls) {
        p.segments.push_back({wall.start.x(), wall.start.y(), wall.end.x(), wall.end.y()});
    }
    const auto& s = result.steps;
    if (any_truth(result)) {
        p.lines.push_back({column(s, [](auto& k) { return k.truth ? k.truth->x : kNone; }),
                           column(s, [](auto& k) { return k.truth ? k.truth->y : kNone; }),
                           colors::kTruth, 2.0, false, "true"});
    }
    p.lines.push_back({column(s, [](auto& k) { return k.old_estimate(kX); }),
                       column(s, [](auto& k) { return k.old_estimate(kY); }), kRecorded, 1.5, true,
                       "recorded estimate"});
    p.lines.push_back({column(s, [](auto& k) { return k.new_estimate(kX); }),
                       column(s, [](auto& k) { return k.new_estimate(kY); }), kNew, 1.5, false,
                       "new estimate"});
    return figure;
}

// One estimate's error in component `index` (x̃ = x̂ − x, θ wrapped: pose_error.hpp) and its
// ±σ band.
struct ErrorSeries {
    std::vector<double> error;
    std::vector<double> minus_sigma;
    std::vector<double> plus_sigma;
};

ErrorSeries error_series(const std::vector<RefilterStep>& steps, int index, bool recorded) {
    ErrorSeries series;
    for (const RefilterStep& step : steps) {
        const StateVector& estimate = recorded ? step.old_estimate : step.new_estimate;
        const StateCovariance& covariance = recorded ? step.old_covariance : step.new_covariance;
        double error = kNone;
        if (step.truth) {
            error = pose_error(estimate, *step.truth).vector()(index);
        }
        const double sigma = std::sqrt(std::max(0.0, covariance(index, index)));
        series.error.push_back(error);
        series.minus_sigma.push_back(-sigma);
        series.plus_sigma.push_back(sigma);
    }
    return series;
}

Figure errors(const lessons::RefilterResult& result, const std::string& title, int width) {
    Figure figure(title + " — re-filtered errors", 3, width,
                  static_cast<int>(std::lround(width * (1000.0 / 1200.0))));
    const auto& s = result.steps;
    const auto t = column(s, [](auto& k) { return k.time; });
    // Panel i shows state component i (kX, kY, kTheta).
    constexpr const char* kNames[] = {"x", "y", "θ"};
    constexpr const char* kUnits[] = {"m", "m", "rad"};
    for (const int index : {kX, kY, kTheta}) {
        const std::string name = kNames[index];
        plot::Panel& p = figure.panel(index);
        p.title = "Error in " + name + " (estimate − truth), recorded and new, ±σ";
        p.x_label = "t (s)";
        p.y_label = name + " error (" + kUnits[index] + ")";
        const ErrorSeries old_series = error_series(s, index, true);
        const ErrorSeries new_series = error_series(s, index, false);
        p.bands.push_back(
            {t, old_series.minus_sigma, old_series.plus_sigma, kRecordedBand, "±σ recorded"});
        p.bands.push_back({t, new_series.minus_sigma, new_series.plus_sigma, kNewBand, "±σ new"});
        p.lines.push_back({t, old_series.error, kRecorded, 1.2, false, "recorded"});
        p.lines.push_back({t, new_series.error, kNew, 1.2, false, "new"});
    }
    return figure;
}

}  // namespace

std::vector<RunFigure> refilter_figures(const lessons::RefilterResult& result,
                                        const sim::WorldSpec& world, const std::string& title,
                                        int width) {
    std::vector<RunFigure> figures;
    figures.push_back({"refilter_trajectory", trajectory(result, world, title, width)});
    if (any_truth(result)) {
        figures.push_back({"refilter_errors", errors(result, title, width)});
    }
    return figures;
}

std::vector<std::string> write_refilter_plots(const lessons::RefilterResult& result,
                                              const sim::WorldSpec& world,
                                              const std::filesystem::path& directory,
                                              const std::string& title) {
    return write_figures(refilter_figures(result, world, title), directory);
}

}  // namespace legofeup::report
