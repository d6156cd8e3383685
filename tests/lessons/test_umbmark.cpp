// UMBmark (Borenstein & Feng 1996): a hand-worked example, the first-order error model, and
// the project's simulator driving the square with known E_d and E_b.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "calibration_test_support.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/lessons/calibration/umbmark.hpp"
#include "legofeup/sim/simulator.hpp"

namespace {

using legofeup::OdometryParams;
using legofeup::Pose2;
using legofeup::Vector2;
using legofeup::lessons::umbmark;
using legofeup::lessons::UmbmarkInput;
using legofeup::lessons::UmbmarkResult;
using legofeup::testing::input_error_of;
constexpr double kPi = std::numbers::pi;

UmbmarkInput nominal_input(double side) {
    UmbmarkInput input;
    input.side = side;
    input.wheel_base = 0.12;
    input.right_wheel_diameter = 0.0432;
    input.left_wheel_diameter = 0.0432;
    return input;
}

TEST(Umbmark, HandWorkedExample) {
    // L = 1 m, b = 0.12 m, D = 43.2 mm, two runs each way:
    //   cw:  (−0.10, −0.12), (−0.12, −0.10)  → centre (−0.11, −0.11)
    //   ccw: (−0.03, +0.04), (−0.05, +0.02)  → centre (−0.04, +0.03)
    // r_cw = 0.11·√2 = 0.1555635, r_ccw = √(0.04² + 0.03²) = 0.05, E_max,syst = 0.1555635.
    // α_x = (x_cw + x_ccw)/(−4L) = (−0.11 − 0.04)/(−4) = 0.0375
    // α_y = (y_cw − y_ccw)/(−4L) = (−0.11 − 0.03)/(−4) = 0.035      → α = 0.03625 rad
    // β_x = (x_cw − x_ccw)/(−4L) = (−0.11 + 0.04)/(−4) = 0.0175
    // β_y = (y_cw + y_ccw)/(−4L) = (−0.11 + 0.03)/(−4) = 0.02       → β = 0.01875 rad
    // R = (L/2)/sin(β/2) = 0.5/sin(0.009375) = 0.5/0.00937486267 = 53.334115 m
    // E_d = (R + b/2)/(R − b/2) = 53.394115/53.274115 = 1.0022525
    // E_b = (π/2)/(π/2 − α) = 1.5707963/1.5345463 = 1.0236226
    // b_actual = 0.12 · 1.0236226 = 0.1228347 m
    // c_L = 2/(E_d + 1) = 2/2.0022525 = 0.9988750, c_R = 2/(1/E_d + 1) = 1.0011250
    // D_L = 0.0432 · 0.9988750 = 0.0431514 m, D_R = 0.0432 · 1.0011250 = 0.0432486 m
    // Codo_L = 360/(π · 0.0431514) = 2655.570, Codo_R = 360/(π · 0.0432486) = 2649.602
    UmbmarkInput input = nominal_input(1.0);
    input.clockwise = {{-0.10, -0.12}, {-0.12, -0.10}};
    input.counter_clockwise = {{-0.03, 0.04}, {-0.05, 0.02}};
    const UmbmarkResult r = umbmark(input);
    EXPECT_NEAR(r.centre_cw.x(), -0.11, 1e-15);
    EXPECT_NEAR(r.centre_cw.y(), -0.11, 1e-15);
    EXPECT_NEAR(r.centre_ccw.x(), -0.04, 1e-15);
    EXPECT_NEAR(r.centre_ccw.y(), 0.03, 1e-15);
    EXPECT_NEAR(r.r_cw, 0.1555635, 1e-7);
    EXPECT_NEAR(r.r_ccw, 0.05, 1e-15);
    EXPECT_NEAR(r.e_max_syst, 0.1555635, 1e-7);
    EXPECT_NEAR(r.alpha_from_x, 0.0375, 1e-15);
    EXPECT_NEAR(r.alpha_from_y, 0.035, 1e-15);
    EXPECT_NEAR(r.beta_from_x, 0.0175, 1e-15);
    EXPECT_NEAR(r.beta_from_y, 0.02, 1e-15);
    EXPECT_NEAR(r.alpha, 0.03625, 1e-15);
    EXPECT_NEAR(r.beta, 0.01875, 1e-15);
    EXPECT_NEAR(r.radius, 53.334115, 1e-5);
    EXPECT_NEAR(r.e_d, 1.0022525, 1e-7);
    EXPECT_NEAR(r.e_b, 1.0236226, 1e-7);
    EXPECT_NEAR(r.wheel_base, 0.1228347, 1e-7);
    EXPECT_NEAR(r.c_left, 0.9988750, 1e-7);
    EXPECT_NEAR(r.c_right, 1.0011250, 1e-7);
    EXPECT_NEAR(r.left_wheel_diameter, 0.0431514, 1e-7);
    EXPECT_NEAR(r.right_wheel_diameter, 0.0432486, 1e-7);
    EXPECT_NEAR(r.codo_left, 2655.570, 1e-3);
    EXPECT_NEAR(r.codo_right, 2649.602, 1e-3);
}

TEST(Umbmark, InvertsTheFirstOrderErrorModel) {
    // To first order: x_cw = y_cw = −2L(α + β), x_ccw = −2L(α − β), y_ccw = +2L(α − β).
    const double side = 2.0;
    for (const auto& [alpha, beta] : {std::pair{0.02, 0.0}, std::pair{0.0, 0.01},
                                      std::pair{-0.015, 0.004}, std::pair{0.01, -0.02}}) {
        UmbmarkInput input = nominal_input(side);
        input.clockwise = {{-2 * side * (alpha + beta), -2 * side * (alpha + beta)}};
        input.counter_clockwise = {{-2 * side * (alpha - beta), 2 * side * (alpha - beta)}};
        const UmbmarkResult r = umbmark(input);
        EXPECT_NEAR(r.alpha_from_x, alpha, 1e-15);
        EXPECT_NEAR(r.alpha_from_y, alpha, 1e-15);
        EXPECT_NEAR(r.beta_from_x, beta, 1e-15);
        EXPECT_NEAR(r.beta_from_y, beta, 1e-15);
        // Only β: no wheel-base change; only α: equal wheels.
        EXPECT_EQ(r.e_b == 1.0, alpha == 0.0);
        EXPECT_EQ(r.e_d == 1.0, beta == 0.0);
        // Positive β curves left: the right wheel is the larger (E_d > 1).
        EXPECT_EQ(r.e_d > 1.0, beta > 0.0);
        EXPECT_EQ(r.e_b > 1.0, alpha > 0.0);
        EXPECT_NEAR(r.right_wheel_diameter / r.left_wheel_diameter, r.e_d, 1e-14);
        EXPECT_NEAR(0.5 * (r.right_wheel_diameter + r.left_wheel_diameter), 0.0432, 1e-15);
    }
}

TEST(Umbmark, RefusesUnusableInput) {
    UmbmarkInput input = nominal_input(0.0);
    input.wheel_base = -0.12;
    input.counter_clockwise = {{0.01, std::nan("")}};
    const std::string message = input_error_of([&] { umbmark(input); });
    for (const char* expected :
         {"side = 0: must be a positive number", "wheel_base = -0.12: must be a positive number",
          "clockwise: needs the return error of at least one run",
          "counter-clockwise run 1: the return error must be two finite numbers"}) {
        EXPECT_NE(message.find(expected), std::string::npos) << expected << "\nin\n" << message;
    }
    // Centimetres typed as metres: α ≈ 1.5 rad is no small angle.
    UmbmarkInput centimetres = nominal_input(1.0);
    centimetres.clockwise = {{-3.0, -3.0}};
    centimetres.counter_clockwise = {{-3.0, 3.0}};
    EXPECT_NE(input_error_of([&] {
                  umbmark(centimetres);
              }).find("too large for UMBmark's small-angle formulas"),
              std::string::npos);
}

TEST(Umbmark, ParsesReturnErrorLists) {
    const auto errors =
        legofeup::lessons::parse_return_errors(" 0.05,-0.02; 0.04 , -0.03;", "--cw");
    ASSERT_EQ(errors.size(), 2u);
    EXPECT_EQ(errors[0], Vector2(0.05, -0.02));
    EXPECT_EQ(errors[1], Vector2(0.04, -0.03));
    EXPECT_EQ(input_error_of([] { legofeup::lessons::parse_return_errors("0.05;0.1,x", "--ccw"); }),
              "--ccw run 1 = 0.05: must be the return error as x,y in metres (runs separated by "
              "';', e.g. \"0.05,-0.02;0.04,-0.03\")\n--ccw run 2 = 0.1,x: must be the return "
              "error as x,y in metres (runs separated by ';', e.g. \"0.05,-0.02;0.04,-0.03\")");
    EXPECT_NE(input_error_of([] {
                  legofeup::lessons::parse_return_errors("", "--cw");
              }).find("--cw run 1: must be"),
              std::string::npos);
}

// The simulator's robot with Borenstein & Feng's errors, driving the UMBmark square from its
// odometry alone: every leg and every turn is the wheel rotation that the odometry it
// believes in (Codo, b) says is exactly L straight or exactly 90°.
class SquareDriver {
  public:
    SquareDriver(double e_d, double e_b) : simulator_(world(), robot(e_d, e_b), {}, 1) {}

