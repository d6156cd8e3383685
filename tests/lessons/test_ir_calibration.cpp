// The IR curve fit (eq. 2 by Levenberg–Marquardt) and the measurements file.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "calibration_test_support.hpp"
#include "legofeup/lessons/calibration/ir_calibration.hpp"

namespace {

using legofeup::SharpIrCurve;
using legofeup::lessons::fit_ir_curve;
using legofeup::lessons::IrCalibrationPoint;
using legofeup::lessons::IrFit;
using legofeup::lessons::read_ir_points_csv;
using legofeup::testing::input_error_of;

// Eq. 2 written out here, independently of the code under test.
double eq2(double adc, double a, double c_m, double c_r, double b) {
    return a * (c_m / (adc + c_r) - b);
}

SharpIrCurve curve_with(double c_m, double c_r, double b) {
    SharpIrCurve curve;
    curve.c_m = c_m;
    curve.c_r = c_r;
    curve.b = b;
    return curve;
}

// A values spread over the sensor's range (≈ 30 cm … 4 cm for the default curve).
std::vector<double> adc_values(int count) {
    std::vector<double> values;
    for (int i = 0; i < count; ++i) {
        values.push_back(80.0 + 500.0 * i / (count - 1));
    }
    return values;
}

double sum_of_squares(const std::vector<IrCalibrationPoint>& points, double c_m, double c_r,
                      double b) {
    double sum = 0.0;
    for (const IrCalibrationPoint& p : points) {
        const double r = p.distance - eq2(p.adc, 0.01, c_m, c_r, b);
        sum += r * r;
    }
    return sum;
}

TEST(IrCurveJacobian, MatchesCentralDifferences) {
    for (const SharpIrCurve& curve :
         {SharpIrCurve{}, curve_with(2500.0, -3.0, 0.5), curve_with(4000.0, 20.0, 2.0)}) {
        for (double adc : {30.0, 95.0, 300.0, 700.0}) {
            const Eigen::RowVector3d analytic = legofeup::lessons::ir_curve_jacobian(adc, curve);
            const double parameters[] = {curve.c_m, curve.c_r, curve.b};
            for (int j = 0; j < 3; ++j) {
                const double h = 1e-6 * std::max(std::abs(parameters[j]), 1.0);
                double plus[] = {curve.c_m, curve.c_r, curve.b};
                double minus[] = {curve.c_m, curve.c_r, curve.b};
                plus[j] += h;
                minus[j] -= h;
                const double numeric = (eq2(adc, curve.a, plus[0], plus[1], plus[2])
                                        - eq2(adc, curve.a, minus[0], minus[1], minus[2]))
                                       / (2.0 * h);
                EXPECT_NEAR(analytic(j), numeric, 1e-7 * std::max(std::abs(numeric), 1e-3))
                    << "parameter " << j << " at A = " << adc;
            }
        }
    }
}

TEST(IrCurveFit, RecoversExactParametersFromAnyReasonableStart) {
    const double c_m = 2500.0;
    const double c_r = -3.0;
    const double b = 0.5;
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(12)) {
        points.push_back({adc, eq2(adc, 0.01, c_m, c_r, b)});
    }
    for (const SharpIrCurve& start :
         {SharpIrCurve{}, curve_with(1000.0, 40.0, 3.0), curve_with(6000.0, 0.0, -1.0)}) {
        const IrFit fit = fit_ir_curve(points, start);
        EXPECT_TRUE(fit.converged);
        EXPECT_LT(std::abs(fit.curve.c_m - c_m), 1e-6 * std::abs(c_m));
        EXPECT_LT(std::abs(fit.curve.c_r - c_r), 1e-6 * std::abs(c_r));
        EXPECT_LT(std::abs(fit.curve.b - b), 1e-6 * std::abs(b));
        EXPECT_LT(fit.rms_residual, 1e-9);
        EXPECT_GT(fit.iterations, 0);
        // Everything but C_M, C_R and b comes from the start.
        EXPECT_EQ(fit.curve.a, start.a);
        EXPECT_EQ(fit.curve.min_range, start.min_range);
        EXPECT_EQ(fit.curve.max_range, start.max_range);
        EXPECT_EQ(fit.curve.peak_distance, start.peak_distance);
        EXPECT_EQ(fit.curve.contact_adc, start.contact_adc);
        EXPECT_EQ(fit.curve.adc_max, start.adc_max);
    }
}

