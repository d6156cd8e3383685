#include "legofeup/lessons/calibration/ir_calibration.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>

#include "../text_file.hpp"
#include "legofeup/core/config_issue.hpp"
#include "legofeup/lessons/input_error.hpp"
#include "text_fields.hpp"

namespace legofeup::lessons {
namespace {

// The fitted parameters p = [C_M, C_R, b], named.
using Parameters = Eigen::Vector3d;
enum ParameterIndex : int { kCM = 0, kCR = 1, kB = 2 };

constexpr int kMinPoints = 4;
constexpr int kMinDistinctAdc = 3;  // three parameters
constexpr int kMaxIterations = 500;
constexpr double kStepTolerance = 1e-12;      // ‖D·δ‖ ≤ this · ‖D·p‖: converged
constexpr double kGradientTolerance = 1e-12;  // cosine of r with every column of J
constexpr double kInitialDamping = 1e-3;
constexpr double kMaxDamping = 1e16;  // no step reduces the cost: a minimum within rounding

Parameters parameters_of(const SharpIrCurve& curve) {
    return {curve.c_m, curve.c_r, curve.b};
}

SharpIrCurve with_parameters(SharpIrCurve curve, const Parameters& p) {
    curve.c_m = p(kCM);
    curve.c_r = p(kCR);
    curve.b = p(kB);
    return curve;
}

std::string number_text(double value) {
    return format_config_number(value);
}

// Every A must keep A + C_R > 0: eq. 2 has its pole at A = −C_R.
bool all_finite_distances(std::span<const IrCalibrationPoint> points, double c_r) {
    return std::all_of(points.begin(), points.end(),
                       [&](const IrCalibrationPoint& point) { return point.adc + c_r > 0.0; });
}

void check_inputs(std::span<const IrCalibrationPoint> points, const SharpIrCurve& start) {
    std::vector<InputProblem> problems;
    const auto problem = [&](std::string key, std::string value, std::string reason) {
        problems.push_back({"", 0, std::move(key), std::move(value), std::move(reason)});
    };
    if (points.size() < static_cast<std::size_t>(kMinPoints)) {
        problem("points", std::to_string(points.size()),
                "the fit needs at least " + std::to_string(kMinPoints)
                    + " measurements at different distances");
    }
    std::set<double> distinct;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string name = "point " + std::to_string(i + 1);
        const IrCalibrationPoint& point = points[i];
        if (!(std::isfinite(point.adc) && point.adc >= 0.0 && point.adc <= start.adc_max)) {
            problem(name + " adc", number_text(point.adc),
                    "must be an A/D value between 0 and " + std::to_string(start.adc_max));
        } else {
            distinct.insert(point.adc);
        }
        if (!(std::isfinite(point.distance) && point.distance > 0.0)) {
            problem(name + " distance_m", number_text(point.distance),
                    "must be a positive number of metres");
        }
    }
    if (distinct.size() == 1 && points.size() > 1) {
        problem("points", "",
                "every measurement has the same A/D value (A = " + number_text(*distinct.begin())
                    + "): measure at several distances across the range");
    } else if (distinct.size() > 1 && distinct.size() < static_cast<std::size_t>(kMinDistinctAdc)) {
        problem("points", "",
                "only " + std::to_string(distinct.size())
                    + " different A/D values: C_M, C_R and b need at least "
                    + std::to_string(kMinDistinctAdc) + " (measure at more distances)");
    }
    const Parameters p = parameters_of(start);
    if (!p.allFinite() || !std::isfinite(start.a) || !(start.a > 0.0)) {
        problem("start curve", "", "a, C_M, C_R and b must be finite numbers, a positive");
    } else if (!distinct.empty() && !all_finite_distances(points, start.c_r)) {
        problem("start curve C_R", number_text(start.c_r),
                "A + C_R must be positive at every point (eq. 2 has its pole at A = −C_R), but "
                "the smallest A is "
                    + number_text(*distinct.begin()));
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
}

// Model minus measurement, the residual the iteration drives to a least-squares minimum.
Eigen::VectorXd model_residuals(std::span<const IrCalibrationPoint> points,
                                const SharpIrCurve& curve) {
    Eigen::VectorXd r(static_cast<Eigen::Index>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        r(static_cast<Eigen::Index>(i)) =
            distance_from_adc(points[i].adc, curve).distance - points[i].distance;
    }
    return r;
}

Eigen::MatrixX3d jacobian(std::span<const IrCalibrationPoint> points, const SharpIrCurve& curve) {
    Eigen::MatrixX3d j(static_cast<Eigen::Index>(points.size()), 3);
    for (std::size_t i = 0; i < points.size(); ++i) {
        j.row(static_cast<Eigen::Index>(i)) = ir_curve_jacobian(points[i].adc, curve);
    }
    return j;
}

// With C_R fixed, eq. 2 is linear in C_M and b: D = a·C_M·u − a·b with u = 1/(A + C_R).
// Solving that 2-parameter problem first puts the iteration near the minimum whatever the
// start's C_M and b were.
Parameters linear_start(std::span<const IrCalibrationPoint> points, const SharpIrCurve& start) {
    Eigen::MatrixX2d design(static_cast<Eigen::Index>(points.size()), 2);
    Eigen::VectorXd distances(static_cast<Eigen::Index>(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto row = static_cast<Eigen::Index>(i);
        design(row, 0) = start.a / (points[i].adc + start.c_r);
        design(row, 1) = -start.a;
        distances(row) = points[i].distance;
    }
    const Eigen::Vector2d solution = design.colPivHouseholderQr().solve(distances);
    if (!solution.allFinite()) {
        return parameters_of(start);
    }
    return {solution(0), start.c_r, solution(1)};
}

// The largest |cosine| between the residual vector and a column of J: 0 at a stationary
// point of the cost (MINPACK's orthogonality test).
double gradient_cosine(const Eigen::MatrixX3d& j, const Eigen::VectorXd& r) {
    const double r_norm = r.norm();
    if (r_norm == 0.0) {
        return 0.0;
    }
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double column_norm = j.col(c).norm();
        if (column_norm > 0.0) {
            largest = std::max(largest, std::abs(j.col(c).dot(r)) / (column_norm * r_norm));
        }
    }
    return largest;
}

}  // namespace

Eigen::RowVector3d ir_curve_jacobian(double adc, const SharpIrCurve& curve) {
    const double denominator = adc + curve.c_r;  // A + C_R
    return {curve.a / denominator, -curve.a * curve.c_m / (denominator * denominator), -curve.a};
}

IrFit fit_ir_curve(std::span<const IrCalibrationPoint> points, const SharpIrCurve& start) {
    check_inputs(points, start);

    // Levenberg–Marquardt with Marquardt's scaling: each step solves
    //   min ‖J·δ + r‖² + λ‖D·δ‖²,  D = diag(‖columns of J‖),
    // as the least-squares problem [J; √λ·D]·δ = [−r; 0] (QR, not the normal equations).
    // A step is taken only if it lowers the cost and keeps A + C_R > 0 at every point;
    // otherwise λ grows tenfold and the step shortens towards steepest descent.
    Parameters p = linear_start(points, start);
    SharpIrCurve curve = with_parameters(start, p);
    Eigen::VectorXd r = model_residuals(points, curve);
    double cost = r.squaredNorm();
    double damping = kInitialDamping;
    const auto n = static_cast<Eigen::Index>(points.size());

    IrFit fit;
    while (fit.iterations < kMaxIterations && !fit.converged) {
        ++fit.iterations;
        const Eigen::MatrixX3d j = jacobian(points, curve);
        if (cost == 0.0 || gradient_cosine(j, r) <= kGradientTolerance) {
            fit.converged = true;
            break;
        }
        const Eigen::Vector3d scale = j.colwise().norm().transpose().cwiseMax(1e-300);
        bool stepped = false;
        while (!stepped && damping <= kMaxDamping) {
            Eigen::MatrixX3d augmented(n + 3, 3);
            augmented.topRows(n) = j;
            augmented.bottomRows(3) = (std::sqrt(damping) * scale).asDiagonal();
            Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 3);
            rhs.head(n) = -r;
            const Parameters step = augmented.colPivHouseholderQr().solve(rhs);
            const Parameters candidate = p + step;
            if (candidate.allFinite() && all_finite_distances(points, candidate(kCR))) {
                const SharpIrCurve trial = with_parameters(start, candidate);
                const Eigen::VectorXd trial_r = model_residuals(points, trial);
                const double trial_cost = trial_r.squaredNorm();
                if (trial_cost < cost) {
                    const bool small_step = scale.cwiseProduct(step).norm()
                                            <= kStepTolerance * scale.cwiseProduct(p).norm();
                    p = candidate;
                    curve = trial;
                    r = trial_r;
                    cost = trial_cost;
                    damping = std::max(damping / 10.0, 1e-12);
                    stepped = true;
                    fit.converged = small_step;
                    break;
                }
            }
            damping *= 10.0;
        }
        if (!stepped) {
            // No step lowers the cost any more: at a minimum as far as doubles can tell.
            fit.converged = true;
        }
    }

