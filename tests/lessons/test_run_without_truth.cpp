// A run without a ground truth, as on a real robot: the same frames with the truth withheld.
// Its counts are right (the trace's rows and applied updates, counted here from the file) and
// equal to those of the run with the truth; the metrics that need the truth are null, never
// 0, and a check on one fails saying why. With the truth, every one of them has a value.
#include <gtest/gtest.h>

#include <sstream>

#include "csv_test_support.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "legofeup/sim/lockstep_link.hpp"
#include "legofeup/sim/simulator.hpp"

namespace legofeup::lessons {
namespace {

struct TracedRun {
    RunResult result;
    std::string trace;
    nlohmann::json metrics;  ///< summary.json's "metrics"
};

ResolvedRun one_lap_of_f() {
    RunConfig config = find_experiment("f")->config;
    config.laps = 1;
    config.seed = 5;
    return resolve(config);
}

/// The run on the in-process simulator with its truth withheld: what a real robot gives.
TracedRun without_truth(const ResolvedRun& run) {
    sim::WorldSpec world = run.world;
    world.start = run.true_start;
    sim::Simulator simulator(world, run.robot, run.config.simulator, run.config.seed);
    sim::LockstepLink link(simulator);
    UnknownTruth truth;
    std::ostringstream csv;
    TraceCsvWriter writer(csv, run.loop);
    TracedRun traced;
    traced.result = run_with_link(run, link, truth, &writer);
    traced.trace = csv.str();
    traced.metrics = result_metrics_to_json(traced.result);
    return traced;
}

TracedRun with_truth(const ResolvedRun& run) {
    std::ostringstream csv;
    TraceCsvWriter writer(csv, run.loop);
    TracedRun traced;
    traced.result = run_lockstep(run, &writer);
    traced.trace = csv.str();
    traced.metrics = result_metrics_to_json(traced.result);
    return traced;
}

/// The trace's own counts: rows, and rows whose wall update was applied or refused.
struct TraceCounts {
    std::uint64_t rows = 0;
    std::uint64_t applied = 0;
    std::uint64_t rejected = 0;
    std::uint64_t with_truth = 0;
};

TraceCounts count(const std::string& trace) {
    TraceCounts counts;
    for (const auto& row : csv_testing::rows_of(trace)) {
        ++counts.rows;
        const std::string& update = row.at("update");
        counts.applied += update == "applied" ? 1U : 0U;
        counts.rejected += update.rfind("rejected", 0) == 0 ? 1U : 0U;
        counts.with_truth += row.at("x_true").empty() ? 0U : 1U;
    }
    return counts;
}

TEST(RunWithoutTruth, CountsAreTheTracesAndTheErrorsAreNullNotZero) {
    const ResolvedRun run = one_lap_of_f();
    const TracedRun blind = without_truth(run);
    const TracedRun seen = with_truth(run);

    const TraceCounts counts = count(blind.trace);
    EXPECT_EQ(counts.with_truth, 0U);  // the premise: no truth reached the trace
    EXPECT_GT(counts.applied, 50U);    // and the walls were used
    const RunMetrics& m = blind.result.metrics;
    EXPECT_EQ(m.steps, counts.rows);
    EXPECT_EQ(m.updates_applied, counts.applied);
    EXPECT_EQ(m.updates_rejected, counts.rejected);
    EXPECT_EQ(blind.result.steps_without_truth, counts.rows);
    EXPECT_FALSE(m.truth.has_value());

    // The loop never sees the truth: withholding it changes no count.
    const RunMetrics& s = seen.result.metrics;
    EXPECT_EQ(count(seen.trace).with_truth, count(seen.trace).rows);
    EXPECT_EQ(s.steps, m.steps);
    EXPECT_EQ(s.updates_applied, m.updates_applied);
    EXPECT_EQ(s.updates_rejected, m.updates_rejected);
    EXPECT_EQ(s.observations, m.observations);
    EXPECT_EQ(s.mean_nis, m.mean_nis);
    EXPECT_EQ(seen.metrics["association"], blind.metrics["association"]);
    ASSERT_TRUE(s.truth.has_value());
    EXPECT_EQ(s.truth->steps, s.steps);

    // summary.json: every metric that needs the truth is null without it and a value with
    // it; every other metric is a value in both.
    int truth_metrics = 0;
    for (const auto& [name, value] : seen.metrics.items()) {
        EXPECT_FALSE(value.is_null()) << name;
        EXPECT_EQ(blind.metrics.at(name).is_null(), is_truth_metric(name)) << name;
        truth_metrics += is_truth_metric(name) ? 1 : 0;
    }
    EXPECT_GE(truth_metrics, 30);
    EXPECT_GT(seen.metrics["final_position_error_m"].get<double>(), 0.0);
    EXPECT_EQ(blind.metrics["steps"], counts.rows);
    EXPECT_EQ(blind.metrics["updates_applied"], counts.applied);
}

TEST(RunWithoutTruth, ACheckOnAMetricThatNeedsTheTruthFailsSayingWhy) {
    const ResolvedRun run = one_lap_of_f();
    MetricCheck check;
    check.metric = "final_position_error_m";
    check.op = MetricCheck::Op::Less;
    check.threshold = 0.1;
    check.expression = "final_position_error_m < 0.1";
    MetricCheck updates = check;
    updates.metric = "updates_applied";
    updates.op = MetricCheck::Op::Greater;
    updates.threshold = 50.0;
    updates.expression = "updates_applied > 50";

    const auto blind = evaluate_checks({check, updates}, without_truth(run).metrics);
    EXPECT_FALSE(blind[0].passed);  // not passed as if the error were 0
    EXPECT_NE(blind[0].message.find("needs the ground truth"), std::string::npos)
        << blind[0].message;
    EXPECT_TRUE(blind[1].passed) << blind[1].message;  // a count needs none

    const auto seen = evaluate_checks({check, updates}, with_truth(run).metrics);
    EXPECT_TRUE(seen[0].passed) << seen[0].message;
    EXPECT_TRUE(seen[1].passed) << seen[1].message;
}

}  // namespace
}  // namespace legofeup::lessons