// Two units with their own curves, measured at the same A/D values: each sensor's own fit
// recovers its unit exactly, the one curve of both lies between them, and the profile gets
// both; points that do not say their sensor fit the one curve only and clear any own curve.
TEST(IrCalibration, EachSensorsOwnPointsGiveItsOwnCurveAndTheProfileBoth) {
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(10)) {
        points.push_back({adc, eq2(adc, 0.01, 2700.0, 4.0, 0.8), legofeup::kFrontSensor});
        points.push_back({adc, eq2(adc, 0.01, 3100.0, 7.0, 1.2), legofeup::kRearSensor});
    }
    const legofeup::lessons::IrCalibration calibration =
        legofeup::lessons::fit_ir_calibration(points, SharpIrCurve{}, "bench.csv");
    const auto& front = calibration.own[0];  // [kFrontSensor]
    const auto& rear = calibration.own[1];
    ASSERT_TRUE(front && rear);
    EXPECT_NEAR(front->curve.c_m, 2700.0, 1e-6 * 2700.0);
    EXPECT_NEAR(front->curve.c_r, 4.0, 1e-6 * 4.0);
    EXPECT_NEAR(rear->curve.c_m, 3100.0, 1e-6 * 3100.0);
    EXPECT_NEAR(rear->curve.b, 1.2, 1e-6 * 1.2);
    EXPECT_EQ(front->residuals.size(), 10u);
    // The one curve cannot pass through both units' points: a residual of the spread.
    EXPECT_GT(calibration.both.rms_residual, 1e-3);
    const IrFit both_alone = fit_ir_curve(points, SharpIrCurve{});
    EXPECT_EQ(calibration.both.curve.c_m, both_alone.curve.c_m);

    legofeup::lessons::RobotProfile profile;
    profile.ir_curve.max_range = 0.25;  // the profile's own range stays
    legofeup::lessons::apply_ir_calibration(profile, calibration);
    EXPECT_EQ(profile.ir_curve.c_m, calibration.both.curve.c_m);
    EXPECT_EQ(profile.ir_curve.max_range, 0.25);
    ASSERT_TRUE(profile.ir_sensor_parameters[0]);
    EXPECT_EQ(profile.ir_sensor_parameters[0]->c_m, front->curve.c_m);
    EXPECT_EQ(profile.ir_sensor_parameters[1]->c_r, rear->curve.c_r);

    for (IrCalibrationPoint& point : points) {
        point.sensor.reset();
    }
    const auto unsaid = legofeup::lessons::fit_ir_calibration(points, SharpIrCurve{}, "x.csv");
    EXPECT_FALSE(unsaid.own[0] || unsaid.own[1]);
    legofeup::lessons::apply_ir_calibration(profile, unsaid);
    EXPECT_FALSE(profile.ir_sensor_parameters[0] || profile.ir_sensor_parameters[1]);
}

TEST(IrCalibration, AProblemWithOneSensorsPointsNamesTheSensor) {
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(8)) {
        points.push_back({adc, eq2(adc, 0.01, 2914.0, 5.0, 1.0), legofeup::kFrontSensor});
    }
    points.push_back({400.0, 0.1, legofeup::kRearSensor});  // the rear took one point only
    const std::string message = input_error_of(
        [&] { legofeup::lessons::fit_ir_calibration(points, SharpIrCurve{}, "bench.csv"); });
    EXPECT_NE(message.find("bench.csv (rear sensor's points)"), std::string::npos) << message;
    EXPECT_EQ(message.find("front sensor's"), std::string::npos) << message;
}

