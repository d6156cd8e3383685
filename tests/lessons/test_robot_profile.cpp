// Robot profiles: the nominal robot's file, reading back what was written, every refusal,
// atomic saving, and what applying a profile changes in the loop's configuration.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "calibration_test_support.hpp"
#include "legofeup/comms/nxt/nxt_link.hpp"
#include "legofeup/fileio/atomic_file.hpp"
#include "legofeup/lessons/robot_profile.hpp"

namespace {

namespace fs = std::filesystem;
using legofeup::LoopConfig;
using legofeup::SharpIrCurve;
using legofeup::lessons::apply_robot_profile;
using legofeup::lessons::load_robot_profile;
using legofeup::lessons::RobotProfile;
using legofeup::lessons::save_robot_profile;
using legofeup::testing::input_error_of;

// Counts per metre of an NXT wheel, written out independently: 360 counts per turn.
double codo(double diameter) {
    return 360.0 / (std::numbers::pi * diameter);
}

void expect_same_curve(const SharpIrCurve& a, const SharpIrCurve& b) {
    EXPECT_EQ(a.a, b.a);
    EXPECT_EQ(a.c_m, b.c_m);
    EXPECT_EQ(a.c_r, b.c_r);
    EXPECT_EQ(a.b, b.b);
    EXPECT_EQ(a.min_range, b.min_range);
    EXPECT_EQ(a.max_range, b.max_range);
    EXPECT_EQ(a.peak_distance, b.peak_distance);
    EXPECT_EQ(a.contact_adc, b.contact_adc);
    EXPECT_EQ(a.adc_max, b.adc_max);
}

void expect_same_profile(const RobotProfile& a, const RobotProfile& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.bluetooth_address, b.bluetooth_address);
    EXPECT_EQ(a.right_wheel_diameter, b.right_wheel_diameter);
    EXPECT_EQ(a.left_wheel_diameter, b.left_wheel_diameter);
    EXPECT_EQ(a.wheel_base, b.wheel_base);
    EXPECT_EQ(a.codo_right, b.codo_right);
    EXPECT_EQ(a.codo_left, b.codo_left);
    expect_same_curve(a.ir_curve, b.ir_curve);
    EXPECT_EQ(a.ir_sensor_parameters, b.ir_sensor_parameters);
    EXPECT_EQ(a.power_per_meter_per_second, b.power_per_meter_per_second);
    EXPECT_EQ(a.right_motor_port, b.right_motor_port);
    EXPECT_EQ(a.left_motor_port, b.left_motor_port);
    EXPECT_EQ(a.front_ir_port, b.front_ir_port);
    EXPECT_EQ(a.rear_ir_port, b.rear_ir_port);
    EXPECT_EQ(a.reversed_motors, b.reversed_motors);
    EXPECT_EQ(a.relay_program, b.relay_program);
}

// Every field away from its default (and Codo overridden).
RobotProfile unusual_profile() {
    RobotProfile p;
    p.name = "Robô \"B\" \\ lab 2\ttab";
    p.bluetooth_address = "00:16:53:0a:1B:2C";
    p.right_wheel_diameter = 0.0561;
    p.left_wheel_diameter = 0.05587;
    p.wheel_base = 0.1234567890123;
    p.codo_right = 2044.25;
    p.codo_left = 1.0 / 3.0 * 6000.0;
    p.ir_curve.a = 0.001;
    p.ir_curve.c_m = 29140.5;
    p.ir_curve.c_r = -7.25;
    p.ir_curve.b = 9.5;
    p.ir_curve.min_range = 0.05;
    p.ir_curve.max_range = 0.35;
    p.ir_curve.peak_distance = 0.045;
    p.ir_curve.contact_adc = 180.0;
    p.ir_curve.adc_max = 4095;
    p.ir_sensor_parameters[legofeup::kRearSensor] = legofeup::IrCurveParameters{
        0.001, 29500.25, -7.125, 9.75};  // the front sensor keeps the shared curve
    p.power_per_meter_per_second = 212.125;
    p.right_motor_port = 0;
    p.left_motor_port = 2;
    p.front_ir_port = 3;
    p.rear_ir_port = 2;
    p.reversed_motors = true;
    p.relay_program = "relay_v2.rxe";
    return p;
}

