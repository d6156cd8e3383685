#include "legofeup/ui/panels/setting_relevance.hpp"

#include <array>
#include <string_view>

namespace legofeup::ui {

namespace {

enum Uses : unsigned {
    kWalls = 1U << static_cast<unsigned>(Localisation::Walls),
    kBeacons = 1U << static_cast<unsigned>(Localisation::Beacons),
    kGyroFusion = 1U << static_cast<unsigned>(Localisation::GyroFusion),
    kCompass = 1U << static_cast<unsigned>(Localisation::Compass),
    kLaser = 1U << static_cast<unsigned>(Localisation::Laser),
    /// The EKF/UKF pose filter runs in every localisation but the 5-state fusion.
    kPoseFilter = kWalls | kBeacons | kCompass | kLaser,
    /// The odometry's Q11, Q22 (paper eq. 13 of LegoFeup): the laser lesson has its own Q
    /// (paper 001 eq. 13, laser.q_*).
    kOdometryQ = kWalls | kBeacons | kCompass | kGyroFusion,
};

struct Rule {
    std::string_view prefix;  ///< a whole key, or a section with its dot ("ir_curve.")
    unsigned uses;
    std::string_view lesson;
};

// First match wins: the whole keys before their sections.
constexpr std::array kRules = {
    Rule{"filter.q11", kOdometryQ, "the other lessons (the laser lesson's Q is laser.q_*)"},
    Rule{"filter.q22", kOdometryQ, "the other lessons (the laser lesson's Q is laser.q_*)"},
    Rule{"filter.r11", kWalls, "the wall lesson (IR sensors)"},
    Rule{"filter.r22", kWalls, "the wall lesson (IR sensors)"},
    Rule{"filter.wall_updates", kWalls, "the wall lesson"},
    Rule{"filter.gate", kWalls, "the wall lesson"},  // and filter.gate_probability
    Rule{"filter.kind", kPoseFilter, "the EKF/UKF lessons"},
    Rule{"filter.compare_kinds", kPoseFilter, "the EKF/UKF lessons"},
    Rule{"filter.ukf", kPoseFilter, "the EKF/UKF lessons"},  // filter.ukf_kappa
    Rule{"ir_curve.", kWalls, "the wall lesson (IR sensors)"},
    Rule{"ir_mount.", kWalls, "the wall lesson (IR sensors)"},
    Rule{"robot.ir_", kWalls, "the wall lesson (IR sensors)"},
    Rule{"simulator.ir_", kWalls, "the wall lesson (IR sensors)"},
    Rule{"association.", kWalls, "the wall lesson (wall association)"},
    Rule{"beacons.", kBeacons, "the beacon lesson"},
    Rule{"gyro_fusion.", kGyroFusion, "the wheel-speed lesson (5-state EKF)"},
    Rule{"compass.", kCompass, "the compass lesson"},
    Rule{"laser.", kLaser, "the laser lesson (scan matching in a map)"},
    // Not here, so always shown: the simulator's sensors (beacon_scanner, gyro,
    // accelerometers, compass_sensor, laser_scanner: a run may have them for its plots),
    // the kidnapping (the simulator's), the wheel-speed and velocity KFs (they run beside
    // every localisation) and the calibration.
};

const Rule* rule_for(const std::string& key) {
    for (const Rule& rule : kRules) {
        if (key.starts_with(rule.prefix)) {
            return &rule;
        }
    }
    return nullptr;
}

}  // namespace

bool setting_relevant(const std::string& key, Localisation localisation) {
    const Rule* rule = rule_for(key);
    return rule == nullptr || (rule->uses & (1U << static_cast<unsigned>(localisation))) != 0U;
}

std::string setting_lesson(const std::string& key) {
    const Rule* rule = rule_for(key);
    return rule == nullptr ? std::string() : std::string(rule->lesson);
}

}  // namespace legofeup::ui
