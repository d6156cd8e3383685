#pragma once
// Monte Carlo runs of one configuration: N runs with seeds S, S+1, …, S+N−1, averaged per
// control step across the runs (Bar-Shalom, Li & Kirubarajan §5.4):
//
//   ε̄ₖ = (1/Nₖ) Σᵢ εᵢ,ₖ   the averaged NEES; for a consistent 3-state filter Nₖ·ε̄ₖ ~ χ²(3Nₖ),
//                         so ε̄ₖ lies in [χ²₀.₀₂₅(3Nₖ)/Nₖ, χ²₀.₉₇₅(3Nₖ)/Nₖ] 95 % of the time;
//   ν̄ₖ = (1/Mₖ) Σᵢ νᵢ,ₖ   the averaged NIS of the Mₖ runs with an applied 2-D wall update at k,
//                         bounds χ²(2Mₖ)/Mₖ.
//
// Runs are aligned by step index; a run that ended earlier stops contributing, so Nₖ is
// counted per step. Per-step sums are exact (ExactSum) and per-run records are kept by
// index, so results are bit-identical for any number of jobs and any split into shards.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/lessons/analysis/batch_run.hpp"
#include "legofeup/lessons/analysis/exact_sum.hpp"
#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons::analysis {

/// What one run contributes at one control step.
struct StepSample {
    double nees = 0.0;              ///< NaN when P was not positive definite
    double nis = 0.0;               ///< NaN when no update was applied at this step
    double position_squared = 0.0;  ///< |p − p̂|², m²
    double heading_squared = 0.0;   ///< (θ − θ̂)², rad² (wrapped)
};

/// Records a StepSample for every step with a known truth (a few numbers per step, not
/// the snapshots: 1,000 runs stay small).
class StepRecorder final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override;
    const std::vector<StepSample>& samples() const { return samples_; }

  private:
    std::vector<StepSample> samples_;
};

/// Sums over the runs present at one control step; additive across runs and shards.
struct StepSums {
    std::uint64_t runs = 0;       ///< runs that reached this step
    std::uint64_t nees_runs = 0;  ///< of those, with a finite NEES (Nₖ)
    std::uint64_t nis_runs = 0;   ///< with an applied update (Mₖ)
    ExactSum nees;
    ExactSum nis;
    ExactSum position_squared;
    ExactSum heading_squared;

    void add(const StepSample& sample);
    StepSums& operator+=(const StepSums& other);
};

/// One run's outcome, as the tables list it.
struct RunRecord {
    std::size_t index = 0;  ///< 0 … N−1 within the Monte Carlo
    std::uint64_t seed = 0;
    bool routine_finished = false;
    std::uint64_t steps = 0;
    std::uint64_t updates_applied = 0;
    double rms_position_error = 0.0;  ///< m
    double max_position_error = 0.0;  ///< m
    double final_position_error = 0.0;
    double rms_heading_error = 0.0;  ///< rad
    double final_heading_error = 0.0;
    double mean_nees = 0.0;
    double nees_inside_fraction = 0.0;
    double mean_nis = 0.0;
    /// What the run's mean NEES is worth in independent samples, and the 95 % interval of that
    /// time average for a consistent filter (TruthMetrics::time_average_nees_bounds).
    double nees_effective_samples = 0.0;
    double time_average_nees_lower = 0.0;
    double time_average_nees_upper = 0.0;
};

RunRecord make_run_record(std::size_t index, std::uint64_t seed, const RunResult& result);

/// Everything additive about a set of runs: what a shard writes and a merge adds up.
struct MonteCarloSums {
    std::vector<StepSums> steps;  ///< by control step, as long as the longest run
    std::vector<RunRecord> runs;  ///< by index

    void add_run(const RunRecord& record, const std::vector<StepSample>& samples);
    /// Adds another set of runs (another shard); runs stay ordered by index.
    void merge(const MonteCarloSums& other);
};

struct MonteCarloSpec {
    RunConfig config;  ///< its seed is replaced by each run's
    std::size_t runs = 100;
    std::uint64_t first_seed = 1;
};

/// Runs the spec's runs that `shard` takes (all by default) on `jobs` threads (0: all cores).
/// Throws InputError if the configuration is invalid.
MonteCarloSums run_monte_carlo(const MonteCarloSpec& spec, int jobs, const Shard& shard = {},
                               const BatchProgress& progress = {});

/// The general form used by sweeps: runs `runs` and hands each run's result and samples to
/// `sink` in index order.
using RecordedRunSink = std::function<void(std::size_t index, const RunResult& result,
                                           const std::vector<StepSample>& samples)>;
void run_recorded(const std::vector<ResolvedRun>& runs, int jobs, const RecordedRunSink& sink,
                  const BatchProgress& progress = {});

/// The averages at one control step k.
struct StepStatistics {
    std::size_t step = 0;  ///< k, from 0
    double time = 0.0;     ///< k · control period, s
    std::uint64_t runs = 0;
    std::uint64_t nees_runs = 0;
    double mean_nees = 0.0;  ///< ε̄ₖ (NaN when no run has a finite NEES)
    ChiSquareInterval nees_bounds;
    std::uint64_t nis_runs = 0;
    double mean_nis = 0.0;  ///< ν̄ₖ (NaN when no run updated)
    ChiSquareInterval nis_bounds;
    double rms_position_error = 0.0;  ///< √(Σ|p − p̂|² / runs), m
    double rms_heading_error = 0.0;   ///< rad
};

/// Mean, standard deviation, extremes and percentiles (linear interpolation).
struct Distribution {
    double mean = 0.0;
    double stddev = 0.0;  ///< sample standard deviation (N − 1)
    double min = 0.0;
    double max = 0.0;
    double p5 = 0.0;
    double median = 0.0;
    double p95 = 0.0;
};

/// Of `values`, in their order (the result does not depend on how they were computed).
Distribution describe(const std::vector<double>& values);

struct MonteCarloSummary {
    std::vector<StepStatistics> steps;
    std::vector<RunRecord> runs;
    std::size_t runs_finished = 0;  ///< runs whose routine finished before the time limit
    Distribution rms_position_error;
    Distribution final_position_error;
    Distribution rms_heading_error;
    double mean_nees = 0.0;  ///< over every run and step with a finite NEES
    double mean_nis = 0.0;   ///< over every applied update
    /// Share of steps whose averaged NEES (NIS) lies inside its 95 % bounds; about 0.95 for
    /// a consistent filter.
    double nees_inside_fraction = 0.0;
    double nis_inside_fraction = 0.0;
    /// The 95 % interval of mean_nees (an average over runs and time) for a consistent filter:
    /// χ²(3N)/N with N the runs' effective samples pooled with their steps as weights
    /// (pooled_effective_samples), divided by nees_dispersion when that is above 1.
    ChiSquareInterval time_average_nees_bounds;
    /// How much more the runs' mean NEES scatter than their effective samples predict
    /// (legofeup::nees_dispersion; about 1 when they do not; NaN for one run).
    double nees_dispersion = 0.0;
    /// Share of runs whose own mean NEES lies inside its own time-average bounds; about 0.95
    /// for a consistent filter.
    double runs_nees_inside_time_average_fraction = 0.0;
};

/// The averages and aggregates of `sums`; `control_period` gives the steps' times.
MonteCarloSummary summarize(const MonteCarloSums& sums, double control_period);

}  // namespace legofeup::lessons::analysis
