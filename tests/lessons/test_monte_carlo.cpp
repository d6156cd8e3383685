// Monte Carlo averages checked against an independent computation from the runs' snapshots,
// its χ² bounds against core, its determinism for any jobs and any split into shards, and the
// shard files that carry the parts.

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <random>

#include "analysis_test_support.hpp"
#include "legofeup/core/consistency.hpp"
#include "legofeup/lessons/analysis/analysis_tables.hpp"
#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/analysis/shard_file.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

using testing::short_run_config;

MonteCarloSpec short_spec(std::size_t runs) {
    return {short_run_config(), runs, 11};
}

TEST(ExactSum, GivesTheSameBitsInAnyOrderAndSurvivesText) {
    std::mt19937_64 random(7);
    std::lognormal_distribution<double> value(0.0, 3.0);
    std::vector<double> values(500);
    for (double& v : values) {
        v = value(random);
    }
    ExactSum forward;
    double plain = 0.0;
    for (const double v : values) {
        forward.add(v);
        plain += v;
    }
    ExactSum backward;
    for (auto it = values.rbegin(); it != values.rend(); ++it) {
        backward.add(*it);
    }
    ExactSum odd;  // two "shards" merged
    ExactSum even;
    for (std::size_t k = 0; k < values.size(); ++k) {
        (k % 2 == 0 ? even : odd).add(values[k]);
    }
    odd += even;
    EXPECT_TRUE(forward == backward);
    EXPECT_TRUE(forward == odd);
    EXPECT_NEAR(forward.value(), plain, 1e-12 * plain);
    for (const ExactSum& sum : {forward, ExactSum{}}) {
        const auto back = ExactSum::from_text(sum.to_text());
        ASSERT_TRUE(back.has_value());
        EXPECT_TRUE(*back == sum);
    }
    ExactSum negative;
    negative.add(-2.5);
    EXPECT_EQ(negative.value(), -2.5);
    EXPECT_EQ(ExactSum::from_text(negative.to_text())->value(), -2.5);
    for (const std::string& bad :
         std::vector<std::string>{"", "-", "12g", "0x12", std::string(40, 'f')}) {
        EXPECT_FALSE(ExactSum::from_text(bad).has_value()) << bad;
    }
}

TEST(Describe, MeanDeviationExtremesAndInterpolatedPercentiles) {
    const Distribution d = describe({4.0, 1.0, 3.0, 2.0});
    EXPECT_DOUBLE_EQ(d.mean, 2.5);
    EXPECT_DOUBLE_EQ(d.stddev, std::sqrt(5.0 / 3.0));  // Σ(x − 2.5)² = 5, N − 1 = 3
    EXPECT_EQ(d.min, 1.0);
    EXPECT_EQ(d.max, 4.0);
    EXPECT_DOUBLE_EQ(d.median, 2.5);
    EXPECT_DOUBLE_EQ(d.p5, 1.15);  // position 0.05 · 3 between 1 and 2
    EXPECT_DOUBLE_EQ(d.p95, 3.85);
    EXPECT_TRUE(std::isnan(describe({}).mean));
}

// What each run's every step gave, recorded straight from the snapshots.
class Snapshots final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        nees.push_back(normalized_estimation_error(to_state(truth.pose), snapshot.estimate,
                                                   snapshot.covariance));
        nis.push_back(snapshot.update.status == StepStatus::Applied ? snapshot.update.nis
                                                                    : std::nan(""));
        position.push_back(
            std::hypot(truth.pose.x - snapshot.estimate(kX), truth.pose.y - snapshot.estimate(kY)));
    }
    std::vector<double> nees;
    std::vector<double> nis;
    std::vector<double> position;
};