TEST(RobotProfile, DefaultsAreTheNominalRobotOfTheLoopAndTheNxtLink) {
    const RobotProfile profile;
    const LoopConfig loop;
    EXPECT_DOUBLE_EQ(profile.codo_right, codo(0.0432));
    EXPECT_DOUBLE_EQ(profile.codo_left, codo(0.0432));
    EXPECT_EQ(profile.codo_right, loop.odometry.codo_right);
    EXPECT_EQ(profile.codo_left, loop.odometry.codo_left);
    EXPECT_EQ(profile.wheel_base, loop.odometry.wheel_base);
    expect_same_curve(profile.ir_curve, loop.ir_curve);
    const legofeup::comms::nxt::NxtWiring wiring;
    EXPECT_EQ(profile.right_motor_port, wiring.right_motor);
    EXPECT_EQ(profile.left_motor_port, wiring.left_motor);
    EXPECT_EQ(profile.front_ir_port, wiring.front_ir);
    EXPECT_EQ(profile.rear_ir_port, wiring.rear_ir);
    EXPECT_EQ(profile.reversed_motors, wiring.reversed_motors);
    EXPECT_EQ(profile.power_per_meter_per_second, wiring.power_per_meter_per_second);
}

TEST(RobotProfile, TheDefaultFileIsTheNominalRobot) {
    const RobotProfile file =
        load_robot_profile(std::string(LEGOFEUP_SOURCE_DIR) + "/resources/robots/nxt-default.toml");
    RobotProfile expected;
    expected.name = "NXT 2.0, nominal";
    expect_same_profile(file, expected);
}

using RobotProfileFile = legofeup::testing::ScratchDirectory;

TEST_F(RobotProfileFile, ReadsBackWhatItWrote) {
    const std::string path = (dir_ / "robot.toml").string();
    for (const RobotProfile& profile : {RobotProfile{}, unusual_profile()}) {
        save_robot_profile(path, profile);
        expect_same_profile(load_robot_profile(path), profile);
    }
    // Every key is written with its explanation.
    const std::string text = legofeup::testing::read_text(path);
    for (const char* line :
         {"wheel_base = 0.1234567890123  # b, effective distance", "codo_right = 2044.25  # Codo1",
          "reversed_motors = true  # true if", "[ir_curve]", "adc_max = 4095  # full scale",
          "name = \"Robô \\\"B\\\" \\\\ lab 2\\u0009tab\""}) {
        EXPECT_NE(text.find(line), std::string::npos) << line << "\nin\n" << text;
    }
}

TEST_F(RobotProfileFile, DerivesCodoFromTheDiametersUnlessTheFileSetsIt) {
    const RobotProfile derived = load_robot_profile(
        write("derived.toml", "right_wheel_diameter = 0.056\nleft_wheel_diameter = 0.0555\n"));
    EXPECT_DOUBLE_EQ(derived.codo_right, codo(0.056));
    EXPECT_DOUBLE_EQ(derived.codo_left, codo(0.0555));

    const RobotProfile overridden = load_robot_profile(
        write("overridden.toml", "right_wheel_diameter = 0.056\ncodo_right = 2100.5\n"));
    EXPECT_EQ(overridden.codo_right, 2100.5);
    EXPECT_DOUBLE_EQ(overridden.codo_left, codo(0.0432));
    // What the odometry stands for: the override's diameter, the stored one where derived.
    const auto used = legofeup::lessons::odometry_wheel_diameters(overridden);
    EXPECT_DOUBLE_EQ(used.right, 360.0 / (std::numbers::pi * 2100.5));
    EXPECT_EQ(used.left, 0.0432);

    // Saved, a derived Codo is only shown (commented out); an override is a setting.
    save_robot_profile((dir_ / "saved.toml").string(), overridden);
    const std::string text = legofeup::testing::read_text(dir_ / "saved.toml");
    EXPECT_NE(text.find("\ncodo_right = 2100.5  #"), std::string::npos) << text;
    EXPECT_NE(text.find("\n# codo_left = "), std::string::npos) << text;

    RobotProfile changed = overridden;
    changed.right_wheel_diameter = 0.05;
    legofeup::lessons::derive_codo(changed);
    EXPECT_DOUBLE_EQ(changed.codo_right, codo(0.05));
    EXPECT_DOUBLE_EQ(changed.codo_left, codo(0.0432));
}

