// Writing submissions: the TOML document parse_submission reads back, and the [tuning] a
// configuration amounts to.
#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/submission.hpp"
#include "tuning_settings.hpp"

namespace legofeup::lessons {
namespace {

// TOML escapes for the characters a basic string cannot hold as they are. `multiline`
// keeps line breaks (for """ strings); quotes are always escaped, so no run of three
// quotes can end the string early.
std::string escaped(const std::string& text, bool multiline) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '\\' || c == '"') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += multiline ? "\n" : "\\n";
        } else if (c == '\t') {
            out += c;
        } else if (c == '\r') {
            out += "\\r";
        } else if (byte < 0x20 || byte == 0x7F) {
            char code[8];
            std::snprintf(code, sizeof code, "\\u%04X", static_cast<unsigned>(byte));
            out += code;
        } else {
            out += c;
        }
    }
    return out;
}

std::string quoted(const std::string& text) {
    return "\"" + escaped(text, false) + "\"";
}

// A key as TOML needs it: bare when it can be, quoted otherwise.
std::string key_text(const std::string& key) {
    const bool bare = !key.empty()
                      && key.find_first_not_of(
                             "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghij"
                             "klmnopqrstuvwxyz0123456789_-")
                             == std::string::npos;
    return bare ? key : quoted(key);
}

// A run-configuration document's sections moved under [tuning]: "[filter]" becomes
// "[tuning.filter]", and top-level keys go under a [tuning] header of their own.
std::string under_tuning(const std::string& tuning_toml) {
    std::istringstream lines(tuning_toml);
    std::string out;
    std::string line;
    bool in_section = false;
    bool top_header_written = false;
    while (std::getline(lines, line)) {
        if (line.size() > 2 && line.front() == '[' && line.back() == ']') {
            out += "\n[tuning." + line.substr(1) + "\n";
            in_section = true;
            continue;
        }
        if (!in_section && !top_header_written
            && line.find_first_not_of(" \t") != std::string::npos) {
            out += "\n[tuning]\n";
            top_header_written = true;
        }
        out += line + "\n";
    }
    return out;
}

}  // namespace

bool is_tunable(const std::string& key, const GradingSpec& grading) {
    const Setting* setting = find_setting_by_key(key);
    const auto dot = key.find('.');
    const std::string section = setting != nullptr         ? setting->section()
                                : dot != std::string::npos ? key.substr(0, dot)
                                                           : std::string();
    return std::any_of(grading.tunable.begin(), grading.tunable.end(),
                       [&](const std::string& name) { return name == key || name == section; });
}

std::string settings_to_toml(const RunConfig& config, const std::set<std::string>& keys) {
    std::string top;
    std::vector<std::string> section_order;
    std::map<std::string, std::string> sections;
    for (const Setting& setting : run_settings()) {
        if (keys.count(setting.key) == 0 || (setting.is_set && !setting.is_set(config))) {
            continue;
        }
        const std::string line =
            setting.name() + " = " + format_setting_value(setting.get(config)) + "\n";
        const std::string section = setting.section();
        if (section.empty()) {
            top += line;
            continue;
        }
        if (sections.count(section) == 0) {
            section_order.push_back(section);
        }
        sections[section] += line;
    }
    std::string out = top;
    for (const std::string& section : section_order) {
        out += (out.empty() ? "" : "\n") + ("[" + section + "]\n") + sections[section];
    }
    return out;
}

std::string tuning_to_toml(const RunConfig& tuned, const Lesson& lesson) {
    const LessonStep* graded = lesson.grading ? lesson.find_step(lesson.grading->step) : nullptr;
    if (graded == nullptr) {
        return {};
    }
    std::set<std::string> changed;
    for (const Setting& setting : run_settings()) {
        const auto shown = [&](const RunConfig& config) {
            return setting.is_set && !setting.is_set(config)
                       ? std::string("(unset)")
                       : format_setting_value(setting.get(config));
        };
        if (is_tunable(setting.key, *lesson.grading) && shown(tuned) != shown(graded->config)) {
            changed.insert(setting.key);
        }
    }
    return settings_to_toml(tuned, changed);
}

std::string submission_to_toml(const Submission& submission) {
    std::string out = "# LegoFeup Lab submission (docs/lessons.md)\n";
    out += "lesson = " + quoted(submission.lesson) + "\n";
    out += "students = " + quoted(submission.students) + "\n";
    for (const auto& [step, answers] : submission.answers) {
        out += "\n[answers." + key_text(step) + "]\n";
        for (const auto& [question, answer] : answers) {
            // The line break after the opening quotes is not part of the text (TOML).
            out += key_text(question) + " = \"\"\"\n" + escaped(answer, true) + "\"\"\"\n";
        }
    }
    return out + under_tuning(submission.tuning_toml);
}

}  // namespace legofeup::lessons