TEST(IrCurveFit, ResidualsAreMeasuredMinusFitted) {
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(8)) {
        points.push_back({adc, eq2(adc, 0.01, 2914.0, 5.0, 1.0)});
    }
    points[3].distance += 0.004;  // one reading off by 4 mm
    const IrFit fit = fit_ir_curve(points, SharpIrCurve{});
    ASSERT_EQ(fit.residuals.size(), points.size());
    double sum = 0.0;
    double largest = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double expected =
            points[i].distance
            - eq2(points[i].adc, 0.01, fit.curve.c_m, fit.curve.c_r, fit.curve.b);
        EXPECT_NEAR(fit.residuals[i], expected, 1e-15) << i;
        sum += expected * expected;
        largest = std::max(largest, std::abs(expected));
    }
    EXPECT_NEAR(fit.rms_residual, std::sqrt(sum / 8.0), 1e-15);
    EXPECT_NEAR(fit.max_abs_residual, largest, 1e-15);
    EXPECT_GT(fit.residuals[3], 0.001);  // the outlier is above the curve
}

TEST(IrCurveFit, NoisyDataLeaveResidualsOfTheNoiseSize) {
    // Least squares with n points and 3 parameters: E[Σr²] = σ²(n − 3).
    const int n = 25;
    const double sigma = 0.002;
    const double c_m = 2914.0;
    const double c_r = 5.0;
    const double b = 1.0;
    double mean_square_sum = 0.0;
    const int seeds = 100;
    for (int seed = 1; seed <= seeds; ++seed) {
        std::mt19937_64 random(static_cast<std::uint64_t>(seed));
        std::normal_distribution<double> noise(0.0, sigma);
        std::vector<IrCalibrationPoint> points;
        for (double adc : adc_values(n)) {
            points.push_back({adc, eq2(adc, 0.01, c_m, c_r, b) + noise(random)});
        }
        const IrFit fit = fit_ir_curve(points, SharpIrCurve{});
        ASSERT_TRUE(fit.converged) << "seed " << seed;
        const double fitted = sum_of_squares(points, fit.curve.c_m, fit.curve.c_r, fit.curve.b);
        // A least-squares minimum: no worse than the true parameters, nor than any nearby point.
        EXPECT_LE(fitted, sum_of_squares(points, c_m, c_r, b)) << "seed " << seed;
        for (int j = 0; j < 3; ++j) {
            for (double sign : {-1.0, 1.0}) {
                double p[] = {fit.curve.c_m, fit.curve.c_r, fit.curve.b};
                p[j] *= 1.0 + sign * 1e-4;
                EXPECT_GE(sum_of_squares(points, p[0], p[1], p[2]), fitted);
            }
        }
        EXPECT_NEAR(fit.rms_residual * fit.rms_residual * n, fitted, 1e-12);
        EXPECT_GT(fit.rms_residual, 0.5 * sigma) << "seed " << seed;
        EXPECT_LT(fit.rms_residual, 1.5 * sigma) << "seed " << seed;
        mean_square_sum += fit.rms_residual * fit.rms_residual;
    }
    const double expected = sigma * sigma * (n - 3) / n;
    EXPECT_NEAR(mean_square_sum / seeds, expected, 0.1 * expected);
}

TEST(IrCurveFit, RefusesTooFewPointsWithReasons) {
    const std::vector<IrCalibrationPoint> three = {{100.0, 0.25}, {200.0, 0.13}, {400.0, 0.06}};
    EXPECT_EQ(input_error_of([&] { fit_ir_curve(three, SharpIrCurve{}); }),
              "points = 3: the fit needs at least 4 measurements at different distances");
}

