#pragma once
// The one list of every setting a run configuration has: its key in TOML files, the field
// name validation uses, its meaning and unit, its type, and how to read and write it in a
// RunConfig. Files are read and written, and summaries and the GUI list settings, from this
// table, so a setting added here is available everywhere at once.

#include <cstdint>
#include <functional>
#include <string>
#include <variant>
#include <vector>

#include "legofeup/lessons/run_config.hpp"

namespace legofeup::lessons {

using SettingValue = std::variant<double, std::int64_t, bool, std::string, Vector2>;

enum class SettingType : std::uint8_t { Real, Integer, Boolean, Text, Point, Choice };

struct Setting {
    std::string key;    ///< "section.name" as in TOML files, or "name" at the top level
    std::string field;  ///< the name validate() uses for it ("motion.v_ref", …)
    std::string help;   ///< meaning and unit, written as a comment in files
    SettingType type = SettingType::Real;
    std::vector<std::string> choices;  ///< allowed texts of a Choice
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