    fit.curve = curve;
    fit.residuals.resize(points.size());
    double sum_of_squares = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double residual = -r(static_cast<Eigen::Index>(i));  // measured − fitted
        fit.residuals[i] = residual;
        sum_of_squares += residual * residual;
        fit.max_abs_residual = std::max(fit.max_abs_residual, std::abs(residual));
    }
    fit.rms_residual = std::sqrt(sum_of_squares / static_cast<double>(points.size()));
    return fit;
}

std::vector<IrCalibrationPoint> points_of(std::span<const IrCalibrationPoint> points,
                                          IrSensor sensor) {
    std::vector<IrCalibrationPoint> taken;
    std::copy_if(points.begin(), points.end(), std::back_inserter(taken),
                 [sensor](const IrCalibrationPoint& point) { return point.sensor == sensor; });
    return taken;
}

namespace {

// The fit names points by number: say which source (and which sensor's points) they are in.
IrFit fit_named(std::span<const IrCalibrationPoint> points, const SharpIrCurve& start,
                const std::string& source) {
    try {
        return fit_ir_curve(points, start);
    } catch (const InputError& error) {
        std::vector<InputProblem> problems = error.problems();
        for (InputProblem& problem : problems) {
            problem.source = problem.source.empty() ? source : problem.source;
        }
        throw InputError(std::move(problems));
    }
}

}  // namespace

