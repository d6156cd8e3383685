#pragma once
// A sweep over the filter's noise: a grid of factors multiplying the configuration's process
// noise Q (q11 and q22 together) and measurement noise R (r11 and r22 together). Every cell
// is a Monte Carlo of the same seeds (common random numbers: cells differ only in Q and R,
// not in the noise the runs drew), summarised by its error and its NEES consistency.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "legofeup/lessons/analysis/batch_run.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons::analysis {

/// Parses a list of positive factors: "0.01,0.1,1,10", or "LOW:HIGH:COUNT" for COUNT
/// log-spaced values from LOW to HIGH ("1e-2:1e2:5" is 0.01, 0.1, 1, 10, 100). Throws
/// InputError naming `option` (e.g. "--q") and the text.
std::vector<double> parse_scales(const std::string& text, const std::string& option);

struct SweepSpec {
    RunConfig config;
    std::vector<double> q_scales;  ///< rows of the grid
    std::vector<double> r_scales;  ///< columns
    std::size_t runs = 20;         ///< seeds per cell
    std::uint64_t first_seed = 1;

    std::size_t cell_count() const { return q_scales.size() * r_scales.size(); }
};

struct SweepCell {
    std::size_t index = 0;  ///< q_index · r_scales.size() + r_index
    std::size_t q_index = 0;
    std::size_t r_index = 0;
    double q_scale = 1.0;
    double r_scale = 1.0;
    std::size_t runs = 0;
    double rms_position_error = 0.0;    ///< mean over the runs of each run's RMS error, m
    double final_position_error = 0.0;  ///< mean over the runs, m
    double mean_nees = 0.0;             ///< over every run and step
    double nees_inside_fraction = 0.0;  ///< steps whose averaged NEES is inside its bounds
    double mean_nis = 0.0;
    double nis_inside_fraction = 0.0;
    /// log₁₀(mean NEES / 3): 0 for a consistent filter, > 0 overconfident (P too small:
    /// Q or R too low), < 0 pessimistic (P too large). One decade off is a factor 10.
    double consistency = 0.0;
};

/// Runs the cells `shard` takes (all by default), every cell's runs on `jobs` threads (0: all
/// cores); cells in index order. Progress counts runs. Throws InputError if a cell's
/// configuration is invalid.
std::vector<SweepCell> run_sweep(const SweepSpec& spec, int jobs, const Shard& shard = {},
                                 const BatchProgress& progress = {});

}  // namespace legofeup::lessons::analysis