    // The return error (true end − start, start frame) of one run.
    Vector2 run(const OdometryParams& believed, double side, bool clockwise) {
        simulator_.reset({0.0, 0.0, 0.0}, 1);
        believed_ = believed;
        odometry_ = {};
        last_counts_ = simulator_.sensor_frame().encoder_counts;
        const double turn = (clockwise ? -1.0 : 1.0) * 0.5 * kPi;
        for (int corner = 0; corner < 4; ++corner) {
            rotate_wheels(side * believed.codo_right, side * believed.codo_left);
            // Eq. 8 backwards: Δθ = (d1 − d2)/b with d1 = −d2 = b·Δθ/2.
            const double wheel = 0.5 * believed.wheel_base * turn;
            rotate_wheels(wheel * believed.codo_right, -wheel * believed.codo_left);
        }
        // The robot believes it is back at the start, facing as it started.
        EXPECT_LT(std::hypot(odometry_.x, odometry_.y), 0.003);
        EXPECT_LT(std::abs(legofeup::wrap_angle(odometry_.theta)), 0.01);
        const Pose2 end = simulator_.ground_truth().pose;
        return {end.x, end.y};
    }

  private:
    static legofeup::sim::WorldSpec world() {
        legofeup::sim::WorldSpec empty;
        empty.walls.clear();
        return empty;
    }