TEST(IrCurveFit, RefusesBadPointsNamingEach) {
    const double nan = std::nan("");
    const std::vector<IrCalibrationPoint> points = {{100.0, 0.25}, {1100.0, 0.13}, {-2.0, 0.1},
                                                    {400.0, 0.0},  {300.0, -0.1},  {nan, nan}};
    const std::string message = input_error_of([&] { fit_ir_curve(points, SharpIrCurve{}); });
    for (const char* expected :
         {"point 2 adc = 1100: must be an A/D value between 0 and 1023",
          "point 3 adc = -2: must be an A/D value between 0 and 1023",
          "point 4 distance_m = 0: must be a positive number of metres",
          "point 5 distance_m = -0.1: must be a positive number of metres",
          "point 6 adc = nan: must be", "point 6 distance_m = nan: must be"}) {
        EXPECT_NE(message.find(expected), std::string::npos) << expected << "\nin\n" << message;
    }
    // A smaller converter: 1000 is out of range.
    SharpIrCurve eight_bit;
    eight_bit.adc_max = 255;
    const std::vector<IrCalibrationPoint> high = {
        {10.0, 0.3}, {100.0, 0.2}, {200.0, 0.1}, {1000.0, 0.05}};
    EXPECT_EQ(input_error_of([&] { fit_ir_curve(high, eight_bit); }),
              "point 4 adc = 1000: must be an A/D value between 0 and 255");
}

TEST(IrCurveFit, RefusesIdenticalOrTooFewDistinctAdcValues) {
    const std::vector<IrCalibrationPoint> same = {
        {300.0, 0.1}, {300.0, 0.11}, {300.0, 0.09}, {300.0, 0.1}};
    EXPECT_EQ(input_error_of([&] { fit_ir_curve(same, SharpIrCurve{}); }),
              "points: every measurement has the same A/D value (A = 300): measure at several "
              "distances across the range");
    const std::vector<IrCalibrationPoint> two = {
        {300.0, 0.1}, {300.0, 0.11}, {150.0, 0.2}, {150.0, 0.19}};
    EXPECT_NE(input_error_of([&] {
                  fit_ir_curve(two, SharpIrCurve{});
              }).find("only 2 different A/D values"),
              std::string::npos);
}

TEST(IrCurveFit, RefusesAStartWithThePoleInsideTheData) {
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(6)) {
        points.push_back({adc, eq2(adc, 0.01, 2914.0, 5.0, 1.0)});
    }
    // A + C_R = 80 − 100 < 0 at the first point: eq. 2 has no finite distance there.
    const std::string message =
        input_error_of([&] { fit_ir_curve(points, curve_with(2914.0, -100.0, 1.0)); });
    EXPECT_EQ(message,
              "start curve C_R = -100: A + C_R must be positive at every point (eq. 2 has its "
              "pole at A = −C_R), but the smallest A is 80");
}

TEST(IrCurveFit, NeverStepsOntoThePole) {
    // Data from a curve whose pole lies just below the smallest A: the iteration must reach
    // it from a start with C_R far above without ever making A + C_R ≤ 0.
    std::vector<IrCalibrationPoint> points;
    for (double adc : adc_values(10)) {
        points.push_back({adc, eq2(adc, 0.01, 1500.0, -70.0, 0.2)});
    }
    const IrFit fit = fit_ir_curve(points, curve_with(2914.0, 200.0, 1.0));
    EXPECT_TRUE(fit.converged);
    EXPECT_GT(80.0 + fit.curve.c_r, 0.0);
    EXPECT_NEAR(fit.curve.c_r, -70.0, 1e-5);
    EXPECT_NEAR(fit.curve.c_m, 1500.0, 1.5e-3);
}

using IrPointsCsv = legofeup::testing::ScratchDirectory;

TEST_F(IrPointsCsv, ReadsMeasurementsSkippingCommentsAndBlankLines) {
    const std::string path = write("ir.csv",
                                   "# GP2D120, front sensor, white wall\n"
                                   "adc,distance_m\r\n"
                                   "\n"
                                   "590, 0.04   # closest trusted\r\n"
                                   "  310 ,0.08\n"
                                   "89.5,3e-1\n");
    const std::vector<IrCalibrationPoint> points = read_ir_points_csv(path);
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0].adc, 590.0);
    EXPECT_EQ(points[0].distance, 0.04);
    EXPECT_EQ(points[1].adc, 310.0);
    EXPECT_EQ(points[1].distance, 0.08);
    EXPECT_EQ(points[2].adc, 89.5);
    EXPECT_EQ(points[2].distance, 0.3);
}

