#pragma once
// The one table of every setting a run configuration has, and every fact about each: its key
// in TOML files, the field name validation uses, its type and how to read and write it in a
// RunConfig, its label and help, the configuration panel's page it is on, whether it applies
// while the robot runs, and which runs use it. Files are read and written, summaries list
// settings, and the GUI builds its panel from this table, so a setting added here is
// available everywhere at once (docs/configuration.md, "Adding a setting").
//
// Labels, help and page titles are English source texts for Qt's translation: the GUI shows
// them through QCoreApplication::translate(kSettingTextContext, text), and lupdate collects
// them from the table's markers (lessons/src/setting_builders.hpp). Qt-free.

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

using SettingValue = std::variant<double, std::int64_t, bool, std::string, Vector2>;

enum class SettingType : std::uint8_t { Real, Integer, Boolean, Text, Point, Choice };

/// The translation context of every text of the table (labels, help, page titles, the runs
/// that use a setting): the namespace lupdate files the table's markers under.
inline constexpr const char* kSettingTextContext = "legofeup::lessons";

/// The configuration panel's pages, in the order students meet them: the filter's noise
/// first, the simulator's errors next.
enum class SettingPage : std::uint8_t {
    Filter,
    Localisation,
    Laser,
    InitialBelief,
    Controller,
    Simulator,
    SimulatedSensors,
    SimulatedLaser,
    Robot,
    Run,
};

/// Every page, in the panel's order.
const std::vector<SettingPage>& setting_pages();

/// A page's title (an English source text, see kSettingTextContext).
const char* setting_page_title(SettingPage page);

/// When a change made while the robot runs takes effect.
enum class SettingApplies : std::uint8_t {
    Live,       ///< at the loop's next step
    NextStart,  ///< at the next start or reset (the routine's shape, the simulated robot, …)
};

/// Which runs use a setting; the configuration panel greys it in the others.
struct SettingUse {
    /// Whether a run of this configuration uses the setting.
    bool (*used_by)(const RunConfig& config) = nullptr;
    /// The runs that do, in words for a greyed row's tooltip ("the wall lesson (IR
    /// sensors)"); "" for a setting every run uses.
    const char* runs = "";
};

/// How a row is labelled: the paper's symbol ("Q11", "V_ref"), which files also write before
/// the help, or the setting's name in words ("wall updates").
struct SettingLabel {
    const char* text = "";
    bool is_symbol = false;
};

struct Setting {
    std::string key;     ///< "section.name" as in TOML files, or "name" at the top level
    std::string field;   ///< the name validate() uses for it ("motion.v_ref", …)
    SettingLabel label;  ///< the panel row's label
    /// Meaning and unit, true of every value (a Boolean's help says what both states do):
    /// shown under the row, and written as a comment in files (file_comment()).
    std::string help;
    SettingPage page = SettingPage::Run;
    SettingApplies applies = SettingApplies::NextStart;
    SettingUse use;
    SettingType type = SettingType::Real;
    std::vector<std::string> choices;  ///< allowed texts of a Choice
    /// The largest whole number an Integer setting takes: what its member can hold (an
    /// int's 2147483647), so that no value read is cut to another one.
    std::int64_t integer_max = std::numeric_limits<std::int64_t>::max();
    std::function<SettingValue(const RunConfig&)> get;
    std::function<void(RunConfig&, const SettingValue&)> set;
    /// For optional settings: whether the configuration sets it (files write unset ones as
    /// comments). Empty for settings that always have a value.
    std::function<bool(const RunConfig&)> is_set;
    /// For Text settings that name a file: the names that select a built-in file (kept as
    /// written); any other relative path is taken from the configuration file's directory.
    /// Empty for settings that are not files.
    std::function<const std::vector<std::string>&()> built_in_files;

    std::string section() const;  ///< the part of key before the dot ("" at the top level)
    std::string name() const;     ///< the part after it
    /// The comment files write after the value: "Q11: variance of …" for a symbol's setting,
    /// the help alone for the others.
    std::string file_comment() const;
    bool applies_live() const { return applies == SettingApplies::Live; }
    /// Whether a run of `config` uses this setting (SettingUse).
    bool used_by(const RunConfig& config) const { return use.used_by(config); }
};

/// Every setting, in the order files list them.
const std::vector<Setting>& run_settings();

/// The setting with this key, or nullptr.
const Setting* find_setting_by_key(const std::string& key);
/// The setting validate() reports under this field name, or nullptr.
const Setting* find_setting_by_field(const std::string& field);

/// A value as TOML writes it (numbers in their shortest exact form).
std::string format_setting_value(const SettingValue& value);

}  // namespace legofeup::lessons
