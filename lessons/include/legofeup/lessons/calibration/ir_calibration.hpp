#pragma once
// Calibrating the Sharp IR sensor of a real robot: the paper's characteristic curve (eq. 2)
// D = a·(C_M / (A + C_R) − b) fitted to measured pairs (A/D value A, distance D) by
// Levenberg–Marquardt over C_M, C_R and b. a stays fixed: it is the unit of the fit (0.01 m
// when the fit is written in centimetres) and only rescales C_M and b. See docs/calibration.md.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/core/sharp_ir.hpp"
#include "legofeup/lessons/robot_profile.hpp"

namespace legofeup::lessons {

/// One measurement: the sensor's raw reading with a target at a known distance.
struct IrCalibrationPoint {
    double adc = 0.0;       ///< A, the raw 10-bit A/D value (0 … adc_max)
    double distance = 0.0;  ///< D, metres from the sensor's front face to the target
    /// Which sensor took it, when the file says (its `sensor` column: front or rear).
    std::optional<IrSensor> sensor = std::nullopt;
};

/// The points `sensor` took (those whose sensor is said), in their order.
std::vector<IrCalibrationPoint> points_of(std::span<const IrCalibrationPoint> points,
                                          IrSensor sensor);

struct IrFit {
    /// The start curve with C_M, C_R and b replaced by the fitted values.
    SharpIrCurve curve;
    /// Per point, in the order given: measured − fitted distance, metres.
    std::vector<double> residuals;
    double rms_residual = 0.0;      ///< √(Σ residual² / n), metres
    double max_abs_residual = 0.0;  ///< metres
    int iterations = 0;             ///< Levenberg–Marquardt iterations (Jacobians evaluated)
    /// true when the iteration stopped because it had converged (a step or the gradient
    /// became negligible), false when it ran out of iterations.
    bool converged = false;
};

/// ∂D/∂(C_M, C_R, b) of eq. 2 at `adc`: [a/(A + C_R), −a·C_M/(A + C_R)², −a]. One row of
/// the fit's Jacobian (tests compare it with finite differences).
Eigen::RowVector3d ir_curve_jacobian(double adc, const SharpIrCurve& curve);

/// Fits C_M, C_R and b of eq. 2 to `points`, starting from `start` (whose a, ranges,
/// fold-back and adc_max are kept). Throws InputError, listing every problem, for fewer than
/// 4 points, an A outside 0 … adc_max, a distance that is not a positive finite number, fewer
/// than 3 different A values (all identical included), or a start curve with A + C_R ≤ 0 at
/// some point; the iteration never leaves the region where A + C_R > 0 at every point.
IrFit fit_ir_curve(std::span<const IrCalibrationPoint> points, const SharpIrCurve& start);

/// A calibration of the robot's two sensors from one set of points: the paper's one curve
/// for both, fitted to every point, and each sensor's own curve, fitted to the points it took
/// when they say which (real GP2D120s differ by up to ±10 % from unit to unit).
struct IrCalibration {
    IrFit both;
    std::array<std::optional<IrFit>, kIrSensorCount> own;
};

/// How a sensor's points are named in messages: "ir.csv (front sensor's points)", or
/// "front sensor's points" when `source` is empty (a table typed in the GUI).
std::string sensor_points_source(const std::string& source, IrSensor sensor);

/// Fits both curves as fit_ir_curve does; a problem with one sensor's points is named after
/// `source` and that sensor (sensor_points_source), one with all of them after `source`.
IrCalibration fit_ir_calibration(std::span<const IrCalibrationPoint> points,
                                 const SharpIrCurve& start, const std::string& source);

/// The calibration into a profile: eq. 2's parameters of the one curve into ir_curve (its
/// ranges stay), and each sensor's own parameters where it has them; a sensor without its own
/// points loses any own curve it had, so the profile never mixes two calibrations.
void apply_ir_calibration(RobotProfile& profile, const IrCalibration& calibration);

/// Reads measurements from a CSV file: the header `adc,distance_m`, then one `A,D` pair a
/// line (D in metres), or the header `adc,distance_m,sensor` and `A,D,front` or `A,D,rear`
/// (every line then says its sensor); blank lines and everything after `#` are ignored. Throws
/// InputError with path:line, the column, the value and the reason for every bad line.
std::vector<IrCalibrationPoint> read_ir_points_csv(const std::string& path);
/// Parses measurements from text as read_ir_points_csv does; `source` names it in messages.
std::vector<IrCalibrationPoint> parse_ir_points_csv(std::string_view text,
                                                    const std::string& source);

}  // namespace legofeup::lessons