TEST_F(IrPointsCsv, RefusesBadLinesWithPathLineFieldAndValue) {
    const std::string path = write("bad.csv",
                                   "adc,distance_m\n"
                                   "590,0.04\n"
                                   "abc,0.05\n"
                                   "300,-0.1\n"
                                   "200,0.1,7\n"
                                   "150,nan\n"
                                   "-4,12cm\n");
    const std::string message = input_error_of([&] { read_ir_points_csv(path); });
    EXPECT_EQ(message, path + ":3: adc = abc: must be an A/D value (a number from 0 up)\n" + path
                           + ":4: distance_m = -0.1: must be a positive number of metres\n" + path
                           + ":5: row = 200,0.1,7: expected 2 values (adc,distance_m), found 3\n"
                           + path + ":6: distance_m = nan: must be a positive number of metres\n"
                           + path + ":7: adc = -4: must be an A/D value (a number from 0 up)\n"
                           + path + ":7: distance_m = 12cm: must be a positive number of metres");
}

TEST_F(IrPointsCsv, ReadsWhichSensorTookEachPointAndRefusesAnUnknownSensor) {
    const std::string path = write("sensors.csv",
                                   "adc,distance_m,sensor\n580,0.04,front\n"
                                   "570,0.04,rear\n300,0.1,front\n");
    const std::vector<IrCalibrationPoint> points = read_ir_points_csv(path);
    ASSERT_EQ(points.size(), 3u);
    EXPECT_EQ(points[0].sensor, legofeup::kFrontSensor);
    EXPECT_EQ(points[1].sensor, legofeup::kRearSensor);
    const auto front = legofeup::lessons::points_of(points, legofeup::kFrontSensor);
    ASSERT_EQ(front.size(), 2u);
    EXPECT_EQ(front[1].adc, 300.0);
    EXPECT_EQ(legofeup::lessons::points_of(points, legofeup::kRearSensor).size(), 1u);
    // Without the column no point says its sensor: none is any one sensor's.
    const std::string plain = write("plain.csv", "adc,distance_m\n580,0.04\n");
    EXPECT_FALSE(read_ir_points_csv(plain)[0].sensor.has_value());
    const std::string bad = write("bad.csv",
                                  "adc,distance_m,sensor\n580,0.04,left\n"
                                  "570,0.04\n");
    EXPECT_EQ(input_error_of([&] { read_ir_points_csv(bad); }),
              bad + ":2: sensor = left: must be front or rear\n" + bad
                  + ":3: row = 570,0.04: expected 3 values (adc,distance_m,sensor), found 2");
}

TEST_F(IrPointsCsv, RefusesAMissingHeaderAnEmptyFileAndAMissingFile) {
    const std::string headless = write("headless.csv", "# measured today\n590,0.04\n");
    EXPECT_EQ(input_error_of([&] { read_ir_points_csv(headless); }),
              headless + ":2: header = 590,0.04: the first line must be: adc,distance_m (or "
                             "adc,distance_m,sensor)");
    const std::string empty = write("empty.csv", "# nothing yet\n\n");
    EXPECT_NE(
        input_error_of([&] { read_ir_points_csv(empty); }).find(empty + ": the file is empty"),
        std::string::npos);
    const std::string header_only = write("header.csv", "adc,distance_m\n");
    EXPECT_EQ(input_error_of([&] { read_ir_points_csv(header_only); }),
              header_only + ": no measurements after the header");
    const std::string missing = (dir_ / "missing.csv").string();
    EXPECT_EQ(input_error_of([&] { read_ir_points_csv(missing); }),
              missing + ": cannot open the measurements file");
}

}  // namespace