std::string sensor_points_source(const std::string& source, IrSensor sensor) {
    const std::string whose =
        sensor == kFrontSensor ? "front sensor's points" : "rear sensor's points";
    return source.empty() ? whose : source + " (" + whose + ")";
}

IrCalibration fit_ir_calibration(std::span<const IrCalibrationPoint> points,
                                 const SharpIrCurve& start, const std::string& source) {
    IrCalibration calibration;
    calibration.both = fit_named(points, start, source);
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const std::vector<IrCalibrationPoint> own = points_of(points, sensor);
        if (!own.empty()) {
            calibration.own[static_cast<std::size_t>(sensor)] =
                fit_named(own, start, sensor_points_source(source, sensor));
        }
    }
    return calibration;
}

void apply_ir_calibration(RobotProfile& profile, const IrCalibration& calibration) {
    profile.ir_curve =
        with_curve_parameters(profile.ir_curve, curve_parameters(calibration.both.curve));
    for (const IrSensor sensor : {kFrontSensor, kRearSensor}) {
        const auto& own = calibration.own[static_cast<std::size_t>(sensor)];
        profile.ir_sensor_parameters[static_cast<std::size_t>(sensor)] =
            own ? std::optional(curve_parameters(own->curve)) : std::nullopt;
    }
}

std::vector<IrCalibrationPoint> read_ir_points_csv(const std::string& path) {
    return parse_ir_points_csv(read_text_file(path, kMeasurementsFile), path);
}

std::vector<IrCalibrationPoint> parse_ir_points_csv(std::string_view text,
                                                    const std::string& source) {
    std::vector<InputProblem> problems;
    std::vector<IrCalibrationPoint> points;
    const auto problem = [&](int line, std::string key, std::string_view value,
                             std::string reason) {
        problems.push_back({source, line, std::move(key), std::string(value), std::move(reason)});
    };
    bool header_seen = false;
    bool with_sensor = false;  // the header has the sensor column
    std::size_t next = 0;      // where the next line starts
    for (int line = 1; next < text.size(); ++line) {
        const std::size_t end = std::min(text.find('\n', next), text.size());
        const std::string_view row = text.substr(next, end - next);
        next = end + 1;
        const std::string_view content = trimmed(row.substr(0, row.find('#')));
        if (content.empty()) {
            continue;
        }
        const std::vector<std::string_view> fields = split_fields(content, ',');
        if (!header_seen) {
            header_seen = true;
            with_sensor = fields.size() == 3 && fields[2] == "sensor";
            if ((fields.size() != 2 && !with_sensor) || fields[0] != "adc"
                || fields[1] != "distance_m") {
                problem(line, "header", content,
                        "the first line must be: adc,distance_m (or adc,distance_m,sensor)");
                break;
            }
            continue;
        }
        const std::size_t columns = with_sensor ? 3 : 2;
        if (fields.size() != columns) {
            problem(line, "row", content,
                    "expected " + std::to_string(columns) + " values ("
                        + (with_sensor ? "adc,distance_m,sensor" : "adc,distance_m") + "), found "
                        + std::to_string(fields.size()));
            continue;
        }
        std::optional<IrSensor> sensor;
        if (with_sensor) {
            if (fields[2] == "front" || fields[2] == "rear") {
                sensor = fields[2] == "front" ? kFrontSensor : kRearSensor;
            } else {
                problem(line, "sensor", fields[2], "must be front or rear");
                continue;
            }
        }
        const auto adc = parse_number(fields[0]);
        const auto distance = parse_number(fields[1]);
        if (!adc || !std::isfinite(*adc) || *adc < 0.0) {
            problem(line, "adc", fields[0], "must be an A/D value (a number from 0 up)");
        }
        if (!distance || !std::isfinite(*distance) || !(*distance > 0.0)) {
            problem(line, "distance_m", fields[1], "must be a positive number of metres");
        }
        if (adc && distance) {
            points.push_back({*adc, *distance, sensor});
        }
    }
    if (!header_seen) {
        problem(0, "", "",
                "the file is empty: expected the header adc,distance_m and measurements");
    } else if (problems.empty() && points.empty()) {
        problem(0, "", "", "no measurements after the header");
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
    return points;
}

}  // namespace legofeup::lessons
