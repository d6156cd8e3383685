// The Monte Carlo localisation lesson (resources/lessons/mcl.toml): reachable as
// "mcl:<step>", each step's checks pass on its own preset and fail on the run they must be
// told from — global localisation with and without augmented MCL's random particles (a),
// the particle filter tracking beside the EKF (b), the far kidnapping the particle filter
// recovers from while the EKF does not (c), and c again with recovery off, which must fail
// c's checks (so they test the recovery, not the kidnapping).
#include <gtest/gtest.h>

#include <string>

#include "legofeup/lessons/experiments.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/run_summary.hpp"
#include "lesson_checks_test_support.hpp"

namespace legofeup::lessons {
namespace {

const LessonStep& mcl_step(const std::string& id) {
    return built_in_step("mcl", id);
}

TEST(MclLesson, StepsAreParticleFilterRunsInTheOffice) {
    for (const char* id : {"a", "b", "c"}) {
        const Experiment* experiment = find_experiment(std::string("mcl:") + id);
        ASSERT_NE(experiment, nullptr) << id;
        EXPECT_EQ(experiment->config.lesson.kind, FilterKind::Pf) << id;
        EXPECT_EQ(experiment->config.lesson.localisation, Localisation::Laser) << id;
        EXPECT_EQ(experiment->config.world_file, "office") << id;
    }
    const RunConfig& a = find_experiment("mcl:a")->config;
    EXPECT_TRUE(a.initial.unknown_pose);
    EXPECT_EQ(a.steer_by, SteeringPose::Odometry);  // an unknown pose cannot steer
    EXPECT_TRUE(a.lesson.particles.recovery);
    EXPECT_TRUE(find_experiment("mcl:b")->config.lesson.compare_kinds);
    const RunConfig& c = find_experiment("mcl:c")->config;
    EXPECT_TRUE(c.lesson.compare_kinds);
    EXPECT_TRUE(c.simulator.kidnap.enabled);
    EXPECT_TRUE(c.lesson.particles.recovery);
    EXPECT_EQ(c.steer_by, SteeringPose::Estimate);
}

// One test, so each step runs once (a run is the slow part). Seeds outside those the
// thresholds were measured on (1–20, 101–110).
TEST(MclLesson, ChecksPassOnTheirOwnPresetAndFailWithoutTheRecovery) {
    const nlohmann::json a = metrics_of(mcl_step("a").config, 41);
    EXPECT_EQ(failures(evaluate_checks(mcl_step("a").checks, a)), "") << "mcl:a";
    // The start was unknown: the cloud's mean began metres from the robot.
    EXPECT_GT(a["max_position_error_m"].get<double>(), 1.0);

    const nlohmann::json b = metrics_of(mcl_step("b").config, 42);
    EXPECT_EQ(failures(evaluate_checks(mcl_step("b").checks, b)), "") << "mcl:b";

    const nlohmann::json c = metrics_of(mcl_step("c").config, 43);
    EXPECT_EQ(failures(evaluate_checks(mcl_step("c").checks, c)), "") << "mcl:c";
    // b's checks (both filters on the robot) fail on c's run: there the EKF stays lost.
    EXPECT_NE(failures(evaluate_checks(mcl_step("b").checks, c)), "");

    // c without random particles: the cloud has nothing near R3 and stays lost, so c's
    // checks must fail — they are about the recovery, not about the kidnapping.
    RunConfig no_recovery = mcl_step("c").config;
    no_recovery.lesson.particles.recovery = false;
    const nlohmann::json lost = metrics_of(no_recovery, 43);
    EXPECT_NE(failures(evaluate_checks(mcl_step("c").checks, lost)), "");
    EXPECT_GT(lost["final_position_error_m"].get<double>(), 3.0);
}

}  // namespace
}  // namespace legofeup::lessons
