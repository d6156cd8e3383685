#pragma once
// Odometry calibration with Borenstein & Feng's UMBmark (IEEE Trans. Robotics and Automation
// 12(6), 1996): the robot drives a square of side L clockwise and counter-clockwise, using
// nothing but its odometry, and stops where it believes it started. The return errors of
// the two directions separate the two dominant systematic errors — the effective wheel base
// (type A, E_b) and unequal wheel diameters (type B, E_d) — and give their corrections.
//
// Conventions (docs/calibration.md has the derivation):
//  - The start frame: origin at the start, x along the first leg, y to the robot's left.
//    Clockwise runs turn right at each corner, counter-clockwise runs turn left.
//  - A return error is (measured end position − start position) in that frame, metres.
//  - α (type A) is how much less than 90° the robot really turns at each corner (positive:
//    it turns too little, its real wheel base is larger than the odometry's).
//  - β (type B) is the heading change over one leg the robot believes straight (positive: it
//    curves to the left, the right wheel is the larger).
// To first order in α and β the centres of gravity of the return errors are
//   x_cw = −2L(α + β),  y_cw = −2L(α + β),  x_ccw = −2L(α − β),  y_ccw = +2L(α − β),
// so B&F's α = (x_cw + x_ccw)/(−4L), β = (x_cw − x_ccw)/(−4L) and, from the y coordinates,
// α = (y_cw − y_ccw)/(−4L), β = (y_cw + y_ccw)/(−4L). The two differ by the second-order
// terms (and by measuring noise); the estimate used is their mean, which is also the least-
// squares fit of α and β to all four coordinates. A second calibration round, run with the
// corrected parameters, removes most of what the first-order formulas leave.

#include <string>
#include <string_view>
#include <vector>

#include "legofeup/core/state.hpp"

namespace legofeup::lessons {

struct UmbmarkInput {
    double side = 0.0;  ///< L, the side of the square, m
    /// The odometry's parameters while the runs were made (what is being corrected).
    double wheel_base = 0.12;                ///< b, m
    double right_wheel_diameter = 0.0432;    ///< m
    double left_wheel_diameter = 0.0432;     ///< m
    double counts_per_turn = 360.0;          ///< encoder counts per wheel revolution
    std::vector<Vector2> clockwise;          ///< return errors (x, y) of the cw runs, m
    std::vector<Vector2> counter_clockwise;  ///< return errors of the ccw runs, m
};

struct UmbmarkResult {
    Vector2 centre_cw = Vector2::Zero();   ///< (x_c.g.,cw, y_c.g.,cw): mean return error, m
    Vector2 centre_ccw = Vector2::Zero();  ///< (x_c.g.,ccw, y_c.g.,ccw), m
    double r_cw = 0.0;                     ///< r_c.g.,cw = |centre_cw|, m
    double r_ccw = 0.0;                    ///< r_c.g.,ccw, m
    double e_max_syst = 0.0;               ///< E_max,syst = max(r_cw, r_ccw), m

    double alpha_from_x = 0.0;  ///< (x_cw + x_ccw)/(−4L), rad
    double alpha_from_y = 0.0;  ///< (y_cw − y_ccw)/(−4L), rad
    double beta_from_x = 0.0;   ///< (x_cw − x_ccw)/(−4L), rad
    double beta_from_y = 0.0;   ///< (y_cw + y_ccw)/(−4L), rad
    double alpha = 0.0;         ///< the mean of the two: what the corrections use, rad
    double beta = 0.0;          ///< rad

    double radius = 0.0;   ///< R = (L/2)/sin(β/2) of the curved legs, m (infinite if β = 0)
    double e_d = 1.0;      ///< E_d = D_R/D_L = (R + b/2)/(R − b/2)
    double e_b = 1.0;      ///< E_b = b_actual/b = (π/2)/(π/2 − α)
    double c_left = 1.0;   ///< c_L = 2/(E_d + 1): the left diameter's correction factor
    double c_right = 1.0;  ///< c_R = 2/(1/E_d + 1)

    double wheel_base = 0.0;            ///< corrected b_actual = E_b·b, m
    double right_wheel_diameter = 0.0;  ///< c_R · D_R (input), m
    double left_wheel_diameter = 0.0;   ///< c_L · D_L (input), m
    double codo_right = 0.0;  ///< counts_per_turn / (π · corrected D_R), counts per metre
    double codo_left = 0.0;
};

/// Computes UMBmark's corrections. Throws InputError for a side, wheel base, diameter or
/// counts that are not positive and finite, no run in either direction, a non-finite
/// return error, or errors so large that E_d or E_b would fall outside 0.5 … 2 (the small-
/// angle formulas do not apply; usually centimetres typed as metres).
UmbmarkResult umbmark(const UmbmarkInput& input);

/// Reads return errors written "x,y;x,y;…" (metres). `option` names the text in messages
/// (e.g. "--cw"). Throws InputError for an empty list or a pair that is not two finite
/// numbers.
std::vector<Vector2> parse_return_errors(std::string_view text, const std::string& option);

}  // namespace legofeup::lessons
