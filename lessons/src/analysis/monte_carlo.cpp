#include "legofeup/lessons/analysis/monte_carlo.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include "legofeup/core/consistency.hpp"
#include "legofeup/core/effective_samples.hpp"
#include "legofeup/core/pose_error.hpp"
#include "legofeup/core/wall_measurement.hpp"

namespace legofeup::lessons::analysis {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

/// χ² bounds of an average of `count` values, computed once per count (Nₖ changes only
/// where runs end).
class BoundsCache {
  public:
    explicit BoundsCache(int dof) : dof_(dof) {}
    ChiSquareInterval operator()(std::uint64_t count) {
        if (count == 0) {
            return {kNan, kNan};
        }
        auto [it, inserted] = cache_.try_emplace(count);
        if (inserted) {
            it->second = average_chi_square_interval(dof_, static_cast<int>(count), 0.95);
        }
        return it->second;
    }

  private:
    int dof_;
    std::map<std::uint64_t, ChiSquareInterval> cache_;
};

double mean_of(const ExactSum& sum, std::uint64_t count) {
    return count > 0 ? sum.value() / static_cast<double>(count) : kNan;
}

// The p-quantile of sorted values, interpolating linearly between neighbours.
double percentile(const std::vector<double>& sorted, double p) {
    const double position = p * static_cast<double>(sorted.size() - 1);
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    const double weight = position - static_cast<double>(below);
    return sorted[below] + weight * (sorted[above] - sorted[below]);
}

std::vector<double> column(const std::vector<RunRecord>& runs, double RunRecord::*field) {
    std::vector<double> values;
    values.reserve(runs.size());
    for (const RunRecord& run : runs) {
        values.push_back(run.*field);
    }
    return values;
}

// The pooled mean NEES weighs every step alike, so run i (Tᵢ steps, all with a truth in the
// simulator) has weight Tᵢ: N = (Σ Tᵢ)² / Σ Tᵢ²/N_i (pooled_effective_samples), divided by
// the runs' dispersion φ when φ > 1 (nees_dispersion: runs differ more than their N_i say).
void add_time_average_bounds(MonteCarloSummary& summary, const std::vector<RunRecord>& runs) {
    std::vector<double> weights;
    std::vector<double> effective;
    std::vector<double> averages;
    std::size_t inside = 0;
    for (const RunRecord& run : runs) {
        weights.push_back(static_cast<double>(run.steps));
        effective.push_back(run.nees_effective_samples);
        averages.push_back(run.mean_nees);
        inside += run.mean_nees >= run.time_average_nees_lower
                          && run.mean_nees <= run.time_average_nees_upper
                      ? 1U
                      : 0U;
    }
    summary.nees_dispersion = nees_dispersion(averages, effective, kStateSize);
    const double pooled = dispersion_corrected_samples(pooled_effective_samples(weights, effective),
                                                       summary.nees_dispersion);
    summary.time_average_nees_bounds =
        pooled > 0.0 ? time_average_chi_square_interval(kStateSize, pooled, 0.95)
                     : ChiSquareInterval{kNan, kNan};
    summary.runs_nees_inside_time_average_fraction =
        runs.empty() ? kNan : static_cast<double>(inside) / static_cast<double>(runs.size());
}

}  // namespace

void StepRecorder::on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) {
    if (!truth_known(truth)) {
        return;
    }
    const PoseError error = pose_error(snapshot.estimate, truth.pose);  // x̃ = x̂ − x
    samples_.push_back({
        normalized_estimation_error(error, snapshot.covariance),
        snapshot.update.status == StepStatus::Applied ? snapshot.update.nis : kNan,
        error.position() * error.position(),
        error.theta * error.theta,
    });
}

void StepSums::add(const StepSample& sample) {
    ++runs;
    position_squared.add(sample.position_squared);
    heading_squared.add(sample.heading_squared);
    if (std::isfinite(sample.nees)) {
        ++nees_runs;
        nees.add(sample.nees);
    }
    if (std::isfinite(sample.nis)) {
        ++nis_runs;
        nis.add(sample.nis);
    }
}