TEST_F(RobotProfileFile, ReadsEachSensorsOwnCurveAndOldProfilesAsOneCurve) {
    std::string path = write("sensors.toml",
                             "[ir_curve]\nc_m = 2900.0\nrear_c_m = 2990.5\n"
                             "rear_b = 0.75\n");
    const RobotProfile profile = load_robot_profile(path);
    EXPECT_FALSE(profile.ir_sensor_parameters[legofeup::kFrontSensor].has_value());
    // The parameters the file leaves out are the shared curve's.
    const legofeup::IrCurveParameters rear{0.01, 2990.5, 5.0, 0.75};
    EXPECT_EQ(profile.ir_sensor_parameters[legofeup::kRearSensor], rear);
    LoopConfig loop;
    apply_robot_profile(profile, loop);
    EXPECT_EQ(legofeup::ir_sensor_curve(loop, legofeup::kFrontSensor).c_m, 2900.0);
    EXPECT_EQ(legofeup::ir_sensor_curve(loop, legofeup::kRearSensor).c_m, 2990.5);
    EXPECT_EQ(legofeup::ir_sensor_curve(loop, legofeup::kRearSensor).max_range, 0.30);

    // A profile of one curve (every profile before there were two) reads both with it,
    // and applying it removes a sensor's own curve from the loop.
    path = write("sensors.toml", "[ir_curve]\nc_m = 2900.0\n");
    apply_robot_profile(load_robot_profile(path), loop);
    EXPECT_EQ(legofeup::ir_sensor_curve(loop, legofeup::kRearSensor).c_m, 2900.0);

    path = write("sensors.toml",
                 "[ir_curve]\nfront_c_m = -5\nrear_b = \"x\"\n"
                 "rear_cm = 1\n");
    EXPECT_EQ(input_error_of([&] { load_robot_profile(path); }),
              path + ":3: ir_curve.rear_b = \"x\": must be a number\n" + path
                  + ":4: ir_curve.rear_cm: unknown setting (did you mean 'ir_curve.rear_c_m'?)");
    path = write("sensors.toml", "[ir_curve]\nfront_c_m = -5\n");
    // Named as validate() names the sensor's curve, at the line that set it.
    EXPECT_EQ(input_error_of([&] { load_robot_profile(path); })
                  .rfind(path
                             + ":2: ir_curve.front.c_m = -5: must be greater than 0 and at "
                               "most 1e+07\n",
                         0),
              0u);
}

TEST_F(RobotProfileFile, RefusesEveryBadSettingWithPathLineFieldValueAndReason) {
    struct Case {
        const char* text;
        const char* message;  // after "<path>:"
    };
    const Case cases[] = {
        {"wheel_base = -1", "1: wheel_base = -1: must be between 0.02 and 2"},
        {"wheel_bse = 0.1", "1: wheel_bse: unknown setting (did you mean 'wheel_base'?)"},
        {"colour = \"red\"", "1: colour: unknown setting"},
        {"right_wheel_diameter = 0.001", "1: right_wheel_diameter = 0.001: must be between"},
        {"left_wheel_diameter = \"big\"", "1: left_wheel_diameter = \"big\": must be a number"},
        {"codo_right = 0", "1: codo_right = 0: must be greater than 0 and at most 1e+06"},
        {"codo_left = nan", "1: codo_left = nan: must be greater than 0"},
        {"power_per_meter_per_second = -5",
         "1: power_per_meter_per_second = -5: must be greater than 0"},
        {"right_motor_port = 3", "1: right_motor_port = 3: must be between 0 and 2"},
        {"right_motor_port = 1.5", "1: right_motor_port = 1.5: must be a whole number"},
        {"\nleft_motor_port = 2",
         "2: left_motor_port = 2: the right motor already uses this output port"},
        {"front_ir_port = 4", "1: front_ir_port = 4: must be between 0 and 3"},
        {"rear_ir_port = 0",
         "1: rear_ir_port = 0: the front IR sensor already uses this input port"},
        {"reversed_motors = 1", "1: reversed_motors = 1: must be true or false"},
        {"name = 5", "1: name = 5: must be a quoted text"},
        {"bluetooth_address = \"00:16:53:0A:1B\"",
         "1: bluetooth_address = \"00:16:53:0A:1B\": must be \"\" or six hex pairs"},
        {"bluetooth_address = \"00-16-53-0A-1B-2C\"", "1: bluetooth_address = "},
        {"relay_program = \"legofeup\"", "1: relay_program = \"legofeup\": must be \"\" or an NXT"},
        {"relay_program = \"a_name_far_too_long.rxe\"", "1: relay_program = "},
        {"[ir_curve]\nc_m = -1", "2: ir_curve.c_m = -1: must be greater than 0"},
        {"[ir_curve]\nadc_max = 1023.5", "2: ir_curve.adc_max = 1023.5: must be a whole number"},
        {"[ir_curve]\nmax_range = 0.01",
         "2: ir_curve.max_range = 0.01: must be greater than ir_curve.min_range"},
        {"[ir_curve]\nslope = 1", "2: ir_curve.slope: unknown setting"},
        {"[motors]\nright = 1", "1: [motors]: unknown section (the only section is [ir_curve])"},
        {"wheel_base = ", "1: "},  // TOML syntax
    };
    for (const Case& c : cases) {
        const std::string path = write("bad.toml", c.text);
        const std::string message = input_error_of([&] { load_robot_profile(path); });
        EXPECT_EQ(message.rfind(path + ":" + c.message, 0), 0u) << "for:\n"
                                                                << c.text << "\ngot:\n"
                                                                << message;
    }
}

