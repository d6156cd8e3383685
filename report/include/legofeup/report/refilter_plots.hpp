#pragma once
// The plots of a re-filtered run (legofeup-cli refilter, the GUI's "re-filter"): the recorded
// estimate and the new one overlaid on the same raw readings — the trajectory with the
// truth, and the errors in x, y and θ of both with their ±σ bands.

#include <filesystem>
#include <string>
#include <vector>

#include "legofeup/lessons/recording/refilter.hpp"
#include "legofeup/report/run_plots.hpp"
#include "legofeup/sim/world.hpp"

namespace legofeup::report {

/// "refilter_trajectory" (walls, truth when known, recorded and new estimate) and, when the
/// truth is known, "refilter_errors" (estimate − truth in x, y, θ for both, each with ±σ).
std::vector<RunFigure> refilter_figures(const lessons::RefilterResult& result,
                                        const sim::WorldSpec& world, const std::string& title,
                                        int width = 1200);

/// Writes refilter_figures() as PNG and SVG into `directory`; returns the base names written.
/// Throws std::runtime_error when a file cannot be written.
std::vector<std::string> write_refilter_plots(const lessons::RefilterResult& result,
                                              const sim::WorldSpec& world,
                                              const std::filesystem::path& directory,
                                              const std::string& title);

}  // namespace legofeup::report
