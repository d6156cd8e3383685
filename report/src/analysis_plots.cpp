#include "legofeup/report/analysis_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "legofeup/core/angles.hpp"
#include "legofeup/report/figure.hpp"

namespace legofeup::report {
namespace {

using lessons::analysis::MonteCarloSummary;
using lessons::analysis::StepStatistics;
using lessons::analysis::SweepCell;
using plot::Band;
using plot::Figure;
using plot::Line;
namespace colors = plot::colors;

constexpr int kWidth = 1200;
constexpr plot::Color kBound{0.35, 0.35, 0.35};

template <class Pick>
std::vector<double> column(const std::vector<StepStatistics>& steps, Pick pick) {
    std::vector<double> values;
    values.reserve(steps.size());
    for (const StepStatistics& step : steps) {
        values.push_back(pick(step));
    }
    return values;
}

std::string runs_text(const MonteCarloSummary& summary) {
    return std::to_string(summary.runs.size()) + (summary.runs.size() == 1 ? " run" : " runs");
}

// An averaged statistic against its 95 % band and its expected value, on a log axis (an
// inconsistent filter is off by orders of magnitude).
Figure consistency_figure(const MonteCarloSummary& summary, const std::string& title, bool nis) {
    const std::vector<double> time = column(summary.steps, [](auto& s) { return s.time; });
    Figure figure(title + (nis ? " — averaged NIS" : " — averaged NEES"), 1, kWidth, 560);
    plot::Panel& p = figure.panel(0);
    const double dof = nis ? 2.0 : 3.0;
    p.title = nis ? "NIS of the applied wall updates averaged over the runs (χ²(2M)/M band)"
                  : "NEES averaged over " + runs_text(summary) + " (χ²(3N)/N band)";
    p.x_label = "time (s)";
    p.y_label = nis ? "averaged NIS" : "averaged NEES";
    p.log_y = true;
    Band band{time,
              column(summary.steps,
                     [nis](auto& s) { return nis ? s.nis_bounds.lower : s.nees_bounds.lower; }),
              column(summary.steps,
                     [nis](auto& s) { return nis ? s.nis_bounds.upper : s.nees_bounds.upper; }),
              colors::kBand, "95 % bounds"};
    p.bands.push_back(std::move(band));
    p.lines.push_back(
        {time, column(summary.steps, [nis](auto& s) { return nis ? s.mean_nis : s.mean_nees; }),
         colors::kEstimate, 1.2, false, nis ? "averaged NIS" : "averaged NEES"});
    p.lines.push_back({{time.empty() ? 0.0 : time.front(), time.empty() ? 1.0 : time.back()},
                       {dof, dof},
                       kBound,
                       1.2,
                       true,
                       nis ? "expected (2)" : "expected (3)"});
    return figure;
}

Figure error_figure(const MonteCarloSummary& summary, const std::string& title) {
    const std::vector<double> time = column(summary.steps, [](auto& s) { return s.time; });
    Figure figure(title + " — RMS errors across " + runs_text(summary), 2, kWidth, 800);
    plot::Panel& position = figure.panel(0);
    position.title = "Position error, RMS over the runs at each step";
    position.x_label = "time (s)";
    position.y_label = "RMS position error (m)";
    position.y_min = 0.0;
    position.lines.push_back({time,
                              column(summary.steps, [](auto& s) { return s.rms_position_error; }),
                              colors::kEstimate, 1.5, false, ""});
    plot::Panel& heading = figure.panel(1);
    heading.title = "Heading error, RMS over the runs at each step";
    heading.x_label = "time (s)";
    heading.y_label = "RMS heading error (deg)";
    heading.y_min = 0.0;
    heading.lines.push_back(
        {time,
         column(summary.steps, [](auto& s) { return radians_to_degrees(s.rms_heading_error); }),
         colors::kOdometry, 1.5, false, ""});
    return figure;
}

// Final position errors in about √N bins, drawn as a filled staircase.
Figure histogram_figure(const MonteCarloSummary& summary, const std::string& title) {
    std::vector<double> errors;
    for (const auto& run : summary.runs) {
        if (std::isfinite(run.final_position_error)) {
            errors.push_back(run.final_position_error);
        }
    }
    Figure figure(title + " — final position errors", 1, kWidth, 520);
    plot::Panel& p = figure.panel(0);
    p.title = "Final position error of each of the " + runs_text(summary);
    p.x_label = "final position error (m)";
    p.y_label = "runs";
    p.y_min = 0.0;
    if (errors.empty()) {
        return figure;
    }
    const auto [low_it, high_it] = std::minmax_element(errors.begin(), errors.end());
    const double low = *low_it;
    const double high = *high_it > low ? *high_it : low + 1e-3;
    const auto bins = static_cast<std::size_t>(
        std::clamp(std::ceil(std::sqrt(static_cast<double>(errors.size()))), 1.0, 50.0));
    const double width = (high - low) / static_cast<double>(bins);
    std::vector<double> counts(bins, 0.0);
    for (const double e : errors) {
        counts[std::min(static_cast<std::size_t>((e - low) / width), bins - 1)] += 1.0;
    }
    Band bars{{}, {}, {}, colors::kBand, ""};
    Line outline{{}, {}, colors::kEstimate, 1.5, false, ""};
    for (std::size_t b = 0; b < bins; ++b) {
        for (const double x :
             {low + width * static_cast<double>(b), low + width * static_cast<double>(b + 1)}) {
            bars.x.push_back(x);
            bars.lower.push_back(0.0);
            bars.upper.push_back(counts[b]);
            outline.x.push_back(x);
            outline.y.push_back(counts[b]);
        }
    }
    p.y_max = *std::max_element(counts.begin(), counts.end()) * 1.1;
    p.bands.push_back(std::move(bars));
    p.lines.push_back(std::move(outline));
    return figure;
}

std::string factor_label(double factor) {
    char text[32];
    std::snprintf(text, sizeof text, "×%g", factor);
    return text;
}

// A cell's value with `digits` significant digits, "–" for none.
std::string value_text(double value, int digits) {
    if (!std::isfinite(value)) {
        return "–";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

Figure heat_map_figure(const std::vector<SweepCell>& cells, const std::vector<double>& q_scales,
                       const std::vector<double>& r_scales, const std::string& title,
                       bool consistency) {
    Figure figure(title + (consistency ? " — NEES consistency" : " — RMS position error"), 1,
                  kWidth, 140 + 70 * static_cast<int>(std::max<std::size_t>(q_scales.size(), 4)));
    plot::Panel& p = figure.panel(0);
    p.title = consistency
                  ? "Mean NEES (in brackets: steps with the averaged NEES inside its bounds)"
                  : "RMS position error, mean over the runs (m)";
    p.x_label = "R scale (r11 and r22 multiplied by)";
    p.y_label = "Q scale (q11, q22 ×)";
    plot::HeatMap map;
    for (const double r : r_scales) {
        map.column_labels.push_back(factor_label(r));
    }
    for (const double q : q_scales) {
        map.row_labels.push_back(factor_label(q));
    }
    const std::size_t count = q_scales.size() * r_scales.size();
    map.values.assign(count, std::numeric_limits<double>::quiet_NaN());
    map.cell_text.assign(count, "");
    for (const SweepCell& cell : cells) {
        if (cell.index >= count) {
            continue;
        }
        map.values[cell.index] = consistency ? cell.consistency : cell.rms_position_error;
        map.cell_text[cell.index] =
            consistency ? value_text(cell.mean_nees, 3) + " ("
                              + value_text(std::round(100.0 * cell.nees_inside_fraction), 3) + "%)"
                        : value_text(cell.rms_position_error, 3);
    }
    if (consistency) {
        map.diverging = true;
        map.colour_label = "log₁₀(mean NEES / 3)";
    } else {
        map.log_scale = true;
        map.colour_label = "RMS position error (m)";
    }
    p.heat_map = std::move(map);
    return figure;
}

}  // namespace

std::vector<std::string> write_monte_carlo_plots(const MonteCarloSummary& summary,
                                                 const std::filesystem::path& directory,
                                                 const std::string& title) {
    consistency_figure(summary, title, false).write((directory / "nees").string());
    consistency_figure(summary, title, true).write((directory / "nis").string());
    error_figure(summary, title).write((directory / "rms_errors").string());
    histogram_figure(summary, title).write((directory / "final_errors").string());
    return {"nees", "nis", "rms_errors", "final_errors"};
}

std::vector<std::string> write_sweep_plots(const std::vector<SweepCell>& cells,
                                           const std::vector<double>& q_scales,
                                           const std::vector<double>& r_scales,
                                           const std::filesystem::path& directory,
                                           const std::string& title) {
    heat_map_figure(cells, q_scales, r_scales, title, false)
        .write((directory / "sweep_rms_error").string());
    heat_map_figure(cells, q_scales, r_scales, title, true)
        .write((directory / "sweep_nees_consistency").string());
    return {"sweep_rms_error", "sweep_nees_consistency"};
}

}  // namespace legofeup::report
