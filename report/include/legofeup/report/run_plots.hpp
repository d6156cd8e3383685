#pragma once
// The plots of one run: the trajectory with 1σ ellipses, the errors with ±σ bands, Px, Py,
// Pθ, the IR distances and the wheel speeds: as figures (for the student report) or written
// as PNG and SVG files (legofeup-cli run).

#include <filesystem>
#include <string>
#include <vector>

#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/report/figure.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::report {

/// Keeps what the plots need from every step.
class RunRecording final : public lessons::RunObserver {
  public:
    struct Step {
        double time;
        Pose2 truth;
        StateVector estimate;
        StateCovariance covariance;
        Pose2 odometry;
        std::array<double, 2> ir_distance;  // NaN when not in range
        WheelSpeeds wheels;
    };

    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override;
    const std::vector<Step>& steps() const { return steps_; }

    /// Every k-th step, and always the last, so that at most `max_steps` remain: for
    /// documents, where all of a two-lap run's 3400 steps would make each plot heavy (MB of
    /// SVG) without showing more at page size.
    RunRecording thinned(std::size_t max_steps) const;

  private:
    std::vector<Step> steps_;
};

/// Steps a report's plots keep per run (a two-lap run, 3400 steps, keeps every 9th:
/// 0.45 s apart, finer than a printed line shows).
inline constexpr std::size_t kReportPlotSteps = 400;

struct RunFigure {
    std::string name;  ///< file base name: "trajectory", "errors", …
    plot::Figure figure;
};

/// The run's figures — trajectory, errors, covariance, ir_distances, wheel_speeds — `width`
/// pixels wide, each as tall as its layout needs in proportion.
std::vector<RunFigure> run_figures(const RunRecording& recording, const sim::WorldSpec& world,
                                   const std::string& title, int width = 1200);

/// Writes each figure as `<directory>/<name>.png` and `.svg`, returning the names written.
/// Throws std::runtime_error naming the file that failed.
std::vector<std::string> write_figures(const std::vector<RunFigure>& figures,
                                       const std::filesystem::path& directory);

/// Writes trajectory, errors, covariance, ir_distances and wheel_speeds (.png and .svg) into
/// `directory`, returning the base names written.
std::vector<std::string> write_run_plots(const RunRecording& recording, const sim::WorldSpec& world,
                                         const std::filesystem::path& directory,
                                         const std::string& title);

}  // namespace legofeup::report
