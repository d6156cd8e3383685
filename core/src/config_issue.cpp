#include "legofeup/core/config_issue.hpp"

#include <cmath>
#include <cstdio>

namespace legofeup {

std::string ConfigIssue::message() const {
    return field + " = " + value + ": " + reason;
}

std::string format_config_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

void ConfigChecker::require(bool ok, const std::string& field, double value,
                            const std::string& reason) {
    if (!ok) {
        issues_.push_back({field, format_config_number(value), reason});
    }
}

void ConfigChecker::finite(const std::string& field, double value) {
    require(std::isfinite(value), field, value, "must be a finite number");
}

void ConfigChecker::in_range(const std::string& field, double value, double low, double high) {
    require(std::isfinite(value) && value >= low && value <= high, field, value,
            "must be between " + format_config_number(low) + " and " + format_config_number(high));
}

void ConfigChecker::in_range_or_zero(const std::string& field, double value, double low,
                                     double high) {
    require(
        value == 0.0 || (std::isfinite(value) && value >= low && value <= high), field, value,
        "must be 0 or between " + format_config_number(low) + " and " + format_config_number(high));
}

void ConfigChecker::positive(const std::string& field, double value, double high) {
    require(std::isfinite(value) && value > 0.0 && value <= high, field, value,
            "must be greater than 0 and at most " + format_config_number(high));
}

std::string join_issue_messages(const std::vector<ConfigIssue>& issues,
                                std::string_view separator) {
    std::string text;
    for (const ConfigIssue& issue : issues) {
        if (!text.empty()) {
            text += separator;
        }
        text += issue.message();
    }
    return text;
}

std::invalid_argument invalid_configuration(std::string_view what,
                                            const std::vector<ConfigIssue>& issues) {
    return std::invalid_argument("invalid " + std::string(what) + " configuration:\n  "
                                 + join_issue_messages(issues, "\n  "));
}

}  // namespace legofeup
