// legofeup-cli calibrate-ir and calibrate-odometry as a user runs them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>

#include "support/program_test.hpp"

namespace {

namespace fs = std::filesystem;
using legofeup::testing::read_file;
using legofeup::testing::Result;

class CalibrateCli : public legofeup::testing::ProgramTest {
  protected:
    Result run(const std::string& arguments) const { return run_program(LEGOFEUP_CLI, arguments); }

    std::string write(const std::string& name, const std::string& text) const {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }
};

// The number after `key = ` in a TOML text (NaN when the key is absent or commented out).
double toml_value(const std::string& text, const std::string& key) {
    const std::regex line("(^|\n)" + key + " = ([-+0-9.eE]+)");
    std::smatch match;
    return std::regex_search(text, match, line) ? std::stod(match[2]) : std::nan("");
}

// Measurements from a curve with C_M = 2700, C_R = 2, b = 0.8 (a = 0.01 m), written out.
std::string measurements() {
    std::string csv = "# front sensor, white card\nadc,distance_m\n";
    for (int adc = 90; adc <= 590; adc += 50) {
        const double distance = 0.01 * (2700.0 / (adc + 2.0) - 0.8);
        char row[64];
        std::snprintf(row, sizeof row, "%d,%.12f\n", adc, distance);
        csv += row;
    }
    return csv;
}

TEST_F(CalibrateCli, CalibrateIrFitsPrintsPlotsAndCreatesTheProfile) {
    const std::string points = write("ir.csv", measurements());
    const fs::path profile = dir_ / "robot.toml";
    const fs::path plots = dir_ / "plots";
    const Result result = run("calibrate-ir --points " + points + " --profile " + profile.string()
                              + " --plot " + plots.string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    EXPECT_NE(result.out.find("IR curve fitted to 11 measurements"), std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("C_M = 2700   C_R = 2   b = 0.8"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("residuals: RMS 0.00 mm"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("Profile written: " + profile.string()), std::string::npos);

    const std::string png = read_file(plots / "ir_calibration.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    EXPECT_NE(read_file(plots / "ir_calibration.svg").find("<svg"), std::string::npos);

    const std::string written = read_file(profile);
    EXPECT_NEAR(toml_value(written, "c_m"), 2700.0, 1e-6);
    EXPECT_NEAR(toml_value(written, "c_r"), 2.0, 1e-8);
    EXPECT_NEAR(toml_value(written, "b"), 0.8, 1e-9);
    EXPECT_EQ(toml_value(written, "wheel_base"), 0.12);  // the rest stays nominal
    EXPECT_FALSE(fs::exists(profile.string() + ".partial"));
}

TEST_F(CalibrateCli, CalibrateIrUpdatesAnExistingProfileKeepingItsOtherSettings) {
    const std::string profile = write("robot.toml",
                                      "name = \"lab robot 3\"\n"
                                      "wheel_base = 0.118\n"
                                      "[ir_curve]\n"
                                      "max_range = 0.25\n");
    const std::string points = write("ir.csv", measurements());
    ASSERT_EQ(run("calibrate-ir --points " + points + " --profile " + profile).exit_code, 0);
    const std::string written = read_file(profile);
    EXPECT_NE(written.find("name = \"lab robot 3\""), std::string::npos) << written;
    EXPECT_EQ(toml_value(written, "wheel_base"), 0.118);
    EXPECT_EQ(toml_value(written, "max_range"), 0.25);
    EXPECT_NEAR(toml_value(written, "c_m"), 2700.0, 1e-6);
}

TEST_F(CalibrateCli, CalibrateIrRefusesABadCsvWithPathAndLine) {
    const std::string points = write("bad.csv", "adc,distance_m\n300,0.1\n310;0.09\n250,-1\n");
    const fs::path profile = dir_ / "robot.toml";
    const Result result = run("calibrate-ir --points " + points + " --profile " + profile.string());
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("error: " + points + ":3: row = 310;0.09: expected 2 values"),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("error: " + points
                              + ":4: distance_m = -1: must be a positive number of metres"),
              std::string::npos)
        << result.err;
    EXPECT_FALSE(fs::exists(profile));  // nothing written
}

TEST_F(CalibrateCli, CalibrateIrNamesTheFileOfPointsTheFitRefuses) {
    const std::string points = write("few.csv", "adc,distance_m\n300,0.1\n1500,0.05\n");
    const Result result = run("calibrate-ir --points " + points);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.err.find("error: " + points + ": point 2 adc = 1500: must be an A/D value"),
              std::string::npos)
        << result.err;
    EXPECT_NE(result.err.find("error: " + points + ": points = 2: the fit needs at least 4"),
              std::string::npos)
        << result.err;
}

TEST_F(CalibrateCli, CalibrateOdometryPrintsTheCorrectionsAndWritesThemToTheProfile) {
    const fs::path profile = dir_ / "robot.toml";
    // The hand-worked example of tests/lessons/test_umbmark.cpp.
    const Result result =
        run("calibrate-odometry --side 1.0 --cw \"-0.10,-0.12;-0.12,-0.10\" --ccw "
            "\"-0.03,0.04;-0.05,0.02\" --profile "
            + profile.string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
    for (const char* line :
         {"E_d = D_R/D_L = 1.002253   E_b = b_actual/b = 1.023623",
          "wheel base:  0.122835 m (was 0.120000 m)",
          "right wheel: 43.2486 mm, Codo 2649.60 counts/m",
          "left wheel:  43.1514 mm, Codo 2655.57 counts/m", "Profile written: "}) {
        EXPECT_NE(result.out.find(line), std::string::npos) << line << "\nin\n" << result.out;
    }
    const std::string written = read_file(profile);
    EXPECT_NEAR(toml_value(written, "wheel_base"), 0.1228347, 1e-7);
    const double right = toml_value(written, "right_wheel_diameter");
    const double left = toml_value(written, "left_wheel_diameter");
    EXPECT_NEAR(right, 0.0432486, 1e-7);
    EXPECT_NEAR(left, 0.0431514, 1e-7);
    EXPECT_NEAR(right / left, 1.0022525, 1e-7);
    // Codo follows from the diameters: shown, not set.
    EXPECT_TRUE(std::isnan(toml_value(written, "codo_right"))) << written;
    EXPECT_NE(written.find("# codo_right = 2649.60"), std::string::npos) << written;

    // A second round starts from the corrected profile: with no error left, nothing changes.
    ASSERT_EQ(run("calibrate-odometry --side 1.0 --cw 0,0 --ccw 0,0 --profile " + profile.string())
                  .exit_code,
              0);
    const std::string again = read_file(profile);
    EXPECT_EQ(toml_value(again, "right_wheel_diameter"), right);
    EXPECT_EQ(toml_value(again, "left_wheel_diameter"), left);
}

TEST_F(CalibrateCli, CalibrateOdometryRefusesBadErrorListsAndABadProfile) {
    const Result bad_list = run("calibrate-odometry --side 1 --cw \"0.1;0.2,0.3\" --ccw 0,0");
    EXPECT_EQ(bad_list.exit_code, 1);
    EXPECT_NE(bad_list.err.find("error: --cw run 1 = 0.1: must be the return error as x,y"),
              std::string::npos)
        << bad_list.err;

    const std::string profile = write("robot.toml", "wheel_base = 0.12\nwheels = 2\n");
    const Result bad_profile =
        run("calibrate-odometry --side 1 --cw 0,0 --ccw 0,0 --profile " + profile);
    EXPECT_EQ(bad_profile.exit_code, 1);
    EXPECT_NE(bad_profile.err.find("error: " + profile + ":2: wheels: unknown setting"),
              std::string::npos)
        << bad_profile.err;
    EXPECT_EQ(read_file(profile), "wheel_base = 0.12\nwheels = 2\n");  // untouched
}

}  // namespace

namespace {

// The data rows (not comments, not the header) of a points file.
int data_rows(const std::string& csv) {
    int rows = 0;
    std::size_t start = 0;
    while (start < csv.size()) {
        const std::size_t end = csv.find('\n', start);
        const std::string line = csv.substr(start, end - start);
        rows += !line.empty() && line[0] != '#' && !line.starts_with("adc,distance_m") ? 1 : 0;
        start = end == std::string::npos ? csv.size() : end + 1;
    }
    return rows;
}

}  // namespace

TEST_F(CalibrateCli, MeasureIrWritesPointsThatCalibrateIrFits) {
    const std::string model = write("realistic.toml", "[simulator]\nir_model = \"realistic\"\n");
    const fs::path points = dir_ / "ir.csv";
    const Result measured = run("measure-ir -e f -c " + model + " -s 2005 -o " + points.string());
    ASSERT_EQ(measured.exit_code, 0) << measured.err;
    EXPECT_NE(measured.out.find("34 points written to " + points.string()), std::string::npos)
        << measured.out;
    const std::string csv = read_file(points);
    EXPECT_NE(csv.find("seed 2005 (IR model realistic)"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\nadc,distance_m,sensor\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",0.04,front\n"), std::string::npos) << csv;
    EXPECT_NE(csv.find(",0.30,rear\n"), std::string::npos) << csv;
    EXPECT_EQ(data_rows(csv), 34);

    const fs::path profile = dir_ / "robot.toml";
    const Result fitted =
        run("calibrate-ir --points " + points.string() + " --profile " + profile.string());
    ASSERT_EQ(fitted.exit_code, 0) << fitted.err;
    EXPECT_NE(fitted.out.find("IR curve fitted to 34 measurements"), std::string::npos);
    // This robot's sensors are not the nominal curve (C_M = 2914, C_R = 5), nor each other.
    const std::string written = read_file(profile);
    EXPECT_GT(std::abs(toml_value(written, "c_r") - 5.0), 1.0);
    EXPECT_NE(fitted.out.find("17 measurements from " + points.string() + " (front sensor's"),
              std::string::npos)
        << fitted.out;
    EXPECT_GT(std::abs(toml_value(written, "front_c_m") - toml_value(written, "rear_c_m")), 50.0);

    // The same points without the sensor column: one curve, and no sensor's own any more.
    std::string plain = csv;
    for (const std::string column : {",sensor\n", ",front\n", ",rear\n"}) {
        for (auto at = plain.find(column); at != std::string::npos; at = plain.find(column)) {
            plain.replace(at, column.size(), "\n");
        }
    }
    const std::string one = write("one.csv", plain);
    const Result refitted = run("calibrate-ir --points " + one + " --profile " + profile.string());
    ASSERT_EQ(refitted.exit_code, 0) << refitted.err;
    EXPECT_EQ(read_file(profile).find("front_c_m"), std::string::npos);
    EXPECT_NEAR(toml_value(read_file(profile), "c_m"), toml_value(written, "c_m"), 1e-3);
}

TEST_F(CalibrateCli, MeasureIrRefusesABadConfigurationAndReadings) {
    const std::string bad = write("bad.toml", "[simulator]\nir_model = \"perfect\"\n");
    const Result refused = run("measure-ir -c " + bad + " -o " + (dir_ / "ir.csv").string());
    EXPECT_EQ(refused.exit_code, 1);
    EXPECT_NE(refused.err.find("ir_model"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(dir_ / "ir.csv"));
    EXPECT_NE(run("measure-ir --readings 0 -o " + (dir_ / "ir.csv").string()).exit_code, 0);
}