StepSums& StepSums::operator+=(const StepSums& other) {
    runs += other.runs;
    nees_runs += other.nees_runs;
    nis_runs += other.nis_runs;
    nees += other.nees;
    nis += other.nis;
    position_squared += other.position_squared;
    heading_squared += other.heading_squared;
    return *this;
}

RunRecord make_run_record(std::size_t index, std::uint64_t seed, const RunResult& result) {
    const RunMetrics& m = result.metrics;
    if (!m.truth) {
        throw std::runtime_error("run " + std::to_string(index) + " (seed " + std::to_string(seed)
                                 + ") had no ground truth: a Monte Carlo analysis scores its "
                                   "runs against the simulator's truth");
    }
    const TruthMetrics& t = *m.truth;
    return {index,
            seed,
            result.routine_finished,
            m.steps,
            m.updates_applied,
            t.rms_position_error,
            t.max_position_error,
            t.final_position_error,
            t.rms_heading_error,
            t.final_heading_error,
            t.mean_nees,
            t.nees_inside_fraction,
            m.mean_nis,
            t.nees_effective_samples,
            t.time_average_nees_bounds.lower,
            t.time_average_nees_bounds.upper};
}

void MonteCarloSums::add_run(const RunRecord& record, const std::vector<StepSample>& samples) {
    if (steps.size() < samples.size()) {
        steps.resize(samples.size());
    }
    for (std::size_t k = 0; k < samples.size(); ++k) {
        steps[k].add(samples[k]);
    }
    const auto later =
        std::upper_bound(runs.begin(), runs.end(), record.index,
                         [](std::size_t index, const RunRecord& run) { return index < run.index; });
    runs.insert(later, record);
}

void MonteCarloSums::merge(const MonteCarloSums& other) {
    if (steps.size() < other.steps.size()) {
        steps.resize(other.steps.size());
    }
    for (std::size_t k = 0; k < other.steps.size(); ++k) {
        steps[k] += other.steps[k];
    }
    std::vector<RunRecord> merged;
    merged.reserve(runs.size() + other.runs.size());
    std::merge(runs.begin(), runs.end(), other.runs.begin(), other.runs.end(),
               std::back_inserter(merged),
               [](const RunRecord& a, const RunRecord& b) { return a.index < b.index; });
    runs = std::move(merged);
}

void run_recorded(const std::vector<ResolvedRun>& runs, int jobs, const RecordedRunSink& sink,
                  const BatchProgress& progress) {
    run_batch(
        runs, jobs,
        [](std::size_t /*index*/) -> std::unique_ptr<RunObserver> {
            return std::make_unique<StepRecorder>();
        },
        [&](std::size_t index, const RunResult& result, std::unique_ptr<RunObserver> observer) {
            sink(index, result, static_cast<const StepRecorder&>(*observer).samples());
        },
        progress);
}

MonteCarloSums run_monte_carlo(const MonteCarloSpec& spec, int jobs, const Shard& shard,
                               const BatchProgress& progress) {
    const ResolvedRun base = resolve(spec.config);
    std::vector<ResolvedRun> runs;
    std::vector<std::size_t> indices;  // Monte Carlo index of each batch entry
    for (std::size_t index = 0; index < spec.runs; ++index) {
        if (shard.takes(index)) {
            runs.push_back(base);
            runs.back().config.seed = spec.first_seed + index;
            indices.push_back(index);
        }
    }
    MonteCarloSums sums;
    run_recorded(
        runs, jobs,
        [&](std::size_t k, const RunResult& result, const std::vector<StepSample>& samples) {
            sums.add_run(make_run_record(indices[k], runs[k].config.seed, result), samples);
        },
        progress);
    return sums;
}

