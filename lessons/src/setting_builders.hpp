#pragma once
// What the settings table (settings_*.cpp) is written with: the facts every entry states, the
// runs that use a setting, the translation markers of its texts, and one builder a kind of
// value (a real bound to a member, an angle written in degrees, a choice of an enum, …).
// Internal to lessons.

#include <concepts>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/config_schema.hpp"

namespace legofeup::lessons {

// ---- translation markers ------------------------------------------------------------------
// The table's English texts are source texts for Qt's translation (the GUI passes them to
// QCoreApplication::translate with kSettingTextContext). lessons does not use Qt, so these
// markers only return their text; lupdate reads them as QT_TR_NOOP, with the context of the
// namespace they are written in ("legofeup::lessons"), when told
//   lupdate -tr-function-alias QT_TR_NOOP+=tr_noop,QT_TR_NOOP+=paper_symbol,QT_TR_NOOP+=in_words
// Every text they mark must be a string literal.

/// A help text, a page title or the runs that use a setting.
constexpr const char* tr_noop(const char* text) {
    return text;
}
/// A row labelled with the paper's symbol ("Q11"); files write it before the help.
constexpr SettingLabel paper_symbol(const char* symbol) {
    return {symbol, true};
}
/// A row labelled with the setting's name in words ("wall updates").
constexpr SettingLabel in_words(const char* words) {
    return {words, false};
}

// ---- which runs use a setting -------------------------------------------------------------

template <Localisation... kUsers>
bool localises_with(const RunConfig& config) {
    return ((config.lesson.localisation == kUsers) || ...);
}

inline bool every_run(const RunConfig& /*config*/) {
    return true;
}

/// The controller, the simulator and its sensors (a run may have them for its plots), the
/// kidnapping, the wheel-speed and velocity KFs (they run beside every localisation), the
/// calibration, the run itself.
inline constexpr SettingUse kEveryRun{every_run, ""};
inline constexpr SettingUse kWallLesson{localises_with<Localisation::Walls>,
                                        tr_noop("the wall lesson")};
inline constexpr SettingUse kWallLessonIr{localises_with<Localisation::Walls>,
                                          tr_noop("the wall lesson (IR sensors)")};
inline constexpr SettingUse kWallLessonAssociation{localises_with<Localisation::Walls>,
                                                   tr_noop("the wall lesson (wall association)")};
/// The EKF/UKF pose filter runs in every localisation but the 5-state fusion (an EKF only).
inline constexpr SettingUse kPoseFilterLessons{
    localises_with<Localisation::Walls, Localisation::Beacons, Localisation::Compass,
                   Localisation::Laser>,
    tr_noop("the EKF/UKF lessons")};
/// The odometry's Q11, Q22 (LegoFeup eq. 13): the laser lesson has its own Q (laser.q_*).
inline constexpr SettingUse kOdometryQLessons{
    localises_with<Localisation::Walls, Localisation::Beacons, Localisation::Compass,
                   Localisation::GyroFusion>,
    tr_noop("the other lessons (the laser lesson's Q is laser.q_*)")};
inline constexpr SettingUse kBeaconLesson{localises_with<Localisation::Beacons>,
                                          tr_noop("the beacon lesson")};
inline constexpr SettingUse kGyroFusionLesson{localises_with<Localisation::GyroFusion>,
                                              tr_noop("the wheel-speed lesson (5-state EKF)")};
inline constexpr SettingUse kCompassLesson{localises_with<Localisation::Compass>,
                                           tr_noop("the compass lesson")};
inline constexpr SettingUse kLaserLesson{localises_with<Localisation::Laser>,
                                         tr_noop("the laser lesson (scan matching in a map)")};

// ---- the facts of an entry ----------------------------------------------------------------

/// A fact an entry must state: it has no default, so a designated initialiser that leaves
/// it out does not compile.
template <class T>
struct Required {
    template <class Given>
    requires std::convertible_to<Given, T> Required(
        Given&& given)  // NOLINT(google-explicit-constructor): `.page = SettingPage::Run`
        : value(std::forward<Given>(given)) {}
    T value;
};

/// Everything the table says about a setting besides its type and where its value lives.
struct SettingFacts {
    Required<std::string> key;    ///< Setting::key
    Required<std::string> field;  ///< Setting::field
    Required<SettingLabel> label;
    Required<const char*> help;  ///< a literal marked with tr_noop
    Required<SettingPage> page;
    Required<SettingApplies> applies;
    Required<SettingUse> use;
};

/// Where a group of settings is, when it applies and who uses it (a section's settings
/// written by one helper, e.g. a scanner's geometry for the filter and for the simulator).
struct SectionFacts {
    Required<SettingPage> page;
    Required<SettingApplies> applies;
    Required<SettingUse> use;
};

namespace setting_builders {

/// The entry's facts, with no value bound yet.
inline Setting described(const SettingFacts& facts, SettingType type) {
    Setting s;
    s.key = facts.key.value;
    s.field = facts.field.value;
    s.label = facts.label.value;
    s.help = facts.help.value;
    s.page = facts.page.value;
    s.applies = facts.applies.value;
    s.use = facts.use.value;
    s.type = type;
    return s;
}

// A setting bound to one member of the configuration. `access` is a generic lambda,
// `[](auto& c) -> auto& { return c.member; }`, so the same accessor reads a const
// configuration and writes a mutable one: reading never copies the configuration. Real
// values are stored as `written × scale` (degrees → radians).
template <class T, class Access>
Setting bound(const SettingFacts& facts, SettingType type, Access access, double scale = 1.0) {
    Setting s = described(facts, type);
    s.get = [access, scale](const RunConfig& c) -> SettingValue {
        if constexpr (std::is_same_v<T, double>) {
            return access(c) / scale;
        } else {
            static_cast<void>(scale);  // only real values are scaled
            return access(c);
        }
    };
    s.set = [access, scale](RunConfig& c, const SettingValue& v) {
        if constexpr (std::is_same_v<T, double>) {
            access(c) = std::get<double>(v) * scale;
        } else {
            static_cast<void>(scale);
            access(c) = std::get<T>(v);
        }
    };
    return s;
}

template <class Access>
Setting real(const SettingFacts& facts, Access access) {
    return bound<double>(facts, SettingType::Real, access);
}

template <class Access>
Setting degrees(const SettingFacts& facts, Access access) {
    return bound<double>(facts, SettingType::Real, access, kPi / 180.0);
}

template <class Access>
Setting boolean(const SettingFacts& facts, Access access) {
    return bound<bool>(facts, SettingType::Boolean, access);
}

template <class Access>
Setting point(const SettingFacts& facts, Access access) {
    return bound<Vector2>(facts, SettingType::Point, access);
}

// A whole number bound to an int member; the reader refuses negative numbers and numbers
// an int cannot hold, validate() the rest of the range.
template <class Access>
Setting whole(const SettingFacts& facts, Access access) {
    Setting s = described(facts, SettingType::Integer);
    s.integer_max = std::numeric_limits<int>::max();
    s.get = [access](const RunConfig& c) -> SettingValue {
        return static_cast<std::int64_t>(access(c));
    };
    s.set = [access](RunConfig& c, const SettingValue& v) {
        access(c) = static_cast<int>(std::get<std::int64_t>(v));
    };
    return s;
}

// A Text setting naming a file: a built-in's name, or a path relative to the configuration.
inline Setting file(const SettingFacts& facts, std::string RunConfig::*member,
                    const std::vector<std::string>& (*built_in_names)()) {
    Setting s = described(facts, SettingType::Text);
    s.get = [member](const RunConfig& c) -> SettingValue { return c.*member; };
    s.set = [member](RunConfig& c, const SettingValue& v) { c.*member = std::get<std::string>(v); };
    s.built_in_files = built_in_names;
    return s;
}

// A real value that is only set when written (another value applies unless it is): `access`
// is a generic lambda returning the std::optional<double> member, `applies` gives the value
// that applies while it is unset (stored units).
template <class Access, class Applies>
Setting optional_real(const SettingFacts& facts, Access access, Applies applies,
                      double scale = 1.0) {
    Setting s = described(facts, SettingType::Real);
    s.get = [access, applies, scale](const RunConfig& c) -> SettingValue {
        return access(c).value_or(applies(c)) / scale;
    };
    s.set = [access, scale](RunConfig& c, const SettingValue& v) {
        access(c) = std::get<double>(v) * scale;
    };
    s.is_set = [access](const RunConfig& c) { return access(c).has_value(); };
    return s;
}

// One part of a pose override (the world's start pose unless set).
inline Setting pose_part(const SettingFacts& facts, PoseOverride RunConfig::*pose,
                         std::optional<double> PoseOverride::*part, double scale = 1.0) {
    return optional_real(
        facts, [ pose, part ](auto& c) -> auto& { return c.*pose.*part; },
        [](const RunConfig&) { return 0.0; }, scale);
}

// A Choice bound to an enum member: `values` named by to_string, read back with `parse`
// (the reader has already checked the text is one of the choices).
template <class Enum, class Access, class Parse>
Setting choice(const SettingFacts& facts, std::initializer_list<Enum> values, Parse parse,
               Access access) {
    Setting s = described(facts, SettingType::Choice);
    for (const Enum value : values) {
        s.choices.emplace_back(to_string(value));
    }
    s.get = [access](const RunConfig& c) -> SettingValue {
        return std::string(to_string(access(c)));
    };
    s.set = [access, parse](RunConfig& c, const SettingValue& v) {
        if (const auto value = parse(std::get<std::string>(v))) {
            access(c) = *value;
        }
    };
    return s;
}

}  // namespace setting_builders

// The parts of the table, each in its own file, in the order files list them.
void add_run_and_filter_settings(std::vector<Setting>& s);       // settings_run_filter.cpp
void add_lesson_filter_settings(std::vector<Setting>& s);        // settings_lesson_filters.cpp
void add_laser_settings(std::vector<Setting>& s);                // settings_laser.cpp
void add_simulated_sensor_settings(std::vector<Setting>& s);     // settings_simulated_sensors.cpp
void add_laser_simulation_settings(std::vector<Setting>& s);     // settings_laser.cpp
void add_initial_and_control_settings(std::vector<Setting>& s);  // settings_control.cpp
void add_robot_settings(std::vector<Setting>& s);                // settings_robot.cpp
void add_simulator_settings(std::vector<Setting>& s);            // settings_simulator.cpp

}  // namespace legofeup::lessons