TEST_F(RobotProfileFile, ListsEveryProblemOfAFileAtOnce) {
    const std::string path = write("bad.toml",
                                   "name = \"x\"\n"
                                   "wheel_base = \"wide\"\n"
                                   "speed = 3\n"
                                   "[ir_curve]\n"
                                   "c_m = true\n");
    EXPECT_EQ(input_error_of([&] { load_robot_profile(path); }),
              path + ":2: wheel_base = \"wide\": must be a number\n" + path
                  + ":3: speed: unknown setting\n" + path
                  + ":5: ir_curve.c_m = true: must be a number");
    const std::string missing = (dir_ / "none.toml").string();
    EXPECT_EQ(input_error_of([&] { load_robot_profile(missing); }),
              missing + ": cannot open the robot profile file");
}

TEST_F(RobotProfileFile, SavesAtomicallyAndNeverWritesAnInvalidProfile) {
    const std::string path = (dir_ / "robot.toml").string();
    save_robot_profile(path, RobotProfile{});
    RobotProfile second = unusual_profile();
    save_robot_profile(path, second);  // replaces the first
    expect_same_profile(load_robot_profile(path), second);
    EXPECT_FALSE(fs::exists(path + ".partial"));

    RobotProfile invalid = second;
    invalid.wheel_base = 0.0;
    invalid.front_ir_port = invalid.rear_ir_port;
    EXPECT_EQ(input_error_of([&] { save_robot_profile(path, invalid); }),
              path + ": wheel_base = 0: must be between 0.02 and 2\n" + path
                  + ": rear_ir_port = 2: the front IR sensor already uses this input port");
    expect_same_profile(load_robot_profile(path), second);  // untouched
    EXPECT_FALSE(fs::exists(path + ".partial"));

    const std::string nowhere = (dir_ / "no-such-directory" / "robot.toml").string();
    try {
        save_robot_profile(nowhere, second);
        FAIL() << "no error";
    } catch (const legofeup::fileio::WriteError& error) {  // the one atomic writer's error
        EXPECT_EQ(error.step(), "creating " + nowhere + ".partial");
        EXPECT_EQ(error.reason(), std::errc::no_such_file_or_directory);
    }
    EXPECT_FALSE(fs::exists(dir_ / "no-such-directory"));
}

TEST(RobotProfile, ApplyChangesTheOdometryAndTheIrCurveOnly) {
    LoopConfig original;
    // Settings a profile must not touch, away from their defaults.
    original.ir_mount.lateral_offset = 0.07;
    original.filter.q11 = 3e-6;
    original.filter.r22 = 2e-3;
    original.initial.pose = {0.5, -0.25, 1.0};
    original.motion.v_ref = 0.15;
    original.gains.heading_gain = 3.5;
    original.association.max_distance_error = 0.2;
    original.max_wheel_speed = 0.3;
    original.max_wheel_travel_per_step = 0.1;
    const RobotProfile profile = unusual_profile();

    LoopConfig applied = original;
    apply_robot_profile(profile, applied);
    EXPECT_EQ(applied.odometry.codo_right, profile.codo_right);
    EXPECT_EQ(applied.odometry.codo_left, profile.codo_left);
    EXPECT_EQ(applied.odometry.wheel_base, profile.wheel_base);
    expect_same_curve(applied.ir_curve, profile.ir_curve);

    EXPECT_EQ(applied.ir_mount.front_longitudinal, original.ir_mount.front_longitudinal);
    EXPECT_EQ(applied.ir_mount.rear_longitudinal, original.ir_mount.rear_longitudinal);
    EXPECT_EQ(applied.ir_mount.lateral_offset, original.ir_mount.lateral_offset);
    EXPECT_EQ(applied.walls.size(), original.walls.size());
    EXPECT_EQ(applied.filter.q11, original.filter.q11);
    EXPECT_EQ(applied.filter.q22, original.filter.q22);
    EXPECT_EQ(applied.filter.r11, original.filter.r11);
    EXPECT_EQ(applied.filter.r22, original.filter.r22);
    EXPECT_EQ(applied.filter.wall_updates, original.filter.wall_updates);
    EXPECT_EQ(applied.initial.pose, original.initial.pose);
    EXPECT_EQ(applied.initial.var_theta, original.initial.var_theta);
    EXPECT_EQ(applied.motion.v_ref, original.motion.v_ref);
    EXPECT_EQ(applied.motion.w_ref, original.motion.w_ref);
    EXPECT_EQ(applied.gains.heading_gain, original.gains.heading_gain);
    EXPECT_EQ(applied.association.max_distance_error, original.association.max_distance_error);
    EXPECT_EQ(applied.max_wheel_speed, original.max_wheel_speed);
    EXPECT_EQ(applied.max_wheel_travel_per_step, original.max_wheel_travel_per_step);
    EXPECT_TRUE(legofeup::validate(applied).empty());
}

}  // namespace