TEST(MonteCarlo, AveragesPerStepMatchAnIndependentComputation) {
    const MonteCarloSpec spec = short_spec(3);
    const MonteCarloSummary summary =
        summarize(run_monte_carlo(spec, 2), spec.config.simulator.control_period);

    std::vector<Snapshots> runs(spec.runs);
    ResolvedRun run = resolve(spec.config);
    for (std::size_t i = 0; i < spec.runs; ++i) {
        run.config.seed = spec.first_seed + i;
        run_lockstep(run, &runs[i]);
    }
    ASSERT_GT(summary.steps.size(), 100U);
    std::size_t steps_with_nis = 0;
    for (std::size_t k = 0; k < summary.steps.size(); ++k) {
        double nees = 0.0;
        double nis = 0.0;
        double squares = 0.0;
        int present = 0;
        int updated = 0;
        for (const Snapshots& r : runs) {
            if (k < r.nees.size()) {
                ++present;
                nees += r.nees[k];
                squares += r.position[k] * r.position[k];
                if (!std::isnan(r.nis[k])) {
                    ++updated;
                    nis += r.nis[k];
                }
            }
        }
        const StepStatistics& s = summary.steps[k];
        ASSERT_EQ(s.runs, static_cast<std::uint64_t>(present)) << k;
        EXPECT_NEAR(s.mean_nees, nees / present, 1e-9 * (1.0 + nees / present)) << k;
        EXPECT_NEAR(s.rms_position_error, std::sqrt(squares / present), 1e-9) << k;
        EXPECT_DOUBLE_EQ(s.time, static_cast<double>(k) * spec.config.simulator.control_period);
        ASSERT_EQ(s.nis_runs, static_cast<std::uint64_t>(updated)) << k;
        if (updated > 0) {
            ++steps_with_nis;
            EXPECT_NEAR(s.mean_nis, nis / updated, 1e-9 * (1.0 + nis / updated)) << k;
        } else {
            EXPECT_TRUE(std::isnan(s.mean_nis)) << k;
        }
    }
    EXPECT_GT(steps_with_nis, 20U);  // the line passes walls: there were updates to average
    // Per-run records are the runs' own metrics, in seed order.
    ASSERT_EQ(summary.runs.size(), spec.runs);
    for (std::size_t i = 0; i < spec.runs; ++i) {
        EXPECT_EQ(summary.runs[i].index, i);
        EXPECT_EQ(summary.runs[i].seed, spec.first_seed + i);
        EXPECT_EQ(summary.runs[i].steps, runs[i].nees.size());
    }
}

