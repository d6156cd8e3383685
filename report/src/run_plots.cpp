#include "legofeup/report/run_plots.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <optional>

#include "legofeup/core/pose_error.hpp"
#include "legofeup/report/figure.hpp"

namespace legofeup::report {
namespace {

using plot::Band;
using plot::Figure;
using plot::Line;
namespace colors = plot::colors;

constexpr double kEllipseInterval = 5.0;  // s between the ellipses drawn on the trajectory
constexpr double kNoDistance = std::numeric_limits<double>::quiet_NaN();

template <class Pick>
std::vector<double> column(const std::vector<RunRecording::Step>& steps, Pick pick) {
    std::vector<double> values;
    values.reserve(steps.size());
    for (const RunRecording::Step& step : steps) {
        values.push_back(pick(step));
    }
    return values;
}

// The 1σ ellipse of the position block of P: semi-axes √λ along the eigenvectors.
plot::Ellipse sigma_ellipse(const RunRecording::Step& step) {
    const Eigen::Matrix2d block = step.covariance.topLeftCorner<2, 2>();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(block);
    const Eigen::Vector2d axes = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    const Eigen::Vector2d major = eigen.eigenvectors().col(1);
    plot::Ellipse e;
    e.cx = step.estimate(kX);
    e.cy = step.estimate(kY);
    e.semi_major = axes(1);
    e.semi_minor = axes(0);
    e.angle = std::atan2(major.y(), major.x());
    return e;
}

// A height in proportion to the width, as designed for a 1200-pixel-wide figure.
int height_for(int width, int height_at_1200) {
    return static_cast<int>(std::lround(width * (height_at_1200 / 1200.0)));
}

Figure trajectory(const RunRecording& rec, const sim::WorldSpec& world, const std::string& title,
                  int width) {
    Figure figure(title + " — trajectory", 1, width, height_for(width, 1100));
    plot::Panel& p = figure.panel(0);
    p.title = "True, estimated (with 1σ ellipses every 5 s) and odometry-only paths";
    p.x_label = "x (m)";
    p.y_label = "y (m)";
    p.equal_aspect = true;
    for (const Wall& wall : world.walls) {
        p.segments.push_back({wall.start.x(), wall.start.y(), wall.end.x(), wall.end.y()});
    }
    const auto& s = rec.steps();
    p.lines.push_back({column(s, [](auto& k) { return k.odometry.x; }),
                       column(s, [](auto& k) { return k.odometry.y; }), colors::kOdometry, 1.5,
                       true, "odometry only"});
    p.lines.push_back({column(s, [](auto& k) { return k.truth.x; }),
                       column(s, [](auto& k) { return k.truth.y; }), colors::kTruth, 2.0, false,
                       "true"});
    p.lines.push_back({column(s, [](auto& k) { return k.estimate(kX); }),
                       column(s, [](auto& k) { return k.estimate(kY); }), colors::kEstimate, 1.5,
                       false, "estimate (EKF)"});
    double next = 0.0;
    for (const RunRecording::Step& step : s) {
        if (step.time >= next) {
            p.ellipses.push_back(sigma_ellipse(step));
            next += kEllipseInterval;
        }
    }
    return figure;
}

Figure errors(const RunRecording& rec, const std::string& title, int width) {
    Figure figure(title + " — estimation error", 3, width, height_for(width, 1000));
    const auto& s = rec.steps();
    const auto t = column(s, [](auto& k) { return k.time; });
    struct Component {
        const char* name;
        const char* unit;
        int index;
    };
    const Component components[] = {{"x", "m", kX}, {"y", "m", kY}, {"θ", "rad", kTheta}};
    for (int row = 0; row < 3; ++row) {
        const Component c = components[row];
        plot::Panel& p = figure.panel(row);
        p.title = std::string("Error in ") + c.name + " (estimate − truth) with ±σ";
        p.x_label = "t (s)";
        p.y_label = std::string(c.name) + " error (" + c.unit + ")";
        const auto sigma = column(
            s, [&](auto& k) { return std::sqrt(std::max(0.0, k.covariance(c.index, c.index))); });
        std::vector<double> lower(sigma.size());
        for (std::size_t i = 0; i < sigma.size(); ++i) {
            lower[i] = -sigma[i];
        }
        p.bands.push_back({t, lower, sigma, colors::kBand, "±σ"});
        p.lines.push_back({t,
                           column(s,
                                  [&](auto& k) {
                                      // x̃ = x̂ − x, the heading wrapped (pose_error.hpp)
                                      return pose_error(k.estimate, k.truth).vector()(c.index);
                                  }),
                           colors::kEstimate, 1.5, false, "error"});
    }
    return figure;
}

Figure covariance(const RunRecording& rec, const std::string& title, int width) {
    Figure figure(title + " — covariance", 3, width, height_for(width, 1000));
    const auto& s = rec.steps();
    const auto t = column(s, [](auto& k) { return k.time; });
    const char* names[] = {"Px (m²)", "Py (m²)", "Pθ (rad²)"};
    for (int row = 0; row < 3; ++row) {
        plot::Panel& p = figure.panel(row);
        p.title = std::string("Variance ") + names[row];
        p.x_label = "t (s)";
        p.y_label = names[row];
        p.log_y = true;
        p.lines.push_back({t, column(s, [&](auto& k) { return k.covariance(row, row); }),
                           colors::kEstimate, 1.5, false, ""});
    }
    return figure;
}

// One panel of two time series (the IR distances, the wheel speeds).
struct TimeSeries {
    double (*pick)(const RunRecording::Step&);
    plot::Color color;
    const char* label;
};

Figure two_series(const RunRecording& rec, const std::string& title, int width,
                  const std::string& panel_title, const std::string& y_label,
                  const TimeSeries& first, const TimeSeries& second,
                  std::optional<double> y_max = std::nullopt) {
    Figure figure(title, 1, width, height_for(width, 520));
    plot::Panel& p = figure.panel(0);
    p.title = panel_title;
    p.x_label = "t (s)";
    p.y_label = y_label;
    if (y_max) {
        p.y_min = 0.0;
        p.y_max = y_max;
    }
    const auto& s = rec.steps();
    const auto t = column(s, [](auto& k) { return k.time; });
    for (const TimeSeries& series : {first, second}) {
        p.lines.push_back({t, column(s, series.pick), series.color, 1.2, false, series.label});
    }
    return figure;
}

}  // namespace

void RunRecording::on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    Step step;
    step.time = snapshot.time;
    step.truth = truth.pose;
    step.estimate = snapshot.estimate;
    step.covariance = snapshot.covariance;
    step.odometry = snapshot.odometry_pose;
    for (std::size_t i = 0; i < 2; ++i) {
        const IrDistance& reading = snapshot.ir[i].reading;
        step.ir_distance[i] = reading.in_range() ? reading.distance : kNoDistance;
    }
    step.wheels = snapshot.wheels;
    steps_.push_back(step);
}

