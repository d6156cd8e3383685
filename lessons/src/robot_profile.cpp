#include "legofeup/lessons/robot_profile.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>

#include "config_reader.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "legofeup/lessons/run_config.hpp"
#include "text_file.hpp"
#include "toml_values.hpp"

namespace legofeup::lessons {
namespace {

constexpr std::string_view kCurveSection = "ir_curve";
constexpr std::size_t kMaxProgramName = 19;  // NXT file names: 15.3 characters

// One key of the file and the member it reads and writes; exactly one accessor is set.
struct ProfileField {
    std::string_view key;  // as written: "wheel_base", "ir_curve.c_m"
    std::string_view help;
    double& (*real)(RobotProfile&) = nullptr;
    int& (*integer)(RobotProfile&) = nullptr;
    bool& (*boolean)(RobotProfile&) = nullptr;
    std::string& (*text)(RobotProfile&) = nullptr;
};

ProfileField real_field(std::string_view key, std::string_view help,
                        double& (*get)(RobotProfile&)) {
    return {.key = key, .help = help, .real = get};
}
ProfileField integer_field(std::string_view key, std::string_view help,
                           int& (*get)(RobotProfile&)) {
    return {.key = key, .help = help, .integer = get};
}
ProfileField boolean_field(std::string_view key, std::string_view help,
                           bool& (*get)(RobotProfile&)) {
    return {.key = key, .help = help, .boolean = get};
}
ProfileField text_field(std::string_view key, std::string_view help,
                        std::string& (*get)(RobotProfile&)) {
    return {.key = key, .help = help, .text = get};
}

// Every field in the order the file lists them.
const std::vector<ProfileField>& profile_fields() {
    using P = RobotProfile;
    static const std::vector<ProfileField> fields = {
        text_field("name", "what this robot is called",
                   [](P& p) -> std::string& { return p.name; }),
        text_field(
            "bluetooth_address",
            "the brick's Bluetooth address, \"00:16:53:XX:XX:XX\"; \"\" = choose when connecting",
            [](P& p) -> std::string& { return p.bluetooth_address; }),
        text_field(
            "relay_program",
            "program on the brick that relays readings (e.g. \"legofeup.rxe\"); \"\" = direct "
            "commands only",
            [](P& p) -> std::string& { return p.relay_program; }),
        real_field("right_wheel_diameter",
                   "D_R, effective diameter of the right wheel (wheel 1), m",
                   [](P& p) -> double& { return p.right_wheel_diameter; }),
        real_field("left_wheel_diameter", "D_L, effective diameter of the left wheel (wheel 2), m",
                   [](P& p) -> double& { return p.left_wheel_diameter; }),
        real_field("wheel_base", "b, effective distance between the wheels' contact points, m",
                   [](P& p) -> double& { return p.wheel_base; }),
        real_field(
            "codo_right",
            "Codo1, counts per metre of the right wheel; left out = 360/(pi*right_wheel_diameter)",
            [](P& p) -> double& { return p.codo_right; }),
        real_field(
            "codo_left",
            "Codo2, counts per metre of the left wheel; left out = 360/(pi*left_wheel_diameter)",
            [](P& p) -> double& { return p.codo_left; }),
        real_field("power_per_meter_per_second",
                   "motor power (-100..100) per m/s of wheel speed, regulated motors",
                   [](P& p) -> double& { return p.power_per_meter_per_second; }),
        integer_field("right_motor_port", "output port of the right motor: 0 = A, 1 = B, 2 = C",
                      [](P& p) -> int& { return p.right_motor_port; }),
        integer_field("left_motor_port", "output port of the left motor: 0 = A, 1 = B, 2 = C",
                      [](P& p) -> int& { return p.left_motor_port; }),
        integer_field("front_ir_port",
                      "input port of the front IR sensor (d_s1): 0 = port 1 ... 3 = 4",
                      [](P& p) -> int& { return p.front_ir_port; }),
        integer_field("rear_ir_port",
                      "input port of the rear IR sensor (d_s2): 0 = port 1 ... 3 = 4",
                      [](P& p) -> int& { return p.rear_ir_port; }),
        boolean_field("reversed_motors", "true if positive motor power drives the robot backwards",
                      [](P& p) -> bool& { return p.reversed_motors; }),
        real_field("ir_curve.a", "a, unit of the fit: metres per fit unit (0.01: the fit is in cm)",
                   [](P& p) -> double& { return p.ir_curve.a; }),
        real_field("ir_curve.c_m", "C_M, constant of multiplication",
                   [](P& p) -> double& { return p.ir_curve.c_m; }),
        real_field("ir_curve.c_r", "C_R, constant of linearisation, A/D counts",
                   [](P& p) -> double& { return p.ir_curve.c_r; }),
        real_field("ir_curve.b", "b, offset of the fit, fit units",
                   [](P& p) -> double& { return p.ir_curve.b; }),
        real_field("ir_curve.min_range", "closer readings are not trusted, m",
                   [](P& p) -> double& { return p.ir_curve.min_range; }),
        real_field("ir_curve.max_range", "farther readings are not trusted, m",
                   [](P& p) -> double& { return p.ir_curve.max_range; }),
        real_field("ir_curve.peak_distance", "the output peaks here and folds back closer in, m",
                   [](P& p) -> double& { return p.ir_curve.peak_distance; }),
        real_field("ir_curve.contact_adc", "A/D value with the target touching the sensor",
                   [](P& p) -> double& { return p.ir_curve.contact_adc; }),
        integer_field("ir_curve.adc_max", "full scale of the A/D converter",
                      [](P& p) -> int& { return p.ir_curve.adc_max; }),
    };
    return fields;
}

// A sensor's own curve is written in [ir_curve] as `front_c_m`, `rear_b`, …: one key per
// sensor and eq. 2 parameter; the parameters a file leaves out are the shared curve's.
struct CurveParameter {
    std::string_view name;
    std::optional<double> IrCurveOverride::*written;
    double IrCurveParameters::*value;
    std::string_view help;
};
constexpr CurveParameter kCurveParameters[] = {
    {"a", &IrCurveOverride::a, &IrCurveParameters::a, "a, metres per fit unit"},
    {"c_m", &IrCurveOverride::c_m, &IrCurveParameters::c_m, "C_M"},
    {"c_r", &IrCurveOverride::c_r, &IrCurveParameters::c_r, "C_R, A/D counts"},
    {"b", &IrCurveOverride::b, &IrCurveParameters::b, "b, fit units"},
};

std::string sensor_name(IrSensor sensor) {
    return sensor == kFrontSensor ? "front" : "rear";
}

// "ir_curve.front_c_m": the key of one sensor's parameter as written in the file.
std::string sensor_curve_key(IrSensor sensor, const CurveParameter& parameter) {
    return std::string(kCurveSection) + "." + sensor_name(sensor) + "_"
           + std::string(parameter.name);
}

// "ir_curve.front.c_m": the same parameter as validate() names it.
std::string sensor_curve_field(IrSensor sensor, const CurveParameter& parameter) {
    return ir_sensor_curve_name(sensor) + "." + std::string(parameter.name);
}

const ProfileField* find_field(std::string_view key) {
    const auto& fields = profile_fields();
    const auto found = std::find_if(fields.begin(), fields.end(),
                                    [&](const ProfileField& field) { return field.key == key; });
    return found == fields.end() ? nullptr : &*found;
}

std::vector<std::string> all_keys() {
    std::vector<std::string> keys;
    for (const ProfileField& field : profile_fields()) {
        keys.emplace_back(field.key);
    }
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        for (const CurveParameter& parameter : kCurveParameters) {
            keys.push_back(sensor_curve_key(sensor, parameter));
        }
    }
    return keys;
}

bool is_hex(char c) {
    return std::isxdigit(static_cast<unsigned char>(c)) != 0;
}

bool valid_bluetooth_address(const std::string& address) {
    if (address.empty()) {
        return true;
    }
    if (address.size() != 17) {
        return false;
    }
    for (std::size_t i = 0; i < address.size(); ++i) {
        if (i % 3 == 2 ? address[i] != ':' : !is_hex(address[i])) {
            return false;
        }
    }
    return true;
}

bool valid_program_name(const std::string& name) {
    if (name.empty()) {
        return true;
    }
    const bool characters = std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
    });
    return characters && name.size() <= kMaxProgramName && name.size() > 4
           && name.ends_with(".rxe");
}