TEST(MonteCarlo, BoundsAreCoresChiSquareIntervalsForTheRunsPresent) {
    const MonteCarloSpec spec = short_spec(3);
    const MonteCarloSummary summary =
        summarize(run_monte_carlo(spec, 2), spec.config.simulator.control_period);
    bool checked_nis = false;
    for (const StepStatistics& s : summary.steps) {
        const ChiSquareInterval nees =
            average_chi_square_interval(3, static_cast<int>(s.nees_runs));
        EXPECT_EQ(s.nees_bounds.lower, nees.lower);
        EXPECT_EQ(s.nees_bounds.upper, nees.upper);
        if (s.nis_runs > 0) {
            const ChiSquareInterval nis =
                average_chi_square_interval(2, static_cast<int>(s.nis_runs));
            EXPECT_EQ(s.nis_bounds.lower, nis.lower);
            EXPECT_EQ(s.nis_bounds.upper, nis.upper);
            checked_nis = true;
        }
    }
    EXPECT_TRUE(checked_nis);
    // N = 3 runs: the averaged NEES of a consistent filter lies in [χ²₀.₀₂₅(9)/3, χ²₀.₉₇₅(9)/3].
    EXPECT_NEAR(summary.steps[0].nees_bounds.lower, 2.700389 / 3.0, 1e-5);
    EXPECT_NEAR(summary.steps[0].nees_bounds.upper, 19.022768 / 3.0, 1e-5);

    // The mean over all runs and steps is a time average: its bounds come from the runs'
    // effective samples, each run weighted by its steps, N = (Σ Tᵢ)² / Σ Tᵢ²/N_i.
    double steps = 0.0;
    double variance = 0.0;
    for (const RunRecord& run : summary.runs) {
        ASSERT_GT(run.nees_effective_samples, 1.0);
        ASSERT_LT(run.nees_effective_samples, static_cast<double>(run.steps));
        const auto t = static_cast<double>(run.steps);
        steps += t;
        variance += t * t / run.nees_effective_samples;
        const ChiSquareInterval own =
            time_average_chi_square_interval(3, run.nees_effective_samples);
        EXPECT_EQ(run.time_average_nees_lower, own.lower);
        EXPECT_EQ(run.time_average_nees_upper, own.upper);
    }
    // … divided by the runs' dispersion φ = Σ (mᵢ/m̄ − 1)² · 3·N_i/2 / (R − 1) when above 1.
    double mean = 0.0;
    for (const RunRecord& run : summary.runs) {
        mean += run.mean_nees / static_cast<double>(summary.runs.size());
    }
    double pearson = 0.0;
    for (const RunRecord& run : summary.runs) {
        pearson += std::pow(run.mean_nees / mean - 1.0, 2) * 1.5 * run.nees_effective_samples;
    }
    const double dispersion = pearson / static_cast<double>(summary.runs.size() - 1);
    EXPECT_NEAR(summary.nees_dispersion, dispersion, 1e-12);
    const ChiSquareInterval pooled =
        time_average_chi_square_interval(3, steps * steps / variance / std::max(dispersion, 1.0));
    EXPECT_NEAR(summary.time_average_nees_bounds.lower, pooled.lower, 1e-12);
    EXPECT_NEAR(summary.time_average_nees_bounds.upper, pooled.upper, 1e-12);
    // Far narrower than one step's χ²(3) interval, wider than that of all steps independent.
    EXPECT_GT(summary.time_average_nees_bounds.lower, 0.216);
    EXPECT_LT(summary.time_average_nees_bounds.lower,
              average_chi_square_interval(3, static_cast<int>(steps)).lower);
}

TEST(MonteCarlo, TheTunedFilterIsConsistentOverManyRuns) {
    MonteCarloSpec spec{find_experiment("f")->config, 8, 1};
    spec.config.laps = 1;
    const MonteCarloSummary summary =
        summarize(run_monte_carlo(spec, 2), spec.config.simulator.control_period);
    // Experiment f is the tuned filter: NEES near its 3 degrees of freedom, errors of cm. Its
    // averaged NEES wanders (slip and the walls seen come and go, and the first steps, with
    // the estimate still at the true start, have a NEES near 0), so it is inside the narrow
    // bounds of 8 runs for part of the lap only; an untuned filter (Q/100) is almost never.
    EXPECT_GT(summary.mean_nees, 1.5);
    EXPECT_LT(summary.mean_nees, 6.0);
    EXPECT_GT(summary.nees_inside_fraction, 0.3);
    EXPECT_GT(summary.mean_nis, 1.0);
    EXPECT_LT(summary.mean_nis, 4.0);
    EXPECT_LT(summary.rms_position_error.mean, 0.1);
    EXPECT_EQ(summary.runs_finished, spec.runs);
    EXPECT_LE(summary.final_position_error.p5, summary.final_position_error.median);
    EXPECT_LE(summary.final_position_error.median, summary.final_position_error.p95);
    // Runs end at slightly different steps: the count per step falls from N as they end.
    EXPECT_EQ(summary.steps.front().runs, spec.runs);
    for (std::size_t k = 0; k < summary.steps.size(); k += 97) {
        std::uint64_t longer = 0;
        for (const RunRecord& run : summary.runs) {
            longer += run.steps > k ? 1U : 0U;
        }
        EXPECT_EQ(summary.steps[k].runs, longer) << k;
    }
}

