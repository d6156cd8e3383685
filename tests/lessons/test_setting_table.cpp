// The settings table states every fact about a setting (lessons/config_schema.hpp): its
// label, help, page, whether it applies live and which runs use it. These tests hold the
// table to that: no entry without a label, help or page, no page without a title or a
// setting, and the facts the configuration panel shows (greying, live or next start) as the
// lessons need them. Leaving a fact out of an entry does not compile (Required, below).

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "legofeup/lessons/config_schema.hpp"
#include "setting_builders.hpp"

namespace legofeup::lessons {
namespace {

// An entry must state every fact: a designated initialiser that leaves one out is ill-formed.
template <class Facts>
concept FactsWithoutPage = requires {
    Facts{.key = "k",
          .field = "f",
          .label = in_words("l"),
          .help = "h",
          .applies = SettingApplies::Live,
          .use = kEveryRun};
};
template <class Facts>
concept AllFacts = requires {
    Facts{.key = "k",
          .field = "f",
          .label = in_words("l"),
          .help = "h",
          .page = SettingPage::Run,
          .applies = SettingApplies::Live,
          .use = kEveryRun};
};
static_assert(AllFacts<SettingFacts>);
static_assert(!FactsWithoutPage<SettingFacts>);

constexpr Localisation kLocalisations[] = {Localisation::Walls, Localisation::Beacons,
                                           Localisation::GyroFusion, Localisation::Compass,
                                           Localisation::Laser};

RunConfig localising_with(Localisation localisation) {
    RunConfig config;
    config.lesson.localisation = localisation;
    return config;
}

bool used(const std::string& key, Localisation localisation) {
    const Setting* setting = find_setting_by_key(key);
    EXPECT_NE(setting, nullptr) << key;
    return setting != nullptr && setting->used_by(localising_with(localisation));
}

bool live(const std::string& key) {
    const Setting* setting = find_setting_by_key(key);
    EXPECT_NE(setting, nullptr) << key;
    return setting != nullptr && setting->applies_live();
}

TEST(SettingTable, EveryEntryHasALabelAHelpAPageAndItsUsers) {
    const auto& pages = setting_pages();
    for (const Setting& setting : run_settings()) {
        EXPECT_NE(std::string(setting.label.text), "") << setting.key;
        EXPECT_FALSE(setting.help.empty()) << setting.key;
        EXPECT_NE(std::find(pages.begin(), pages.end(), setting.page), pages.end()) << setting.key;
        ASSERT_NE(setting.use.used_by, nullptr) << setting.key;
        // A setting some run does not use says which runs do (the greyed row's tooltip).
        const bool everywhere =
            std::all_of(std::begin(kLocalisations), std::end(kLocalisations),
                        [&](Localisation l) { return setting.used_by(localising_with(l)); });
        EXPECT_EQ(std::string(setting.use.runs).empty(), everywhere) << setting.key;
    }
}

TEST(SettingTable, EveryPageHasATitleAndSettings) {
    std::set<std::string> titles;
    for (const SettingPage page : setting_pages()) {
        const std::string title = setting_page_title(page);
        EXPECT_FALSE(title.empty());
        EXPECT_TRUE(titles.insert(title).second) << title;
        EXPECT_TRUE(std::any_of(run_settings().begin(), run_settings().end(),
                                [page](const Setting& s) { return s.page == page; }))
            << title;
    }
}

TEST(SettingTable, ABooleansHelpFitsBothStates) {
    // "false: odometry only" under a ticked box described the state it was not in.
    for (const Setting& setting : run_settings()) {
        if (setting.type != SettingType::Boolean) {
            continue;
        }
        EXPECT_FALSE(setting.help.starts_with("false:")) << setting.key;
        EXPECT_FALSE(setting.help.starts_with("true")) << setting.key;
        EXPECT_EQ(setting.help.find("off:") == std::string::npos,
                  setting.help.find("on:") == std::string::npos)
            << setting.key;
    }
    EXPECT_EQ(find_setting_by_key("filter.wall_updates")->help,
              "on: the IR distances to the walls correct the estimate; off: odometry only (walls "
              "are associated but never used)");
}

TEST(SettingTable, FilesWriteAPaperSymbolBeforeTheHelp) {
    EXPECT_EQ(find_setting_by_key("filter.q11")->file_comment(),
              "Q11: variance of ε_d per 50 ms period, m²");
    EXPECT_EQ(std::string(find_setting_by_key("filter.q11")->label.text), "Q11");
    EXPECT_EQ(std::string(find_setting_by_key("control.v_ref")->label.text), "V_ref");
    EXPECT_EQ(find_setting_by_key("filter.gate")->file_comment(),
              "reject updates whose NIS exceeds the χ²(2) gate");
    EXPECT_EQ(std::string(find_setting_by_key("filter.gate")->label.text), "gate");
}

TEST(SettingTable, EachLocalisationGreysTheOthersFilters) {
    EXPECT_TRUE(used("filter.r11", Localisation::Walls));
    EXPECT_FALSE(used("filter.r11", Localisation::Beacons));
    EXPECT_FALSE(used("ir_curve.max_range", Localisation::Compass));
    EXPECT_FALSE(used("association.max_incidence_deg", Localisation::GyroFusion));
    EXPECT_TRUE(used("beacons.r_bearing", Localisation::Beacons));
    EXPECT_FALSE(used("beacons.r_bearing", Localisation::Walls));
    EXPECT_TRUE(used("compass.r_compass", Localisation::Compass));
    EXPECT_FALSE(used("compass.r_compass", Localisation::Beacons));
    EXPECT_TRUE(used("gyro_fusion.r_w_gyro", Localisation::GyroFusion));
    // EKF or UKF: every pose filter but the 5-state fusion, which is an EKF only.
    for (const char* key : {"filter.kind", "filter.compare_kinds", "filter.ukf_kappa"}) {
        EXPECT_TRUE(used(key, Localisation::Walls)) << key;
        EXPECT_TRUE(used(key, Localisation::Beacons)) << key;
        EXPECT_TRUE(used(key, Localisation::Compass)) << key;
        EXPECT_FALSE(used(key, Localisation::GyroFusion)) << key;
    }
    // Shared settings stay.
    for (const char* key : {"filter.q11", "control.v_ref", "seed", "gyro.noise"}) {
        for (const Localisation l : {Localisation::Walls, Localisation::Beacons,
                                     Localisation::GyroFusion, Localisation::Compass}) {
            EXPECT_TRUE(used(key, l)) << key;
        }
    }
    // The laser lesson (paper 001): its scan matching only there; its Q is its own (eq. 13),
    // so the odometry's Q11, Q22 are the other lessons'; the simulated scanner is always
    // there (a simulator sensor) and "laser." is not "laser_scanner.".
    for (const char* key : {"laser.r_x", "laser.min_matched_points", "laser.icp_metric",
                            "laser.recovery_covariance_factor", "laser.map", "laser.beam_count"}) {
        EXPECT_TRUE(used(key, Localisation::Laser)) << key;
        for (const Localisation l : {Localisation::Walls, Localisation::Beacons,
                                     Localisation::GyroFusion, Localisation::Compass}) {
            EXPECT_FALSE(used(key, l)) << key;
        }
    }
    for (const char* key : {"filter.q11", "filter.q22", "filter.r11", "ir_curve.a",
                            "beacons.r_bearing", "compass.k_d"}) {
        EXPECT_FALSE(used(key, Localisation::Laser)) << key;
    }
    for (const char* key : {"filter.kind", "laser_scanner.enabled", "laser_scanner.beam_count",
                            "kidnap.time", "control.v_ref"}) {
        EXPECT_TRUE(used(key, Localisation::Laser)) << key;
        EXPECT_TRUE(used(key, Localisation::Walls)) << key;
    }
    EXPECT_STREQ(find_setting_by_key("laser.r_x")->use.runs,
                 "the laser lesson (scan matching in a map)");
    EXPECT_STREQ(find_setting_by_key("laser_scanner.enabled")->use.runs, "");
    EXPECT_STREQ(find_setting_by_key("filter.r11")->use.runs, "the wall lesson (IR sensors)");
    EXPECT_STREQ(find_setting_by_key("control.v_ref")->use.runs, "");
}

TEST(SettingTable, TheLoopsSettingsApplyLiveTheStartsWait) {
    // The filter, the controller's speeds and gains, the robot, the IR curve and the
    // association, the further lessons' estimators, and the simulator's noise: at the
    // loop's next step.
    for (const char* key :
         {"filter.q11", "filter.wall_updates", "filter.kind", "control.v_ref",
          "control.heading_tolerance_deg", "robot.wheel_base", "ir_curve.front_a",
          "association.gate", "localisation.method", "beacons.r_bearing", "compass.r_compass",
          "laser.min_matched_points", "laser.beam_count", "wheel_speed_kf.p0",
          "calibration.gyro_offset", "simulator.wheel_diameter_ratio", "simulator.ir_noise"}) {
        EXPECT_TRUE(live(key)) << key;
    }
    // The routine's shape (the loop builds the controller once, at the start: its waypoints,
    // pauses and random places), the run's length, the world, the seed, the starting belief,
    // the simulated robot's body and timing and its sensors: at the next start.
    for (const char* key :
         {"control.routine", "control.line_from", "control.circle_radius", "control.goto_x",
          "control.pause", "control.random_points", "control.rectangle_corner",
          "control.rectangle_size", "seed", "laps", "world", "initial.var_x", "simulator.mass",
          "simulator.ir_model", "beacon_scanner.enabled", "laser_scanner.enabled",
          "laser_scanner.beam_count", "kidnap.time"}) {
        EXPECT_FALSE(live(key)) << key;
    }
}

}  // namespace
}  // namespace legofeup::lessons