// Everything wrong with a profile's values, each issue named by its key in the file.
std::vector<ConfigIssue> profile_issues(const RobotProfile& p) {
    std::vector<ConfigIssue> issues;
    ConfigChecker check(issues);
    check.in_range("right_wheel_diameter", p.right_wheel_diameter, 0.005, 1.0);
    check.in_range("left_wheel_diameter", p.left_wheel_diameter, 0.005, 1.0);
    check.in_range("wheel_base", p.wheel_base, 0.02, 2.0);
    check.positive("codo_right", p.codo_right, 1e6);
    check.positive("codo_left", p.codo_left, 1e6);
    check.positive("power_per_meter_per_second", p.power_per_meter_per_second, 1e4);
    check.in_range("right_motor_port", p.right_motor_port, 0, 2);
    check.in_range("left_motor_port", p.left_motor_port, 0, 2);
    check.require(p.left_motor_port != p.right_motor_port, "left_motor_port", p.left_motor_port,
                  "the right motor already uses this output port");
    check.in_range("front_ir_port", p.front_ir_port, 0, 3);
    check.in_range("rear_ir_port", p.rear_ir_port, 0, 3);
    check.require(p.rear_ir_port != p.front_ir_port, "rear_ir_port", p.rear_ir_port,
                  "the front IR sensor already uses this input port");
    if (!valid_bluetooth_address(p.bluetooth_address)) {
        issues.push_back({"bluetooth_address", "\"" + p.bluetooth_address + "\"",
                          "must be \"\" or six hex pairs separated by colons, e.g. "
                          "\"00:16:53:0A:1B:2C\""});
    }
    if (!valid_program_name(p.relay_program)) {
        issues.push_back({"relay_program", "\"" + p.relay_program + "\"",
                          "must be \"\" or an NXT program name of at most 19 letters, digits, "
                          "'_', '-' or '.', ending in .rxe"});
    }
    const auto curve = validate(p.ir_curve, std::string(kCurveSection));
    issues.insert(issues.end(), curve.begin(), curve.end());
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto& own = p.ir_sensor_parameters[static_cast<std::size_t>(sensor)];
        if (own && curve.empty()) {
            const auto sensor_curve =
                validate(with_curve_parameters(p.ir_curve, *own), ir_sensor_curve_name(sensor));
            issues.insert(issues.end(), sensor_curve.begin(), sensor_curve.end());
        }
    }
    return issues;
}