TEST(MonteCarlo, BitIdenticalForOneOrTwoJobsAndForShardsMerged) {
    const MonteCarloSpec spec = short_spec(5);
    const BatchHeader header = monte_carlo_header(spec, "f", "test");
    const double period = spec.config.simulator.control_period;
    const MonteCarloSums one = run_monte_carlo(spec, 1);
    const MonteCarloSums two = run_monte_carlo(spec, 2);
    // Three shards, merged in reverse order, each through its shard file.
    MonteCarloSums merged;
    for (int i = 3; i >= 1; --i) {
        const Shard shard{i, 3};
        const MonteCarloSums part = run_monte_carlo(spec, 2, shard);
        const ShardFile file =
            parse_shard_file(monte_carlo_shard(header, shard, part).dump(), "shard.json");
        EXPECT_EQ(file.shard.index, i);
        EXPECT_TRUE(file.header == header);
        merged.merge(file.sums);
    }
    const std::string expected_json =
        monte_carlo_summary_json(header, summarize(one, period)).dump();
    const std::string expected_steps = monte_carlo_steps_csv(summarize(one, period));
    const std::string expected_runs = monte_carlo_runs_csv(one.runs);
    for (const MonteCarloSums* other : std::vector<const MonteCarloSums*>{&two, &merged}) {
        const MonteCarloSummary summary = summarize(*other, period);
        EXPECT_EQ(monte_carlo_summary_json(header, summary).dump(), expected_json);
        EXPECT_EQ(monte_carlo_steps_csv(summary), expected_steps);
        EXPECT_EQ(monte_carlo_runs_csv(summary.runs), expected_runs);
        ASSERT_EQ(other->steps.size(), one.steps.size());
        for (std::size_t k = 0; k < one.steps.size(); ++k) {
            ASSERT_TRUE(other->steps[k].nees == one.steps[k].nees) << k;
        }
    }
}

// The particle filter draws from its own random stream, started from each run's seed: its
// runs are as repeatable, and as independent of the thread that ran them, as the EKF's (and
// it is the particle filter that ran: the EKF's runs differ).
TEST(MonteCarlo, TheParticleFilterIsBitIdenticalForOneOrTwoJobs) {
    MonteCarloSpec spec = short_spec(3);
    spec.config.lesson.kind = FilterKind::Pf;
    spec.config.lesson.particles.particle_count = 200;
    spec.config.lesson.particles.recovery = true;
    const MonteCarloSums one = run_monte_carlo(spec, 1);
    const MonteCarloSums two = run_monte_carlo(spec, 2);
    ASSERT_EQ(one.steps.size(), two.steps.size());
    for (std::size_t k = 0; k < one.steps.size(); ++k) {
        ASSERT_TRUE(one.steps[k].nees == two.steps[k].nees) << k;
    }
    EXPECT_EQ(monte_carlo_runs_csv(one.runs), monte_carlo_runs_csv(two.runs));
    spec.config.lesson.kind = FilterKind::Ekf;
    EXPECT_NE(monte_carlo_runs_csv(run_monte_carlo(spec, 1).runs), monte_carlo_runs_csv(one.runs));
}

