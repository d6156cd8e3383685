#include "legofeup/lessons/config_schema.hpp"

#include <charconv>
#include <cmath>

#include "setting_builders.hpp"

namespace legofeup::lessons {
namespace {

std::vector<Setting> make_settings() {
    std::vector<Setting> s;
    add_run_and_filter_settings(s);
    add_lesson_filter_settings(s);
    add_laser_settings(s);
    add_simulated_sensor_settings(s);
    add_laser_simulation_settings(s);
    add_initial_and_control_settings(s);
    add_robot_settings(s);
    add_simulator_settings(s);
    return s;
}

}  // namespace

const std::vector<SettingPage>& setting_pages() {
    static const std::vector<SettingPage> pages = {
        SettingPage::Filter,
        SettingPage::Localisation,
        SettingPage::Laser,
        SettingPage::InitialBelief,
        SettingPage::Controller,
        SettingPage::Simulator,
        SettingPage::SimulatedSensors,
        SettingPage::SimulatedLaser,
        SettingPage::Robot,
        SettingPage::Run,
    };
    return pages;
}

const char* setting_page_title(SettingPage page) {
    switch (page) {
        case SettingPage::Filter:
            return tr_noop("Filter: Q and R; EKF, UKF or particle filter");
        case SettingPage::Localisation:
            return tr_noop("Localisation and the lessons' filters");
        case SettingPage::Laser:
            return tr_noop("Laser: scan matching, kidnapping recovery");
        case SettingPage::InitialBelief:
            return tr_noop("Initial belief: pose and P0");
        case SettingPage::Controller:
            return tr_noop("Controller: path, V_ref, W_ref");
        case SettingPage::Simulator:
            return tr_noop("Simulator: noise and systematic errors");
        case SettingPage::SimulatedSensors:
            return tr_noop("Simulator: beacons, gyro, accelerometers, compass");
        case SettingPage::SimulatedLaser:
            return tr_noop("Simulator: laser rangefinder, kidnapping");
        case SettingPage::Robot:
            return tr_noop("Robot and sensors");
        case SettingPage::Run:
            return tr_noop("Run: seed, laps, world");
    }
    return "";
}

std::string Setting::section() const {
    const auto dot = key.find('.');
    return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

std::string Setting::name() const {
    const auto dot = key.find('.');
    return dot == std::string::npos ? key : key.substr(dot + 1);
}

std::string Setting::file_comment() const {
    return label.is_symbol ? std::string(label.text) + ": " + help : help;
}

const std::vector<Setting>& run_settings() {
    static const std::vector<Setting> settings = make_settings();
    return settings;
}

const Setting* find_setting_by_key(const std::string& key) {
    for (const Setting& setting : run_settings()) {
        if (setting.key == key) {
            return &setting;
        }
    }
    return nullptr;
}

const Setting* find_setting_by_field(const std::string& field) {
    for (const Setting& setting : run_settings()) {
        if (setting.field == field) {
            return &setting;
        }
    }
    return nullptr;
}

std::string format_setting_value(const SettingValue& value) {
    const auto number = [](double x) {
        if (!std::isfinite(x)) {
            return std::string(std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf"));
        }
        char buffer[32];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
        std::string text(buffer, result.ptr);
        // TOML needs a decimal point or an exponent to read a float back as a float.
        if (text.find_first_of(".eE") == std::string::npos) {
            text += ".0";
        }
        return text;
    };
    struct Formatter {
        decltype(number)& format;
        std::string operator()(double x) const { return format(x); }
        std::string operator()(std::int64_t x) const { return std::to_string(x); }
        std::string operator()(bool x) const { return x ? "true" : "false"; }
        std::string operator()(const std::string& x) const {
            std::string quoted = "\"";
            for (char ch : x) {
                if (ch == '"' || ch == '\\') {
                    quoted += '\\';
                }
                quoted += ch;
            }
            return quoted + "\"";
        }
        std::string operator()(const Vector2& x) const {
            return "[" + format(x.x()) + ", " + format(x.y()) + "]";
        }
    };
    return std::visit(Formatter{number}, value);
}

}  // namespace legofeup::lessons
