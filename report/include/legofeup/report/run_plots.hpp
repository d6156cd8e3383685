#pragma once
// The plots of one run: the trajectory with 1σ ellipses, the errors with ±σ bands, Px, Py,
// Pθ, the IR distances and the wheel speeds, each as PNG and SVG.

#include <filesystem>
#include <string>
#include <vector>

#include "legofeup/lessons/lockstep_run.hpp"
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

  private:
    std::vector<Step> steps_;
};

/// Writes trajectory, errors, covariance, ir_distances and wheel_speeds (.png and .svg) into
/// `directory`, returning the base names written.
std::vector<std::string> write_run_plots(const RunRecording& recording, const sim::WorldSpec& world,
                                         const std::filesystem::path& directory,
                                         const std::string& title);

}  // namespace legofeup::report