    static legofeup::sim::RobotSpec robot(double e_d, double e_b) {
        legofeup::sim::RobotSpec spec;
        spec.wheel_diameter_ratio = e_d;
        spec.wheel_base_ratio = e_b;
        spec.motor_time_constant = 0.0;  // the wheels turn exactly as commanded
        return spec;
    }

    // Turns the wheels by these encoder counts (degrees) together, with a trapezoidal speed
    // profile (0.1 m/s at most, 0.5 s ramps) so the tyres do not skid.
    void rotate_wheels(double right_degrees, double left_degrees) {
        const double period = simulator_.settings().control_period;
        const double nominal_radius = 0.5 * simulator_.robot().wheel_diameter;
        const double metres_per_degree = kPi / 180.0 * nominal_radius;
        const double longest = std::max(std::abs(right_degrees), std::abs(left_degrees));
        constexpr int kRamp = 10;
        const int periods =
            static_cast<int>(std::ceil(longest * metres_per_degree / (0.1 * period))) + kRamp;
        std::vector<double> shape(static_cast<std::size_t>(periods));
        double total = 0.0;
        for (int k = 0; k < periods; ++k) {
            const double rise = (k + 0.5) / kRamp;
            const double fall = (periods - k - 0.5) / kRamp;
            shape[static_cast<std::size_t>(k)] = std::min({1.0, rise, fall});
            total += shape[static_cast<std::size_t>(k)];
        }
        for (double weight : shape) {
            // The simulator's motors turn a commanded m/s into rotation with the nominal radius.
            const double share = weight / total / period * metres_per_degree;
            simulator_.set_wheel_command({right_degrees * share, left_degrees * share});
            step();
        }
        simulator_.set_wheel_command({0.0, 0.0});
        for (int k = 0; k < 4; ++k) {
            step();
        }
    }

    void step() {
        simulator_.step_control_period();
        const auto counts = simulator_.sensor_frame().encoder_counts;
        const auto increment = legofeup::odometry_increment(
            legofeup::encoder_delta(counts[0], last_counts_[0]),
            legofeup::encoder_delta(counts[1], last_counts_[1]), believed_);
        odometry_ = legofeup::advance_pose(odometry_, increment);
        last_counts_ = counts;
    }