class ProfileReader {
  public:
    explicit ProfileReader(std::string source) : source_(std::move(source)) {}

    RobotProfile read(const toml::table& root) {
        RobotProfile profile;
        for (const auto& [key, node] : root) {
            const std::string name(key.str());
            const auto* section = node.as_table();
            if (section != nullptr && name == kCurveSection) {
                for (const auto& [inner_key, inner_node] : *section) {
                    read_field(name + "." + std::string(inner_key.str()), inner_node, profile);
                }
            } else if (section != nullptr) {
                problem(line_of(node), "[" + name + "]", "",
                        "unknown section (the only section is [ir_curve])");
            } else {
                read_field(name, node, profile);
            }
        }
        for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
            const IrCurveOverride& own = sensor_curves_[static_cast<std::size_t>(sensor)];
            if (!own.empty()) {
                profile.ir_sensor_parameters[static_cast<std::size_t>(sensor)] =
                    own.applied_to(profile.ir_curve);
            }
        }
        if (!lines_.contains("codo_right")) {
            profile.codo_right =
                nominal_counts_per_metre(profile.right_wheel_diameter, kNxtCountsPerTurn);
        }
        if (!lines_.contains("codo_left")) {
            profile.codo_left =
                nominal_counts_per_metre(profile.left_wheel_diameter, kNxtCountsPerTurn);
        }
        if (problems_.empty()) {
            for (const ConfigIssue& issue : profile_issues(profile)) {
                const auto line = lines_.find(issue.field);
                const auto written = texts_.find(issue.field);
                problem(line == lines_.end() ? 0 : line->second, issue.field,
                        written == texts_.end() ? issue.value : written->second, issue.reason);
            }
        }
        return profile;
    }

    std::vector<InputProblem>& problems() { return problems_; }

  private:
    void read_field(const std::string& key, const toml::node& node, RobotProfile& profile) {
        const int line = line_of(node);
        if (read_sensor_curve(key, node)) {
            return;
        }
        const ProfileField* field = find_field(key);
        if (field == nullptr) {
            const std::string match = closest_match(key, all_keys());
            problem(line, key, "",
                    "unknown setting" + (match.empty() ? "" : " (did you mean '" + match + "'?)"));
            return;
        }
        lines_[key] = line;
        texts_[key] = node_text(node);
        if (field->real != nullptr) {
            if (const auto number = number_of(node)) {
                field->real(profile) = *number;
                return;
            }
            problem(line, key, node_text(node), "must be a number");
        } else if (field->integer != nullptr) {
            const auto* whole = node.as_integer();
            if (whole != nullptr && whole->get() >= std::numeric_limits<int>::min()
                && whole->get() <= std::numeric_limits<int>::max()) {
                field->integer(profile) = static_cast<int>(whole->get());
                return;
            }
            problem(line, key, node_text(node), "must be a whole number");
        } else if (field->boolean != nullptr) {
            if (const auto* flag = node.as_boolean()) {
                field->boolean(profile) = flag->get();
                return;
            }
            problem(line, key, node_text(node), "must be true or false");
        } else if (const auto* words = node.as_string()) {
            field->text(profile) = words->get();
        } else {
            problem(line, key, node_text(node), "must be a quoted text");
        }
    }

    // A sensor's own curve parameter (`ir_curve.front_c_m`): true if `key` is one.
    bool read_sensor_curve(const std::string& key, const toml::node& node) {
        for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
            for (const CurveParameter& parameter : kCurveParameters) {
                if (key != sensor_curve_key(sensor, parameter)) {
                    continue;
                }
                // Issues name the sensor's curve as validate() does: point them here.
                const std::string field = sensor_curve_field(sensor, parameter);
                lines_[field] = line_of(node);
                texts_[field] = node_text(node);
                if (const auto number = number_of(node)) {
                    sensor_curves_[static_cast<std::size_t>(sensor)].*parameter.written = *number;
                } else {
                    problem(line_of(node), key, node_text(node), "must be a number");
                }
                return true;
            }
        }
        return false;
    }

    void problem(int line, std::string key, std::string value, std::string reason) {
        problems_.push_back({source_, line, std::move(key), std::move(value), std::move(reason)});
    }

    std::string source_;
    std::vector<InputProblem> problems_;
    std::map<std::string, int> lines_;                           // key → line it was set on
    std::map<std::string, std::string> texts_;                   // key → value as written
    std::array<IrCurveOverride, kIrSensorCount> sensor_curves_;  // as written, until read
};

