// The laser lesson (paper 001): reachable as "laser:<step>", each step's checks pass on its
// own preset, and each step's checks fail on the run of the step it must be told from —
// a lap (a), a nearby kidnapping the filter recovers from (b), a kidnapping into the twin
// hall it never notices (c), a far kidnapping it notices and sets off recovery for (d) but
// never finds the robot after, on several seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "lesson_checks_test_support.hpp"

namespace legofeup::lessons {
namespace {

const LessonStep& laser_step(const std::string& id) {
    return built_in_step("laser", id);
}

TEST(LaserLesson, StepsAreExperimentsInTheOfficeWithTheScanner) {
    const Experiment* a = find_experiment("laser:a");
    ASSERT_NE(a, nullptr);
    EXPECT_EQ(a->config.lesson.localisation, Localisation::Laser);
    EXPECT_TRUE(a->config.physical.laser_scanner.enabled);
    EXPECT_EQ(a->config.world_file, "office");
    EXPECT_EQ(a->config.routine.kind, RoutineSpec::Kind::Rectangle);
    EXPECT_FALSE(a->config.simulator.kidnap.enabled);
    EXPECT_TRUE(find_experiment("laser:b")->config.simulator.kidnap.enabled);
    EXPECT_TRUE(find_experiment("laser:c")->config.simulator.kidnap.enabled);
    const Experiment* d = find_experiment("laser:d");
    ASSERT_NE(d, nullptr);
    EXPECT_TRUE(d->config.simulator.kidnap.enabled);
    EXPECT_EQ(d->config.lesson.laser.min_matched_points, 500);
    EXPECT_EQ(a->config.lesson.laser.min_matched_points, 100);  // the default
}

// One test, so each step runs once (a run is the slow part; ctest starts every test in a
// program of its own).
TEST(LaserLesson, ChecksPassOnTheirOwnPresetAndFailOnTheStepTheyMustBeToldFrom) {
    std::map<std::string, nlohmann::json> metrics;
    for (const char* id : {"a", "b", "c", "d", "e"}) {
        metrics[id] = metrics_of(laser_step(id).config, 5);
        EXPECT_EQ(failures(evaluate_checks(laser_step(id).checks, metrics[id])), "")
            << "laser:" << id << "'s checks on its own run";
    }
    // a vs c: localised against lost in the twin hall; b vs a and c: the nearby kidnapping
    // happened (a has none) and was recovered from (c's was not); d vs b and c: the far
    // kidnapping set off the recovery (neither b's nearby one nor c's look-alike did); a vs e
    // and e vs a: the paper's Q makes the filter pessimistic, e's tuned Q consistent.
    const std::pair<const char*, const char*> must_fail[] = {{"a", "c"}, {"c", "a"}, {"b", "a"},
                                                             {"b", "c"}, {"d", "b"}, {"d", "c"},
                                                             {"a", "e"}, {"e", "a"}};
    for (const auto& [checks, run] : must_fail) {
        EXPECT_NE(failures(evaluate_checks(laser_step(checks).checks, metrics[run])), "")
            << checks << "'s checks passed on " << run << "'s run";
    }
}

// What step d's text says of each run: when the robot was kidnapped, when the recovery
// fired, and whether any scan after the kidnapping matched.
class KidnapWatcher final : public RunObserver {
  public:
    void on_step(const LoopSnapshot& snapshot, const GroundTruth& truth) override {
        if (truth.teleports > 0 && kidnap_time < 0.0) {
            kidnap_time = snapshot.time;  // the first step that sees the kidnapped robot
        }
        if (snapshot.laser.recovery_triggered) {
            recovery_times.push_back(snapshot.time);
        }
        if (kidnap_time >= 0.0 && snapshot.laser.matched) {
            ++matches_after_kidnap;
        }
    }

    double kidnap_time = -1.0;
    std::vector<double> recovery_times;
    int matches_after_kidnap = 0;
};

// Step d's outcome holds on any seed, not on a lucky one: the far kidnapping into R3 is
// noticed (every later scan refused), the recovery fires after exactly
// recovery_after_mismatches scans — (N − 1) scan periods after the kidnapping's own scan,
// 9.9 s — and nothing finds the robot again. Seeds apart from those the thresholds were
// measured on (1001–1020, 2001–2020).
TEST(LaserLesson, FarKidnappingIsNoticedTenSecondsLaterAndNeverFoundOnSeveralSeeds) {
    const LessonStep& d = laser_step("d");
    const int streak = d.config.lesson.laser.recovery_after_mismatches;
    const double scan_period = d.config.physical.laser_scanner.scan_period;
    ASSERT_EQ(streak, 100);  // the paper's §IV-B
    for (const std::uint64_t seed : {31u, 32u, 33u}) {
        RunConfig config = d.config;
        config.seed = seed;
        KidnapWatcher watcher;
        const nlohmann::json metrics =
            result_metrics_to_json(run_lockstep(resolve(config), &watcher));
        EXPECT_EQ(failures(evaluate_checks(d.checks, metrics)), "") << "seed " << seed;
        EXPECT_NEAR(watcher.kidnap_time, d.config.simulator.kidnap.time, 1e-9) << seed;
        EXPECT_EQ(watcher.matches_after_kidnap, 0) << "seed " << seed;
        ASSERT_EQ(watcher.recovery_times.size(), 1u) << "seed " << seed;
        EXPECT_NEAR(watcher.recovery_times.front() - watcher.kidnap_time,
                    (streak - 1) * scan_period, 1e-6)
            << "seed " << seed;
    }
}

}  // namespace
}  // namespace legofeup::lessons
