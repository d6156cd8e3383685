#pragma once
// The plots of a Monte Carlo and of a sweep, each as PNG and SVG: the averaged NEES and NIS
// against their χ² bounds, the RMS errors across runs over time, the final errors'
// histogram, and the sweep's heat maps of error and NEES consistency.

#include <filesystem>
#include <string>
#include <vector>

#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/analysis/sweep.hpp"

namespace legofeup::report {

/// Writes nees, nis, rms_errors and final_errors (.png and .svg) into `directory`, returning
/// the base names written. Throws std::runtime_error when a file cannot be written.
std::vector<std::string> write_monte_carlo_plots(
    const lessons::analysis::MonteCarloSummary& summary, const std::filesystem::path& directory,
    const std::string& title);

/// Writes sweep_rms_error and sweep_nees_consistency (.png and .svg): cells as Q-scale rows
/// × R-scale columns with their values written in them.
std::vector<std::string> write_sweep_plots(const std::vector<lessons::analysis::SweepCell>& cells,
                                           const std::vector<double>& q_scales,
                                           const std::vector<double>& r_scales,
                                           const std::filesystem::path& directory,
                                           const std::string& title);

}  // namespace legofeup::report