std::string toml_number(double value) {
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string written(buffer, error == std::errc() ? end : buffer);
    if (written.find_first_of(".eEn") == std::string::npos) {
        written += ".0";  // keep it a TOML float
    }
    return written;
}

std::string toml_string(const std::string& value) {
    std::string quoted = "\"";
    for (const char c : value) {
        const auto byte = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += c;
        } else if (byte < 0x20 || byte == 0x7F) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04X", byte);
            quoted += escape;
        } else {
            quoted += c;
        }
    }
    return quoted + "\"";
}

bool codo_is_derived(double codo, double diameter) {
    return codo == nominal_counts_per_metre(diameter, kNxtCountsPerTurn);
}

}  // namespace

void derive_codo(RobotProfile& profile) {
    profile.codo_right = nominal_counts_per_metre(profile.right_wheel_diameter, kNxtCountsPerTurn);
    profile.codo_left = nominal_counts_per_metre(profile.left_wheel_diameter, kNxtCountsPerTurn);
}

WheelDiameters odometry_wheel_diameters(const RobotProfile& profile) {
    const auto diameter = [](double stored, double codo) {
        return codo_is_derived(codo, stored) ? stored : kNxtCountsPerTurn / (kPi * codo);
    };
    return {diameter(profile.right_wheel_diameter, profile.codo_right),
            diameter(profile.left_wheel_diameter, profile.codo_left)};
}