    legofeup::sim::Simulator simulator_;
    OdometryParams believed_;
    Pose2 odometry_;
    std::array<std::int32_t, 2> last_counts_{};
};

// Nominal odometry: 43.2 mm wheels, b = 0.12 m.
OdometryParams nominal_odometry() {
    return {};
}

struct Calibration {
    UmbmarkResult result;
    double return_error;  // the larger |return error| of the two directions, m
};

// One UMBmark round of one run each way with the odometry `believed`, then the corrections.
Calibration calibrate(SquareDriver& robot, const OdometryParams& believed, double side) {
    UmbmarkInput input;
    input.side = side;
    input.wheel_base = believed.wheel_base;
    input.right_wheel_diameter = 360.0 / (kPi * believed.codo_right);
    input.left_wheel_diameter = 360.0 / (kPi * believed.codo_left);
    input.clockwise = {robot.run(believed, side, true)};
    input.counter_clockwise = {robot.run(believed, side, false)};
    const UmbmarkResult result = umbmark(input);
    return {result, std::max(input.clockwise[0].norm(), input.counter_clockwise[0].norm())};
}

OdometryParams corrected(const UmbmarkResult& result) {
    return {result.codo_right, result.codo_left, result.wheel_base};
}

TEST(UmbmarkOnTheSimulator, ARobotWithoutErrorsComesBack) {
    SquareDriver robot(1.0, 1.0);
    const Calibration round = calibrate(robot, nominal_odometry(), 1.0);
    EXPECT_LT(round.return_error, 0.003);
    EXPECT_NEAR(round.result.e_d, 1.0, 1e-4);
    EXPECT_NEAR(round.result.e_b, 1.0, 1e-3);
}

TEST(UmbmarkOnTheSimulator, RecoversEdAndEbAndTheCorrectionShrinksTheReturnError) {
    // The formulas keep first-order terms in α and β only, so one round is off by terms of
    // second order; on the simulator (as on an exact arc model of the square) that is below
    // 0.5·(|α| + |β|)² for these cases, the stated tolerance. A second round with the corrected
    // odometry then recovers both factors to 5e-4.
    struct Case {
        double e_d;
        double e_b;
    };
    const double side = 1.0;
    const double base = nominal_odometry().wheel_base;
    for (const Case c : {Case{1.005, 1.03}, Case{0.995, 0.98}, Case{1.01, 1.0}}) {
        SCOPED_TRACE("E_d = " + std::to_string(c.e_d) + ", E_b = " + std::to_string(c.e_b));
        // The true angles: the corner turn falls short by α; a leg curves by β = Δd/b_actual
        // with D_R − D_L = 2(E_d − 1)/(E_d + 1) · D (same mean diameter).
        const double alpha = 0.5 * kPi * (1.0 - 1.0 / c.e_b);
        const double beta = side * 2.0 * (c.e_d - 1.0) / (c.e_d + 1.0) / (c.e_b * base);
        const double tolerance = 0.5 * std::pow(std::abs(alpha) + std::abs(beta), 2);
        SquareDriver robot(c.e_d, c.e_b);
        const Calibration first = calibrate(robot, nominal_odometry(), side);
        EXPECT_NEAR(first.result.e_d, c.e_d, tolerance);
        EXPECT_NEAR(first.result.e_b, c.e_b, tolerance);
        EXPECT_NEAR(first.result.alpha, alpha, tolerance);
        EXPECT_NEAR(first.result.beta, beta, tolerance);

        const Calibration second = calibrate(robot, corrected(first.result), side);
        EXPECT_LT(second.return_error, first.return_error / 10.0)
            << first.return_error << " m before, " << second.return_error << " m after";
        // The second round's factors multiply the first's.
        const double e_d = first.result.e_d * second.result.e_d;
        const double e_b = first.result.e_b * second.result.e_b;
        EXPECT_NEAR(second.result.wheel_base / 0.12, e_b, 1e-12);
        EXPECT_NEAR(second.result.right_wheel_diameter / second.result.left_wheel_diameter, e_d,
                    1e-12);
        EXPECT_NEAR(e_d, c.e_d, 5e-4);
        EXPECT_NEAR(e_b, c.e_b, 5e-4);
    }
}

}  // namespace
