#include "legofeup/lessons/calibration/umbmark.hpp"

#include <cmath>
#include <limits>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/core/odometry.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "text_fields.hpp"

namespace legofeup::lessons {
namespace {

constexpr double kMinFactor = 0.5;  // E_d and E_b beyond 0.5 … 2 are not a small-angle case
constexpr double kMaxFactor = 2.0;

Vector2 centre_of_gravity(const std::vector<Vector2>& errors) {
    Vector2 sum = Vector2::Zero();
    for (const Vector2& error : errors) {
        sum += error;
    }
    return sum / static_cast<double>(errors.size());
}

void check_input(const UmbmarkInput& input) {
    std::vector<InputProblem> problems;
    const auto positive = [&](const char* key, double value) {
        if (!(std::isfinite(value) && value > 0.0)) {
            problems.push_back(
                {"", 0, key, format_config_number(value), "must be a positive number"});
        }
    };
    positive("side", input.side);
    positive("wheel_base", input.wheel_base);
    positive("right_wheel_diameter", input.right_wheel_diameter);
    positive("left_wheel_diameter", input.left_wheel_diameter);
    positive("counts_per_turn", input.counts_per_turn);
    const auto runs = [&](const char* key, const std::vector<Vector2>& errors) {
        if (errors.empty()) {
            problems.push_back({"", 0, key, "", "needs the return error of at least one run"});
        }
        for (std::size_t i = 0; i < errors.size(); ++i) {
            if (!errors[i].allFinite()) {
                problems.push_back({"", 0, std::string(key) + " run " + std::to_string(i + 1), "",
                                    "the return error must be two finite numbers"});
            }
        }
    };
    runs("clockwise", input.clockwise);
    runs("counter-clockwise", input.counter_clockwise);
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
}

void check_factor(const char* name, double value) {
    if (!(std::isfinite(value) && value >= kMinFactor && value <= kMaxFactor)) {
        throw InputError({{"", 0, name, format_config_number(value),
                           "the return errors are too large for UMBmark's small-angle formulas "
                           "(expected close to 1): check that they are in metres and measured "
                           "in the start frame (x along the first leg, y to the left)"}});
    }
}

}  // namespace

UmbmarkResult umbmark(const UmbmarkInput& input) {
    check_input(input);
    const double side = input.side;  // L
    UmbmarkResult result;
    result.centre_cw = centre_of_gravity(input.clockwise);
    result.centre_ccw = centre_of_gravity(input.counter_clockwise);
    result.r_cw = result.centre_cw.norm();
    result.r_ccw = result.centre_ccw.norm();
    result.e_max_syst = std::max(result.r_cw, result.r_ccw);

    const double x_cw = result.centre_cw.x();
    const double y_cw = result.centre_cw.y();
    const double x_ccw = result.centre_ccw.x();
    const double y_ccw = result.centre_ccw.y();
    result.alpha_from_x = (x_cw + x_ccw) / (-4.0 * side);
    result.alpha_from_y = (y_cw - y_ccw) / (-4.0 * side);
    result.beta_from_x = (x_cw - x_ccw) / (-4.0 * side);
    result.beta_from_y = (y_cw + y_ccw) / (-4.0 * side);
    result.alpha = 0.5 * (result.alpha_from_x + result.alpha_from_y);
    result.beta = 0.5 * (result.beta_from_x + result.beta_from_y);

    // Type B: a leg the robot believes straight is an arc of chord L turning by β, so its
    // radius is R = (L/2)/sin(β/2); the right wheel runs on R + b/2, the left on R − b/2.
    // E_d = (R + b/2)/(R − b/2) is evaluated as (1 + u)/(1 − u), u = b/(2R) = b·sin(β/2)/L,
    // which stays finite for β = 0 (R infinite, E_d = 1).
    const double half_sine = std::sin(0.5 * result.beta);
    result.radius =
        half_sine == 0.0 ? std::numeric_limits<double>::infinity() : 0.5 * side / half_sine;
    const double u = input.wheel_base * half_sine / side;
    result.e_d = (1.0 + u) / (1.0 - u);
    // Type A: the robot turns π/2 − α where its odometry counts π/2, so its real wheel base
    // is b·(π/2)/(π/2 − α).
    result.e_b = (0.5 * kPi) / (0.5 * kPi - result.alpha);
    check_factor("E_d", result.e_d);
    check_factor("E_b", result.e_b);

    // Diameters: D_R/D_L must become E_d times what it was, keeping the average.
    result.c_left = 2.0 / (result.e_d + 1.0);
    result.c_right = 2.0 / (1.0 / result.e_d + 1.0);
    result.wheel_base = result.e_b * input.wheel_base;
    result.right_wheel_diameter = result.c_right * input.right_wheel_diameter;
    result.left_wheel_diameter = result.c_left * input.left_wheel_diameter;
    result.codo_right =
        nominal_counts_per_metre(result.right_wheel_diameter, input.counts_per_turn);
    result.codo_left = nominal_counts_per_metre(result.left_wheel_diameter, input.counts_per_turn);
    return result;
}

std::vector<Vector2> parse_return_errors(std::string_view text, const std::string& option) {
    std::vector<Vector2> errors;
    std::vector<InputProblem> problems;
    const std::vector<std::string_view> pairs = split_fields(text, ';');
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (pairs[i].empty() && i + 1 == pairs.size() && i > 0) {
            break;  // a trailing ';'
        }
        const std::vector<std::string_view> numbers = split_fields(pairs[i], ',');
        const auto x = numbers.size() == 2 ? parse_number(numbers[0]) : std::nullopt;
        const auto y = numbers.size() == 2 ? parse_number(numbers[1]) : std::nullopt;
        if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) {
            problems.push_back({"", 0, option + " run " + std::to_string(i + 1),
                                std::string(pairs[i]),
                                "must be the return error as x,y in metres (runs separated by "
                                "';', e.g. \"0.05,-0.02;0.04,-0.03\")"});
            continue;
        }
        errors.emplace_back(*x, *y);
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
    return errors;
}

}  // namespace legofeup::lessons
