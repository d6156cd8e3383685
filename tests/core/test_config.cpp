#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "legofeup/core/loop_config.hpp"

namespace legofeup {
namespace {

bool mentions(const std::vector<ConfigIssue>& issues, const std::string& field) {
    return std::any_of(issues.begin(), issues.end(),
                       [&](const ConfigIssue& issue) { return issue.field == field; });
}

TEST(LoopConfig, DefaultsAreValid) {
    EXPECT_TRUE(validate(LoopConfig{}).empty());
}

TEST(LoopConfig, RefusesAbsurdVariancesWithFieldValueAndReason) {
    LoopConfig config;
    config.filter.q11 = 1e12;
    const auto issues = validate(config);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].field, "filter.q11");
    EXPECT_EQ(issues[0].value, "1e+12");
    EXPECT_EQ(issues[0].message(), "filter.q11 = 1e+12: must be between 1e-15 and 1e+09");
}

TEST(LoopConfig, AcceptsTheExperimentsExtremes) {
    LoopConfig config;
    config.filter.q11 = 1e-12;
    config.filter.q22 = 1e6;
    config.filter.r11 = 1e-12;
    config.filter.r22 = 1e3;
    EXPECT_TRUE(validate(config).empty());
}

TEST(LoopConfig, RefusesNonFiniteAndNonPositiveValues) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    LoopConfig config;
    config.filter.r11 = 0.0;
    config.filter.r22 = nan;
    config.initial.var_theta = -1.0;
    config.odometry.wheel_base = 0.0;
    config.motion.w_ref = std::numeric_limits<double>::infinity();
    config.gains.heading_gain = nan;
    config.filter.gate_probability = 1.0;
    const auto issues = validate(config);
    for (const char* field :
         {"filter.r11", "filter.r22", "initial.var_theta", "odometry.wheel_base", "motion.w_ref",
          "gains.heading_gain", "filter.gate_probability"}) {
        EXPECT_TRUE(mentions(issues, field)) << field;
    }
    EXPECT_EQ(issues.size(), 7u);
}

TEST(LoopConfig, RefusesAbsurdParticleFilterSettings) {
    LoopConfig config;
    config.lesson.kind = FilterKind::Pf;
    EXPECT_TRUE(validate(config).empty());
    for (const int count : {0, -5, kMaxParticleCount + 1, 1'000'000'000}) {
        config.lesson.particles.particle_count = count;
        const auto issues = validate(config);
        ASSERT_EQ(issues.size(), 1u) << count;
        EXPECT_EQ(issues[0].field, "pf.particles");
        EXPECT_EQ(issues[0].reason, "must be between 1 and 1000000");
    }
    config.lesson.particles = {};
    config.lesson.particles.alpha_fast = 0.0005;  // below alpha_slow
    config.lesson.particles.resample_threshold = 1.5;
    config.lesson.particles.scan_model.sigma_hit = 0.0;
    config.lesson.particles.motion_alphas.rotation_from_rotation = -0.1;
    config.lesson.particles.motion_alphas.translation_from_rotation = 2.0;
    const auto issues = validate(config);
    for (const char* field :
         {"pf.alpha_fast", "pf.resample_threshold", "pf.sigma_hit", "pf.alpha1", "pf.alpha4"}) {
        EXPECT_TRUE(mentions(issues, field)) << field;
    }
    EXPECT_EQ(issues.size(), 5u);
}

// Global localisation needs somewhere to spread the belief: walls that enclose an area, or
// in the laser lesson a map with a free cell.
TEST(LoopConfig, AnUnknownPoseNeedsFreeSpace) {
    LoopConfig config;
    config.initial.unknown_pose = true;
    EXPECT_TRUE(validate(config).empty());
    config.walls = WallMap{};
    auto issues = validate(config);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].message(),
              "initial.unknown_pose = 1: needs walls that enclose an area to spread the belief "
              "over");
    config.walls = standard_arena_walls(ArenaSpec{});
    config.lesson.localisation = Localisation::Laser;
    config.map = std::make_shared<const OccupancyGrid>(
        4, 4, 0.5, Pose2{}, std::vector<CellState>(16, CellState::Occupied));
    issues = validate(config);
    EXPECT_TRUE(mentions(issues, "initial.unknown_pose"));
    config.initial.unknown_pose = false;
    EXPECT_FALSE(mentions(validate(config), "initial.unknown_pose"));
}

TEST(LoopConfig, ChecksTheIrCurveAndMount) {
    LoopConfig config;
    config.ir_curve.max_range = 0.03;  // below min_range
    config.ir_mount.front_longitudinal = config.ir_mount.rear_longitudinal;
    const auto issues = validate(config);
    EXPECT_TRUE(mentions(issues, "ir_curve.max_range"));
    EXPECT_TRUE(mentions(issues, "ir_mount.front_longitudinal"));

    LoopConfig folded;
    folded.ir_curve.peak_distance = 0.05;  // above min_range: the fold-back would be trusted
    EXPECT_TRUE(mentions(validate(folded), "ir_curve.peak_distance"));

    LoopConfig off_scale;
    off_scale.ir_curve.c_m = 1e6;  // 4 cm would need an A/D value far above 1023
    EXPECT_TRUE(mentions(validate(off_scale), "ir_curve.c_m"));
}

TEST(LoopConfig, ChecksWallsAndRoutines) {
    LoopConfig config;
    config.walls = WallMap({{"dot", {1.0, 1.0}, {1.0, 1.0}}});
    config.controller = FollowCircle({0.0, 0.0}, -1.0, true);
    const auto issues = validate(config);
    EXPECT_TRUE(mentions(issues, "walls[0] (dot).end"));
    EXPECT_TRUE(mentions(issues, "controller.radius"));

    LoopConfig path;
    path.controller =
        FollowPath({LineSegment{{0, 0}, {1, 0}}, ArcSegment{{1, 1}, 1.0, true, 0.0}}, 1);
    EXPECT_TRUE(mentions(validate(path), "controller.path[1].sweep"));
}

}  // namespace
}  // namespace legofeup
