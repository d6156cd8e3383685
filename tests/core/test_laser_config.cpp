// The laser lesson's settings: names, validation with field names, the map requirement.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "laser_room.hpp"
#include "legofeup/core/legofeup_loop.hpp"
#include "legofeup/core/loop_config.hpp"

namespace legofeup {
namespace {

const ConfigIssue* find_issue(const std::vector<ConfigIssue>& issues, const std::string& field) {
    const auto found = std::find_if(issues.begin(), issues.end(),
                                    [&](const ConfigIssue& issue) { return issue.field == field; });
    return found == issues.end() ? nullptr : &*found;
}

LoopConfig laser_localisation_config() {
    LoopConfig config;
    config.lesson.localisation = Localisation::Laser;
    config.map = testing::laser_test_room();
    return config;
}

TEST(LaserConfig, LocalisationNameRoundTrips) {
    EXPECT_STREQ(to_string(Localisation::Laser), "laser");
    EXPECT_EQ(localisation_from_string("laser"), Localisation::Laser);
    EXPECT_EQ(localisation_from_string("Laser"), std::nullopt);
}

TEST(LaserConfig, DefaultsWithAMapAreValid) {
    EXPECT_TRUE(validate(laser_localisation_config()).empty());
    // The map is only required when the laser localises.
    EXPECT_TRUE(validate(LoopConfig{}).empty());
}

TEST(LaserConfig, LaserLocalisationNeedsANonEmptyMap) {
    LoopConfig config = laser_localisation_config();
    config.map = nullptr;
    auto issues = validate(config);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].field, "map");
    config.map = std::make_shared<const OccupancyGrid>();
    issues = validate(config);
    ASSERT_EQ(issues.size(), 1u);
    EXPECT_EQ(issues[0].field, "map");
    EXPECT_THROW(LegoFeupLoop{config}, std::invalid_argument);
}

TEST(LaserConfig, RefusesAbsurdTuningsWithFieldValueAndReason) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    LoopConfig config = laser_localisation_config();
    LaserTuning& laser = config.lesson.laser;
    laser.q_x_static = -1e-3;
    laser.q_theta_dynamic = nan;
    laser.r_x = 0.0;
    laser.r_theta = 1e12;
    laser.min_matched_points = -1;
    laser.recovery_after_mismatches = 0;
    laser.recovery_covariance_factor = 0.0;
    laser.recovery_correspondence_factor = 1.5;
    laser.mount.theta = std::numeric_limits<double>::infinity();
    laser.icp.max_iterations = 0;
    laser.geometry.beam_count = kMaxScanBeams + 1;
    const auto issues = validate(config);
    for (const char* field :
         {"lesson.laser.q_x_static", "lesson.laser.q_theta_dynamic", "lesson.laser.r_x",
          "lesson.laser.r_theta", "lesson.laser.min_matched_points",
          "lesson.laser.recovery_after_mismatches", "lesson.laser.recovery_covariance_factor",
          "lesson.laser.recovery_correspondence_factor", "lesson.laser.mount.theta",
          "lesson.laser.icp.max_iterations", "lesson.laser.geometry.beam_count"}) {
        EXPECT_NE(find_issue(issues, field), nullptr) << field;
    }
    const ConfigIssue* r_theta = find_issue(issues, "lesson.laser.r_theta");
    ASSERT_NE(r_theta, nullptr);
    EXPECT_EQ(r_theta->message(), "lesson.laser.r_theta = 1e+12: must be between 1e-15 and 1e+09");
    // A bad laser tuning is refused even while another localisation runs (it can be
    // switched to live).
    config.lesson.localisation = Localisation::Walls;
    EXPECT_FALSE(validate(config).empty());
}

TEST(LaserConfig, AcceptsTheLessonsExtremes) {
    LoopConfig config = laser_localisation_config();
    LaserTuning& laser = config.lesson.laser;
    laser.q_x_static = 0.0;  // no slip at rest
    laser.q_y_static = 0.0;
    laser.q_theta_static = 0.0;
    laser.q_x_dynamic = 0.0;
    laser.r_x = kMinUserVariance;
    laser.r_y = kMaxUserVariance;
    laser.min_matched_points = 0;
    laser.recovery_after_mismatches = 1;
    laser.recovery_covariance_factor = 1e6;
    laser.recovery_correspondence_factor = 1.0;
    EXPECT_TRUE(validate(config).empty());
}

}  // namespace
}  // namespace legofeup