TEST(ShardFiles, MergeChecksTheyAreOneBatchAndAllThere) {
    const MonteCarloSpec spec = short_spec(2);
    const BatchHeader header = monte_carlo_header(spec, "f", "test");
    const auto file = [&](const BatchHeader& h, Shard shard, const std::string& name) {
        return parse_shard_file(monte_carlo_shard(h, shard, {}).dump(), name);
    };
    const auto problems_of = [](const std::vector<ShardFile>& shards) {
        try {
            merge_shards(shards);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("merged");
    };
    EXPECT_EQ(problems_of({file(header, {1, 2}, "a"), file(header, {2, 2}, "b")}), "merged");
    EXPECT_EQ(problems_of({file(header, {2, 3}, "a"), file(header, {1, 3}, "b")}),
              "merge: shard 3/3 is missing");
    EXPECT_NE(problems_of({file(header, {1, 2}, "a"), file(header, {1, 2}, "b")})
                  .find("b: shard = 1/2: given twice (also a)"),
              std::string::npos);
    EXPECT_NE(problems_of({file(header, {1, 2}, "a"), file(header, {2, 3}, "b")})
                  .find("b: shard = 2/3: differs from a (1/2)"),
              std::string::npos);
    MonteCarloSpec other_spec = spec;
    other_spec.config.filter.q11 *= 2.0;
    const BatchHeader other = monte_carlo_header(other_spec, "f", "test");
    EXPECT_NE(problems_of({file(header, {1, 2}, "a"), file(other, {2, 2}, "b")})
                  .find("b: configuration = " + header_hash(other)),
              std::string::npos);
    BatchHeader more_runs = header;
    more_runs.runs = 3;
    EXPECT_NE(problems_of({file(header, {1, 2}, "a"), file(more_runs, {2, 2}, "b")})
                  .find("b: runs = 3: differs from a (2)"),
              std::string::npos);
    SweepSpec sweep{spec.config, {1.0}, {1.0}, 2, 11};
    const ShardFile sweep_file =
        parse_shard_file(sweep_shard(sweep_header(sweep, "f", "test"), {2, 2}, {}).dump(), "s");
    EXPECT_NE(problems_of({file(header, {1, 2}, "a"), sweep_file})
                  .find("s: kind = sweep: differs from a (montecarlo)"),
              std::string::npos);
}

TEST(ShardFiles, RejectsWhatIsNotAShardWithTheFileAndTheReason) {
    const auto reason = [](const std::string& text) {
        try {
            parse_shard_file(text, "x.json");
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(reason("{not json").find("x.json: not a shard file (not JSON)"), std::string::npos);
    EXPECT_NE(reason("{\"a\": 1}").find("x.json: format: not a shard file"), std::string::npos);
    EXPECT_NE(reason(R"({"format": "legofeup-shard", "format_version": 99})")
                  .find("x.json: format_version = 99"),
              std::string::npos);
    EXPECT_NE(reason(R"({"format": "legofeup-shard", "format_version": 2})")
                  .find("x.json: damaged shard file"),
              std::string::npos);
    EXPECT_NE(reason(R"({"format": 5})").find("x.json: format: not a shard file"),
              std::string::npos);
    EXPECT_NE(reason(R"({"format": "legofeup-shard", "format_version": 1e300})")
                  .find("x.json: format_version = 1e+300"),
              std::string::npos);
}

// A well-formed shard with one whole number replaced: a number a cast could not hold (found
// by fuzz_shard_file as undefined behaviour) or a negative count is a damaged shard naming
// the field, never a wrapped or undefined value.
TEST(ShardFiles, RejectsWholeNumbersOutOfTheirRange) {
    const MonteCarloSpec spec = short_spec(2);
    const BatchHeader header = monte_carlo_header(spec, "f", "test");
    const nlohmann::json good = monte_carlo_shard(header, {1, 2}, run_monte_carlo(spec, 1, {1, 2}));
    ASSERT_EQ(parse_shard_file(good.dump(), "x.json").shard.count, 2);
    const auto reason = [&](const nlohmann::json::json_pointer& field,
                            const nlohmann::json& value) {
        nlohmann::json bad = good;
        bad[field] = value;
        try {
            parse_shard_file(bad.dump(), "x.json");
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    using Pointer = nlohmann::json::json_pointer;
    EXPECT_NE(reason(Pointer("/shard/count"), 1e300).find("count is 1e+300, not a whole number"),
              std::string::npos);
    EXPECT_NE(
        reason(Pointer("/shard/index"), 4294967297LL).find("index is 4294967297, out of range"),
        std::string::npos);
    EXPECT_NE(reason(Pointer("/header/runs"), -2).find("runs is -2, out of range"),
              std::string::npos);
    EXPECT_NE(reason(Pointer("/run_records/0/seed"), 2.5).find("seed is 2.5, not a whole number"),
              std::string::npos);
    EXPECT_NE(reason(Pointer("/steps/runs/0"), -1).find("steps.runs[0] is -1, out of range"),
              std::string::npos);
    EXPECT_NE(reason(Pointer("/steps/runs/0"), -1).find("x.json: damaged shard file"),
              std::string::npos);
}

}  // namespace
}  // namespace legofeup::lessons::analysis
