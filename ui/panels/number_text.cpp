#include "legofeup/ui/panels/number_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "legofeup/lessons/config_schema.hpp"

namespace legofeup::ui {

std::optional<double> parse_number(const QString& text) {
    const std::string trimmed = text.trimmed().toStdString();
    if (trimmed.empty()) {
        return std::nullopt;
    }
    // from_chars has no locale: "0,5" is refused rather than read as 0 or 5.
    const char* first = trimmed.data();
    const char* last = first + trimmed.size();
    if (*first == '+') {
        ++first;
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

QString number_text(double value) {
    return QString::fromStdString(lessons::format_setting_value(lessons::SettingValue(value)));
}

}  // namespace legofeup::ui