Distribution describe(const std::vector<double>& values) {
    Distribution d;
    if (values.empty()) {
        return {kNan, kNan, kNan, kNan, kNan, kNan, kNan};
    }
    const auto count = static_cast<double>(values.size());
    double sum = 0.0;
    for (const double value : values) {
        sum += value;
    }
    d.mean = sum / count;
    double squares = 0.0;
    for (const double value : values) {
        squares += (value - d.mean) * (value - d.mean);
    }
    d.stddev = values.size() > 1 ? std::sqrt(squares / (count - 1.0)) : 0.0;
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    d.min = sorted.front();
    d.max = sorted.back();
    d.p5 = percentile(sorted, 0.05);
    d.median = percentile(sorted, 0.5);
    d.p95 = percentile(sorted, 0.95);
    return d;
}

MonteCarloSummary summarize(const MonteCarloSums& sums, double control_period) {
    MonteCarloSummary summary;
    summary.runs = sums.runs;
    BoundsCache nees_bounds(kStateSize);
    BoundsCache nis_bounds(WallMeasurement::kSize);  // front and rear IR distances
    double nees_total = 0.0;                         // Σₖ Σᵢ εᵢ,ₖ, step by step in order
    double nis_total = 0.0;
    std::uint64_t nees_count = 0;
    std::uint64_t nis_count = 0;
    std::size_t nees_steps = 0;
    std::size_t nees_inside = 0;
    std::size_t nis_steps = 0;
    std::size_t nis_inside = 0;
    summary.steps.reserve(sums.steps.size());
    for (std::size_t k = 0; k < sums.steps.size(); ++k) {
        const StepSums& s = sums.steps[k];
        StepStatistics step;
        step.step = k;
        step.time = static_cast<double>(k) * control_period;
        step.runs = s.runs;
        step.nees_runs = s.nees_runs;
        step.mean_nees = mean_of(s.nees, s.nees_runs);
        step.nees_bounds = nees_bounds(s.nees_runs);
        step.nis_runs = s.nis_runs;
        step.mean_nis = mean_of(s.nis, s.nis_runs);
        step.nis_bounds = nis_bounds(s.nis_runs);
        step.rms_position_error = std::sqrt(mean_of(s.position_squared, s.runs));
        step.rms_heading_error = std::sqrt(mean_of(s.heading_squared, s.runs));
        if (s.nees_runs > 0) {
            nees_total += s.nees.value();
            nees_count += s.nees_runs;
            ++nees_steps;
            nees_inside += step.nees_bounds.contains(step.mean_nees) ? 1U : 0U;
        }
        if (s.nis_runs > 0) {
            nis_total += s.nis.value();
            nis_count += s.nis_runs;
            ++nis_steps;
            nis_inside += step.nis_bounds.contains(step.mean_nis) ? 1U : 0U;
        }
        summary.steps.push_back(step);
    }
    summary.mean_nees = nees_count > 0 ? nees_total / static_cast<double>(nees_count) : kNan;
    summary.mean_nis = nis_count > 0 ? nis_total / static_cast<double>(nis_count) : kNan;
    summary.nees_inside_fraction =
        nees_steps > 0 ? static_cast<double>(nees_inside) / static_cast<double>(nees_steps) : kNan;
    summary.nis_inside_fraction =
        nis_steps > 0 ? static_cast<double>(nis_inside) / static_cast<double>(nis_steps) : kNan;
    add_time_average_bounds(summary, sums.runs);
    summary.runs_finished = static_cast<std::size_t>(std::count_if(
        sums.runs.begin(), sums.runs.end(), [](const RunRecord& r) { return r.routine_finished; }));
    summary.rms_position_error = describe(column(sums.runs, &RunRecord::rms_position_error));
    summary.final_position_error = describe(column(sums.runs, &RunRecord::final_position_error));
    summary.rms_heading_error = describe(column(sums.runs, &RunRecord::rms_heading_error));
    return summary;
}

}  // namespace legofeup::lessons::analysis
