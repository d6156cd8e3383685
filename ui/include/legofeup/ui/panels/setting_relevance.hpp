#pragma once
// Which settings matter to the lesson being run: the configuration panel greys the others
// (the IR sensors and the walls' association in the beacon lesson, the beacons' noise in
// the wall lesson, EKF/UKF in the 5-state fusion that is an EKF only, the scan matching
// outside the laser lesson and the odometry's Q11, Q22 in it). Qt-free.

#include <string>

#include "legofeup/core/lesson_filters_config.hpp"

namespace legofeup::ui {

/// Whether the setting with TOML key `key` is used by a run that localises with
/// `localisation`. Settings of no particular lesson (the controller, the simulator, the
/// run) are always relevant, and so is any key this table does not know.
bool setting_relevant(const std::string& key, Localisation localisation);

/// The lesson a setting belongs to, in words for its tooltip ("the wall lesson (IR
/// sensors)"), or "" for a setting of every lesson.
std::string setting_lesson(const std::string& key);

}  // namespace legofeup::ui
