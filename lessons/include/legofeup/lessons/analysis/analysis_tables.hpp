#pragma once
// What a Monte Carlo or a sweep leaves to read: summary.json and CSV tables. The same
// functions write the outputs of an unsharded command and of a merge, so both are byte for
// byte the same.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/analysis/sweep.hpp"

namespace legofeup::lessons::analysis {

/// What identifies a batch and what its outputs need besides the results. Every shard file
/// starts with it, so a merge can check that its shards belong together.
struct BatchHeader {
    std::string kind;  ///< "montecarlo" or "sweep"
    std::string experiment;
    std::string title;
    nlohmann::json configuration;  ///< the base configuration (config_to_json)
    std::size_t runs = 0;          ///< runs (per cell, for a sweep)
    std::uint64_t first_seed = 1;
    double control_period = 0.05;  ///< s, the time between control steps
    std::vector<double> q_scales;  ///< sweep only
    std::vector<double> r_scales;

    bool operator==(const BatchHeader& other) const = default;
};

BatchHeader monte_carlo_header(const MonteCarloSpec& spec, const std::string& experiment,
                               const std::string& title);
BatchHeader sweep_header(const SweepSpec& spec, const std::string& experiment,
                         const std::string& title);

/// The header as summary.json and shard files start, and back (throws std::exception on a
/// missing or mistyped field).
nlohmann::json to_json(const BatchHeader& header);
BatchHeader batch_header_from_json(const nlohmann::json& json);

/// A short fingerprint of everything in the header (FNV-1a, 16 hex digits), to tell batches
/// apart in messages.
std::string header_hash(const BatchHeader& header);

/// summary.json of a Monte Carlo: the configuration, the aggregates, and the averaged NEES
/// and NIS against their bounds.
nlohmann::json monte_carlo_summary_json(const BatchHeader& header,
                                        const MonteCarloSummary& summary);
/// steps.csv: one row per control step (averaged NEES and NIS with bounds, RMS errors).
std::string monte_carlo_steps_csv(const MonteCarloSummary& summary);
/// runs.csv: one row per run (seed and metrics).
std::string monte_carlo_runs_csv(const std::vector<RunRecord>& runs);

/// summary.json of a sweep: the grid, every cell, and the best cells.
nlohmann::json sweep_summary_json(const BatchHeader& header, const std::vector<SweepCell>& cells);
/// cells.csv: one row per cell.
std::string sweep_cells_csv(const std::vector<SweepCell>& cells);

/// A run record or a sweep cell as JSON (NaN as null) and back; the names are the CSV's
/// column names. from_json throws std::exception on a missing or mistyped field.
nlohmann::json to_json(const RunRecord& run);
RunRecord run_record_from_json(const nlohmann::json& json);
nlohmann::json to_json(const SweepCell& cell);
SweepCell sweep_cell_from_json(const nlohmann::json& json);

}  // namespace legofeup::lessons::analysis