RunRecording RunRecording::thinned(std::size_t max_steps) const {
    RunRecording kept;
    if (steps_.empty() || max_steps == 0) {
        return kept;
    }
    const std::size_t stride = (steps_.size() + max_steps - 1) / max_steps;  // ⌈n / max⌉
    for (std::size_t i = 0; i < steps_.size(); i += stride) {
        kept.steps_.push_back(steps_[i]);
    }
    if ((steps_.size() - 1) % stride != 0 && kept.steps_.size() < max_steps) {
        kept.steps_.push_back(steps_.back());
    } else if ((steps_.size() - 1) % stride != 0) {
        kept.steps_.back() = steps_.back();
    }
    return kept;
}

std::vector<RunFigure> run_figures(const RunRecording& recording, const sim::WorldSpec& world,
                                   const std::string& title, int width) {
    std::vector<RunFigure> figures;
    figures.push_back({"trajectory", trajectory(recording, world, title, width)});
    figures.push_back({"errors", errors(recording, title, width)});
    figures.push_back({"covariance", covariance(recording, title, width)});
    figures.push_back(
        {"ir_distances",
         two_series(recording, title + " — IR distances", width,
                    "IR distances ds1 (front) and ds2 (rear), in range only", "distance (m)",
                    {[](const RunRecording::Step& k) { return k.ir_distance[0]; }, colors::kFront,
                     "ds1 (front)"},
                    {[](const RunRecording::Step& k) { return k.ir_distance[1]; }, colors::kRear,
                     "ds2 (rear)"},
                    0.32)});
    figures.push_back({"wheel_speeds",
                       two_series(recording, title + " — wheel speeds", width,
                                  "Commanded wheel speeds V1 (right) and V2 (left)", "speed (m/s)",
                                  {[](const RunRecording::Step& k) { return k.wheels.right; },
                                   colors::kFront, "V1 (right)"},
                                  {[](const RunRecording::Step& k) { return k.wheels.left; },
                                   colors::kRear, "V2 (left)"})});
    return figures;
}

std::vector<std::string> write_run_plots(const RunRecording& recording, const sim::WorldSpec& world,
                                         const std::filesystem::path& directory,
                                         const std::string& title) {
    return write_figures(run_figures(recording, world, title), directory);
}

std::vector<std::string> write_figures(const std::vector<RunFigure>& figures,
                                       const std::filesystem::path& directory) {
    std::vector<std::string> names;
    for (const RunFigure& figure : figures) {
        figure.figure.write((directory / figure.name).string());
        names.push_back(figure.name);
    }
    return names;
}

}  // namespace legofeup::report