RobotProfile parse_robot_profile(std::string_view text, const std::string& source) {
    const toml::table root = parse_toml(text, source);
    ProfileReader reader(source);
    RobotProfile profile = reader.read(root);
    if (!reader.problems().empty()) {
        throw InputError(std::move(reader.problems()));
    }
    return profile;
}

RobotProfile load_robot_profile(const std::string& path) {
    return parse_robot_profile(read_text_file(path, kRobotProfileFile), path);
}

std::string robot_profile_to_toml(const RobotProfile& profile) {
    RobotProfile copy = profile;
    const bool derived_right = codo_is_derived(profile.codo_right, profile.right_wheel_diameter);
    const bool derived_left = codo_is_derived(profile.codo_left, profile.left_wheel_diameter);
    std::ostringstream out;
    out << "# LegoFeup Lab robot profile: how this NXT is built and wired, and what calibration\n"
        << "# found (docs/calibration.md). Units are SI: metres, seconds, radians.\n"
        << "# A key left out keeps the nominal robot's value.\n\n";
    bool in_curve = false;
    for (const ProfileField& field : profile_fields()) {
        std::string_view name = field.key;
        if (name.starts_with(kCurveSection) && !in_curve) {
            out << "\n# The Sharp IR curve, paper eq. 2: D = a*(C_M/(A + C_R) - b), A the A/D "
                   "value\n["
                << kCurveSection << "]\n";
            in_curve = true;
        }
        if (in_curve) {
            name.remove_prefix(kCurveSection.size() + 1);
        }
        std::string value;
        if (field.real != nullptr) {
            value = toml_number(field.real(copy));
        } else if (field.integer != nullptr) {
            value = std::to_string(field.integer(copy));
        } else if (field.boolean != nullptr) {
            value = field.boolean(copy) ? "true" : "false";
        } else {
            value = toml_string(field.text(copy));
        }
        const bool derived =
            (name == "codo_right" && derived_right) || (name == "codo_left" && derived_left);
        out << (derived ? "# " : "") << name << " = " << value << "  # " << field.help << "\n";
    }
    // Still in [ir_curve], its last section: each sensor's own curve, where it has one.
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto& own = profile.ir_sensor_parameters[static_cast<std::size_t>(sensor)];
        if (!own) {
            continue;
        }
        out << "# The " << sensor_name(sensor) << " sensor's own curve (calibrate-ir fits each "
            << "sensor); its trusted range is the one above\n";
        for (const CurveParameter& parameter : kCurveParameters) {
            out << sensor_name(sensor) << "_" << parameter.name << " = "
                << toml_number((*own).*parameter.value) << "  # " << parameter.help << "\n";
        }
    }
    return out.str();
}

void save_robot_profile(const std::string& path, const RobotProfile& profile) {
    const auto issues = profile_issues(profile);
    if (!issues.empty()) {
        std::vector<InputProblem> problems;
        for (const ConfigIssue& issue : issues) {
            problems.push_back({path, 0, issue.field, issue.value, issue.reason});
        }
        throw InputError(std::move(problems));
    }
    fileio::write_file_atomically(path, robot_profile_to_toml(profile));
}

void apply_robot_profile(const RobotProfile& profile, LoopConfig& config) {
    config.odometry.codo_right = profile.codo_right;
    config.odometry.codo_left = profile.codo_left;
    config.odometry.wheel_base = profile.wheel_base;
    config.ir_curve = profile.ir_curve;
    config.ir_sensor_parameters = profile.ir_sensor_parameters;
}

}  // namespace legofeup::lessons
