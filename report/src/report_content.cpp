#include "report_content.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string_view>

#include "legofeup/lessons/config_schema.hpp"
#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::report::content {
namespace {

// Shown for every run: they make it repeatable and they are what the lessons tune.
constexpr std::array<std::string_view, 8> kAlwaysShown{
    "seed",       "filter.q11",    "filter.q22",    "filter.r11",
    "filter.r22", "initial.var_x", "initial.var_y", "initial.var_theta"};

std::string format_json(const nlohmann::json& value) {
    if (value.is_boolean()) {
        return value.get<bool>() ? "yes" : "no";
    }
    if (value.is_number_integer() || value.is_number_unsigned()) {
        return value.dump();
    }
    if (value.is_number()) {
        return format_number(value.get<double>());
    }
    if (value.is_array()) {
        std::string text = "[";
        for (std::size_t i = 0; i < value.size(); ++i) {
            text += (i > 0 ? ", " : "") + format_json(value[i]);
        }
        return text + "]";
    }
    if (value.is_object()) {
        std::string text;
        for (const auto& [key, item] : value.items()) {
            text += (text.empty() ? "" : ", ") + key + ": " + format_json(item);
        }
        return text;
    }
    if (value.is_string()) {
        return value.get<std::string>();
    }
    return "–";  // null: the metric was not available
}

/// A metric's value; for one that needs the truth and had none, a dash that says so.
std::string format_metric(const std::string& name, const nlohmann::json& value) {
    if (value.is_null() && lessons::is_truth_metric(name)) {
        return "— (no ground truth on this link)";
    }
    return format_json(value);
}

}  // namespace

std::vector<ParameterRow> parameter_rows(const lessons::RunConfig& config) {
    const lessons::RunConfig defaults;
    std::vector<ParameterRow> rows;
    for (const lessons::Setting& setting : lessons::run_settings()) {
        const bool set = !setting.is_set || setting.is_set(config);
        const bool always =
            std::find(kAlwaysShown.begin(), kAlwaysShown.end(), setting.key) != kAlwaysShown.end();
        const std::string value = set ? lessons::format_setting_value(setting.get(config)) : "";
        const bool default_set = !setting.is_set || setting.is_set(defaults);
        const std::string default_value =
            default_set ? lessons::format_setting_value(setting.get(defaults)) : "";
        if (always || (set && value != default_value)) {
            rows.push_back({setting.key, set ? value : "(default)",
                            default_set ? default_value : "(world start)", setting.file_comment()});
        }
    }
    return rows;
}

std::vector<MetricRow> metric_rows(const nlohmann::json& metrics) {
    std::vector<MetricRow> rows;
    if (!metrics.is_object()) {
        return rows;
    }
    for (const auto& [name, value] : metrics.items()) {
        if (!lessons::is_machine_dependent_metric(name)) {
            rows.push_back({name, format_metric(name, value)});
        }
    }
    return rows;
}

std::string format_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

const char* check_mark(bool passed) {
    return passed ? "✔ passed" : "✘ failed";
}

std::string checks_summary(const std::vector<lessons::CheckResult>& checks) {
    if (checks.empty()) {
        return "no checks";
    }
    const auto passed = std::count_if(checks.begin(), checks.end(),
                                      [](const lessons::CheckResult& c) { return c.passed; });
    return std::to_string(passed) + " of " + std::to_string(checks.size()) + " checks passed";
}

const StepOutcome* find_outcome(const StudentReport& report, const std::string& step_id) {
    const auto it = std::find_if(report.steps.begin(), report.steps.end(),
                                 [&](const StepOutcome& s) { return s.step_id == step_id; });
    return it == report.steps.end() ? nullptr : &*it;
}

const std::string* find_answer(const StepOutcome* outcome, const std::string& question_id) {
    if (outcome == nullptr) {
        return nullptr;
    }
    const auto it = outcome->answers.find(question_id);
    if (it == outcome->answers.end()
        || it->second.find_first_not_of(" \t\r\n") == std::string::npos) {
        return nullptr;
    }
    return &it->second;
}

}  // namespace legofeup::report::content
