#include "legofeup/ui/plots/plot_series.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "legofeup/core/angles.hpp"
#include "legofeup/core/pose_error.hpp"

namespace legofeup::ui {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Colour indices into the series set: the x-, y- and θ-related series share a colour
// across plots, so Px, the x error and its band read as one family.
constexpr int kColourX = 0;
constexpr int kColourY = 1;
constexpr int kColourTheta = 2;
constexpr int kColourRight = 0;  // V1, ds1
constexpr int kColourLeft = 1;   // V2, ds2
constexpr int kColourNis = 3;
constexpr int kColourNees = 4;
// The further lessons' plots: truth green, estimate blue, sensors vermilion and purple.
constexpr int kColourTruth = 2;
constexpr int kColourEstimate = 0;
constexpr int kColourGyro = 1;
constexpr int kColourCompass = 3;
constexpr int kColourFused = 4;
constexpr int kColourEkf = 0;
constexpr int kColourUkf = 1;
constexpr int kColourPf = 3;
constexpr int kColourParticleCount = 0;
constexpr int kColourParticleEffective = 3;
constexpr int kColourApplied = 0;
constexpr int kColourGated = 1;
/// µs per step: a ~1 s exponential average at 20 Hz (a = 1/20).
constexpr double kCostSmoothing = 0.05;

double variance(const StepRecord& s, int i) {
    return widen(i == kX ? s.pxx : i == kY ? s.pyy : s.ptt);
}
double sigma(const StepRecord& s, int i) {
    return std::sqrt(std::max(variance(s, i), 0.0));
}
/// Component `i` of x̃ = x̂ − x (pose_error.hpp): m, or rad for θ; NaN without truth.
double pose_error_component(const StepRecord& s, int i) {
    if (!s.has_truth) {
        return kNaN;
    }
    return pose_error(s.estimate, s.truth).vector()(i);
}

std::optional<double> px(const StepRecord& s) {
    return variance(s, kX);
}
std::optional<double> py(const StepRecord& s) {
    return variance(s, kY);
}
std::optional<double> ptheta(const StepRecord& s) {
    return variance(s, kTheta);
}
std::optional<double> sigma_x_upper(const StepRecord& s) {
    return sigma(s, kX);
}
std::optional<double> sigma_x_lower(const StepRecord& s) {
    return -sigma(s, kX);
}
std::optional<double> sigma_y_upper(const StepRecord& s) {
    return sigma(s, kY);
}
std::optional<double> sigma_y_lower(const StepRecord& s) {
    return -sigma(s, kY);
}
std::optional<double> error_x(const StepRecord& s) {
    return pose_error_component(s, kX);
}
std::optional<double> error_y(const StepRecord& s) {
    return pose_error_component(s, kY);
}
std::optional<double> sigma_theta_upper(const StepRecord& s) {
    return radians_to_degrees(sigma(s, kTheta));
}
std::optional<double> sigma_theta_lower(const StepRecord& s) {
    return -radians_to_degrees(sigma(s, kTheta));
}
/// θ̂ − θ wrapped to (−180°, 180°]: an estimate of π − 0.01 against a truth of −π + 0.01
/// is 0.02 rad off, not 2π − 0.02.
std::optional<double> error_theta(const StepRecord& s) {
    return radians_to_degrees(pose_error_component(s, kTheta));
}
std::optional<double> v1_true(const StepRecord& s) {
    return s.has_truth ? widen(s.true_wheel_speeds.right) : kNaN;
}
std::optional<double> v2_true(const StepRecord& s) {
    return s.has_truth ? widen(s.true_wheel_speeds.left) : kNaN;
}
std::optional<double> v1_command(const StepRecord& s) {
    return widen(s.wheels.right);
}
std::optional<double> v2_command(const StepRecord& s) {
    return widen(s.wheels.left);
}
/// The measured IR distance, m; NaN (a gap) when the reading is out of range.
std::optional<double> ds1(const StepRecord& s) {
    return widen(s.ir_distance[kFrontSensor]);
}
std::optional<double> ds2(const StepRecord& s) {
    return widen(s.ir_distance[kRearSensor]);
}
/// One point per wall update that computed an NIS (applied or rejected by the gate).
std::optional<double> nis(const StepRecord& s) {
    if (!std::isfinite(s.wall_nis)) {
        return std::nullopt;
    }
    return widen(s.wall_nis);
}
std::optional<double> nees(const StepRecord& s) {
    return s.nees;
}

// ---- the further lessons (papers 002–004) ---------------------------------------------

/// The bearing innovations z − h(X̂) of this step's beacon updates, degrees, wrapped; those
/// applied (`applied`) or those the gate or a bad S turned away.
int bearing_innovations(const StepRecord& s, std::span<double, kMaxPointsPerSample> out,
                        bool applied) {
    const int count = std::min<int>(s.bearing_count, kMaxPointsPerSample);
    int written = 0;
    for (int i = 0; i < count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (s.bearing_applied[k] != applied) {
            continue;
        }
        out[static_cast<std::size_t>(written++)] =
            radians_to_degrees(widen(s.bearing_innovation[k]));
    }
    return written;
}
int bearing_applied(const StepRecord& s, std::span<double, kMaxPointsPerSample> out) {
    return bearing_innovations(s, out, true);
}
int bearing_gated(const StepRecord& s, std::span<double, kMaxPointsPerSample> out) {
    return bearing_innovations(s, out, false);
}

bool has_heading_sensor(const StepRecord& s) {
    return s.has_gyro || s.has_compass;
}
/// `heading` − θ_true wrapped to (−180°, 180°] (heading_error); NaN without truth.
double heading_error_degrees(const StepRecord& s, double heading) {
    return s.has_truth ? radians_to_degrees(heading_error(heading, s.truth.theta)) : kNaN;
}
/// Drawn beside the gyro's and the compass's errors, so only when the run has one of them.
std::optional<double> heading_error_estimate(const StepRecord& s) {
    if (!has_heading_sensor(s)) {
        return std::nullopt;
    }
    return heading_error_degrees(s, s.estimate.theta);
}
std::optional<double> heading_error_gyro(const StepRecord& s) {
    if (!s.has_gyro) {
        return std::nullopt;
    }
    return heading_error_degrees(s, widen(s.gyro_heading));
}
std::optional<double> heading_error_compass(const StepRecord& s) {
    if (!s.has_compass) {
        return std::nullopt;
    }
    return heading_error_degrees(s, widen(s.compass_heading));
}

std::optional<double> turn_rate_true(const StepRecord& s) {
    if (!s.has_gyro) {
        return std::nullopt;
    }
    return s.has_truth ? radians_to_degrees(widen(s.true_turn_rate)) : kNaN;
}
std::optional<double> turn_rate_gyro(const StepRecord& s) {
    if (!s.has_gyro) {
        return std::nullopt;
    }
    return radians_to_degrees(widen(s.gyro_rate));
}
std::optional<double> turn_rate_encoders(const StepRecord& s) {
    if (!s.has_gyro || !s.speeds_valid) {
        return std::nullopt;
    }
    return radians_to_degrees(widen(s.encoder_turn_rate));
}
std::optional<double> turn_rate_fused(const StepRecord& s) {
    if (s.localisation != Localisation::GyroFusion) {
        return std::nullopt;
    }
    return radians_to_degrees(widen(s.fused_turn_rate));
}

/// The wheel-speed estimates (computed in every run) belong to the lessons of paper 003: a
/// run with its sensors (gyroscope, accelerometers) or its 5-state fusion.
bool has_wheel_speed_estimates(const StepRecord& s) {
    return s.speeds_valid
           && (s.has_gyro || s.has_accelerometers || s.localisation == Localisation::GyroFusion);
}
std::optional<double> wheel_true(const StepRecord& s, bool right) {
    if (!has_wheel_speed_estimates(s)) {
        return std::nullopt;
    }
    if (!s.has_truth) {
        return kNaN;
    }
    return widen(right ? s.true_wheel_speeds.right : s.true_wheel_speeds.left);
}
std::optional<double> wheel_right_true(const StepRecord& s) {
    return wheel_true(s, true);
}
std::optional<double> wheel_left_true(const StepRecord& s) {
    return wheel_true(s, false);
}
std::optional<double> wheel_estimate(const StepRecord& s, const std::array<float, 2>& speeds,
                                     int wheel) {
    if (!has_wheel_speed_estimates(s)) {
        return std::nullopt;
    }
    return widen(speeds[static_cast<std::size_t>(wheel)]);
}
std::optional<double> wheel_right_kf(const StepRecord& s) {
    return wheel_estimate(s, s.wheel_kf, 0);
}
std::optional<double> wheel_left_kf(const StepRecord& s) {
    return wheel_estimate(s, s.wheel_kf, 1);
}
std::optional<double> wheel_right_differentiated(const StepRecord& s) {
    return wheel_estimate(s, s.wheel_differentiated, 0);
}
std::optional<double> wheel_left_differentiated(const StepRecord& s) {
    return wheel_estimate(s, s.wheel_differentiated, 1);
}

/// The position and cost of filter `kind` at this step: the primary's or the shadow's;
/// nothing unless both ran (the comparison is the point).
struct KindEstimate {
    Vector2 position;
    double seconds = 0.0;
};
std::optional<KindEstimate> estimate_of(const StepRecord& s, FilterKind kind) {
    if (!s.shadow_active) {
        return std::nullopt;
    }
    if (s.filter_kind == kind) {
        return KindEstimate{position_of(s.estimate), widen(s.filter_seconds)};
    }
    if (s.shadow_kind == kind) {
        return KindEstimate{s.shadow_position.cast<double>(), widen(s.shadow_filter_seconds)};
    }
    return std::nullopt;
}
/// ‖(x̂, ŷ) − (x, y)‖, m.
std::optional<double> position_error_of(const StepRecord& s, FilterKind kind) {
    const std::optional<KindEstimate> of = estimate_of(s, kind);
    if (!of) {
        return std::nullopt;
    }
    if (!s.has_truth) {
        return kNaN;
    }
    return (of->position - position_of(s.truth)).norm();
}
std::optional<double> ekf_position_error(const StepRecord& s) {
    return position_error_of(s, FilterKind::Ekf);
}
std::optional<double> ukf_position_error(const StepRecord& s) {
    return position_error_of(s, FilterKind::Ukf);
}
std::optional<double> pf_position_error(const StepRecord& s) {
    return position_error_of(s, FilterKind::Pf);
}
std::optional<double> cost_of(const StepRecord& s, FilterKind kind) {
    const std::optional<KindEstimate> of = estimate_of(s, kind);
    if (!of || !std::isfinite(of->seconds)) {
        return std::nullopt;
    }
    return of->seconds * 1e6;
}
std::optional<double> ekf_cost(const StepRecord& s) {
    return cost_of(s, FilterKind::Ekf);
}
std::optional<double> ukf_cost(const StepRecord& s) {
    return cost_of(s, FilterKind::Ukf);
}
std::optional<double> pf_cost(const StepRecord& s) {
    return cost_of(s, FilterKind::Pf);
}
// ---- the particle filter: its cloud ------------------------------------------------------
std::optional<double> particle_count(const StepRecord& s) {
    return s.particle_count > 0 ? std::optional<double>(s.particle_count) : std::nullopt;
}
std::optional<double> particle_effective(const StepRecord& s) {
    return s.particle_count > 0 ? std::optional<double>(widen(s.particle_effective)) : std::nullopt;
}
// ---- the laser lesson (paper 001): one point per scan the filter matched -------------

/// The scan the filter processed this step (not one skipped for its beam count), if any.
const LaserNumbers* scan_of(const StepRecord& s) {
    return s.laser.processed ? &s.laser : nullptr;
}
/// ICP's matched points of the scans whose match was used (`used`) or was a mismatch.
std::optional<double> laser_matched_points(const StepRecord& s, bool used) {
    const LaserNumbers* laser = scan_of(s);
    if (laser == nullptr || laser->matched != used) {
        return std::nullopt;
    }
    return laser->matched_points;
}
std::optional<double> laser_matched_used(const StepRecord& s) {
    return laser_matched_points(s, true);
}
std::optional<double> laser_matched_mismatch(const StepRecord& s) {
    return laser_matched_points(s, false);
}
std::optional<double> laser_consecutive_mismatches(const StepRecord& s) {
    const LaserNumbers* laser = scan_of(s);
    if (laser == nullptr) {
        return std::nullopt;
    }
    return laser->consecutive_mismatches;
}
/// Where P was inflated (§IV-B): a point at the mismatch count that triggered it.
std::optional<double> laser_recoveries(const StepRecord& s) {
    const LaserNumbers* laser = scan_of(s);
    if (laser == nullptr || !laser->recovery_triggered) {
        return std::nullopt;
    }
    return laser->consecutive_mismatches;
}
/// V = Z − Ẑ (eq. 3) of the scans the update ran on; x and y in cm, θ in degrees.
std::optional<double> laser_innovation(const StepRecord& s, int i) {
    const LaserNumbers* laser = scan_of(s);
    if (laser == nullptr || !laser->updated) {
        return std::nullopt;
    }
    return i == kTheta ? radians_to_degrees(widen(laser->innovation(kTheta)))
                       : 100.0 * widen(laser->innovation(i));
}
std::optional<double> laser_innovation_x(const StepRecord& s) {
    return laser_innovation(s, kX);
}
std::optional<double> laser_innovation_y(const StepRecord& s) {
    return laser_innovation(s, kY);
}
std::optional<double> laser_innovation_theta(const StepRecord& s) {
    return laser_innovation(s, kTheta);
}

std::optional<double> no_single_value(const StepRecord& /*s*/) {
    return std::nullopt;
}

// clang-format off
constexpr std::array<PlotDefinition, kPlotKindCount> kPlots{{
    {PlotKind::Covariance, "Covariance: diagonal of P", "P (m², rad²)", "covariance", true},
    {PlotKind::PositionError, "Position error: estimate − truth", "error (m)",
     "position_error", false},
    {PlotKind::HeadingError, "Heading error: estimate − truth, wrapped", "error (°)",
     "heading_error", false},
    {PlotKind::WheelSpeeds, "Wheel speeds: V1 right, V2 left", "speed (m/s)", "wheel_speeds",
     false},
    {PlotKind::IrDistances, "IR distances as measured", "distance (m)", "ir_distances", false},
    {PlotKind::Nis, "NIS: normalised innovation squared, χ²(2)", "NIS", "nis", true, 2},
    {PlotKind::Nees, "NEES: normalised estimation error squared, χ²(3)", "NEES", "nees", true,
     3},
    {PlotKind::Bearings, "Beacon bearings: innovation z − h(X̂)", "innovation (°)",
     "bearing_innovations", false, 0, true},
    {PlotKind::HeadingSensors, "Heading errors against the truth",
     "error (°)", "heading_sensors", false, 0, true},
    {PlotKind::TurnRate, "Turn rate ω", "ω (°/s)", "turn_rate", false, 0, true},
    {PlotKind::WheelSpeedEstimates, "Wheel speeds: Kalman filter vs differentiated encoders",
     "speed (m/s)", "wheel_speed_estimates", false, 0, true},
    {PlotKind::ShadowError, "Filters on the same frames: position error", "‖error‖ (m)",
     "ekf_ukf_error", false, 0, true},
    {PlotKind::FilterCost, "Filter cost per step (smoothed, this machine)", "time (µs)",
     "filter_cost", false, 0, true},
    {PlotKind::LaserMatches, "ICP: matched points per scan", "points", "laser_matches", false,
     0, true},
    {PlotKind::LaserMismatches, "Mismatches in a row, and the recovery", "mismatches",
     "laser_mismatches", false, 0, true},
    {PlotKind::LaserInnovation, "ICP pose observation: innovation V = Z − Ẑ", "V (cm, °)",
     "laser_innovation", false, 0, true},
    {PlotKind::Particles, "Particles: count and effective sample size", "particles",
     "particles", false, 0, true},
}};

using enum Series;
using enum SeriesLook;
constexpr std::array<SeriesDefinition, kSeriesCount> kSeries{{
    {Px, PlotKind::Covariance, "Px (m²)", px, kColourX, Line, Px},
    {Py, PlotKind::Covariance, "Py (m²)", py, kColourY, Line, Py},
    {Ptheta, PlotKind::Covariance, "Pθ (rad²)", ptheta, kColourTheta, Line, Ptheta},
    {SigmaXUpper, PlotKind::PositionError, "+σx", sigma_x_upper, kColourX, BandEdge, SigmaXUpper},
    {SigmaXLower, PlotKind::PositionError, "±σx", sigma_x_lower, kColourX, Band, SigmaXUpper},
    {SigmaYUpper, PlotKind::PositionError, "+σy", sigma_y_upper, kColourY, BandEdge, SigmaYUpper},
    {SigmaYLower, PlotKind::PositionError, "±σy", sigma_y_lower, kColourY, Band, SigmaYUpper},
    {ErrorX, PlotKind::PositionError, "x error", error_x, kColourX, Line, ErrorX},
    {ErrorY, PlotKind::PositionError, "y error", error_y, kColourY, Line, ErrorY},
    {SigmaThetaUpper, PlotKind::HeadingError, "+σθ", sigma_theta_upper, kColourTheta, BandEdge,
     SigmaThetaUpper},
    {SigmaThetaLower, PlotKind::HeadingError, "±σθ", sigma_theta_lower, kColourTheta, Band,
     SigmaThetaUpper},
    {ErrorTheta, PlotKind::HeadingError, "θ error", error_theta, kColourTheta, Line,
     ErrorTheta},
    {V1Command, PlotKind::WheelSpeeds, "V1 command", v1_command, kColourRight, Line, V1Command},
    {V2Command, PlotKind::WheelSpeeds, "V2 command", v2_command, kColourLeft, Line, V2Command},
    {V1True, PlotKind::WheelSpeeds, "V1 true", v1_true, kColourRight, ThinLine, V1True},
    {V2True, PlotKind::WheelSpeeds, "V2 true", v2_true, kColourLeft, ThinLine, V2True},
    {Ds1, PlotKind::IrDistances, "ds1 front", ds1, kColourRight, Line, Ds1},
    {Ds2, PlotKind::IrDistances, "ds2 rear", ds2, kColourLeft, Line, Ds2},
    {Nis, PlotKind::Nis, "NIS of a wall update", nis, kColourNis, Points, Nis},
    {Nees, PlotKind::Nees, "NEES", nees, kColourNees, Line, Nees},
    {BearingApplied, PlotKind::Bearings, "applied", no_single_value, kColourApplied, Points,
     BearingApplied, bearing_applied},
    {BearingGated, PlotKind::Bearings, "not applied (gate)", no_single_value, kColourGated,
     Points, BearingGated, bearing_gated},
    {HeadingErrorEstimate, PlotKind::HeadingSensors, "estimate", heading_error_estimate,
     kColourEstimate, Line, HeadingErrorEstimate},
    {HeadingErrorGyro, PlotKind::HeadingSensors, "gyro integrated", heading_error_gyro,
     kColourGyro, ThinLine, HeadingErrorGyro},
    {HeadingErrorCompass, PlotKind::HeadingSensors, "compass", heading_error_compass,
     kColourCompass, ThinLine, HeadingErrorCompass},
    {TurnRateTrue, PlotKind::TurnRate, "truth", turn_rate_true, kColourTruth, Line, TurnRateTrue},
    {TurnRateGyro, PlotKind::TurnRate, "gyroscope", turn_rate_gyro, kColourGyro, ThinLine,
     TurnRateGyro},
    {TurnRateEncoders, PlotKind::TurnRate, "encoders", turn_rate_encoders, kColourCompass,
     ThinLine, TurnRateEncoders},
    {TurnRateFused, PlotKind::TurnRate, "5-state EKF", turn_rate_fused, kColourFused, Line,
     TurnRateFused},
    {WheelRightTrue, PlotKind::WheelSpeedEstimates, "right true", wheel_right_true, kColourTruth,
     ThinLine, WheelRightTrue},
    {WheelLeftTrue, PlotKind::WheelSpeedEstimates, "left true", wheel_left_true, kColourTruth,
     ThinLine, WheelLeftTrue},
    {WheelRightKf, PlotKind::WheelSpeedEstimates, "right KF", wheel_right_kf, kColourRight, Line,
     WheelRightKf},
    {WheelLeftKf, PlotKind::WheelSpeedEstimates, "left KF", wheel_left_kf, kColourLeft, Line,
     WheelLeftKf},
    {WheelRightDifferentiated, PlotKind::WheelSpeedEstimates, "right differentiated",
     wheel_right_differentiated, kColourCompass, ThinLine, WheelRightDifferentiated},
    {WheelLeftDifferentiated, PlotKind::WheelSpeedEstimates, "left differentiated",
     wheel_left_differentiated, kColourFused, ThinLine, WheelLeftDifferentiated},
    {EkfPositionError, PlotKind::ShadowError, "EKF", ekf_position_error, kColourEkf, Line,
     EkfPositionError},
    {UkfPositionError, PlotKind::ShadowError, "UKF", ukf_position_error, kColourUkf, Line,
     UkfPositionError},
    {PfPositionError, PlotKind::ShadowError, "PF", pf_position_error, kColourPf, Line,
     PfPositionError},
    {EkfCost, PlotKind::FilterCost, "EKF", ekf_cost, kColourEkf, Line, EkfCost, nullptr,
     kCostSmoothing},
    {UkfCost, PlotKind::FilterCost, "UKF", ukf_cost, kColourUkf, Line, UkfCost, nullptr,
     kCostSmoothing},
    {PfCost, PlotKind::FilterCost, "PF", pf_cost, kColourPf, Line, PfCost, nullptr,
     kCostSmoothing},
    {LaserMatchedUsed, PlotKind::LaserMatches, "used", laser_matched_used, kColourApplied,
     Points, LaserMatchedUsed},
    {LaserMatchedMismatch, PlotKind::LaserMatches, "mismatch (prediction only)",
     laser_matched_mismatch, kColourGated, Points, LaserMatchedMismatch},
    {LaserConsecutiveMismatches, PlotKind::LaserMismatches, "mismatches in a row",
     laser_consecutive_mismatches, kColourGated, Line, LaserConsecutiveMismatches},
    {LaserRecoveries, PlotKind::LaserMismatches, "recovery: P inflated", laser_recoveries,
     kColourNis, Points, LaserRecoveries},
    {LaserInnovationX, PlotKind::LaserInnovation, "x (cm)", laser_innovation_x, kColourX, Line,
     LaserInnovationX},
    {LaserInnovationY, PlotKind::LaserInnovation, "y (cm)", laser_innovation_y, kColourY, Line,
     LaserInnovationY},
    {LaserInnovationTheta, PlotKind::LaserInnovation, "θ (°)", laser_innovation_theta,
     kColourTheta, Line, LaserInnovationTheta},
    {ParticleCount, PlotKind::Particles, "particles", particle_count, kColourParticleCount, Line,
     ParticleCount},
    {ParticleEffective, PlotKind::Particles, "N_eff", particle_effective,
     kColourParticleEffective, Line, ParticleEffective},
}};
// clang-format on

constexpr bool table_in_order() {
    for (int i = 0; i < kPlotKindCount; ++i) {
        if (static_cast<int>(kPlots[static_cast<std::size_t>(i)].kind) != i) {
            return false;
        }
    }
    for (int i = 0; i < kSeriesCount; ++i) {
        if (static_cast<int>(kSeries[static_cast<std::size_t>(i)].series) != i) {
            return false;
        }
    }
    return true;
}
static_assert(table_in_order(), "the tables are indexed by PlotKind and Series");

}  // namespace

const PlotDefinition& plot_definition(PlotKind kind) {
    return kPlots[static_cast<std::size_t>(kind)];
}

const SeriesDefinition& series_definition(Series series) {
    return kSeries[static_cast<std::size_t>(series)];
}

std::span<const SeriesDefinition> series_definitions() {
    return kSeries;
}

ChiSquareInterval consistency_bounds(int dof) {
    const auto n = static_cast<double>(dof);
    return {chi_square_quantile(0.025, n), chi_square_quantile(0.975, n)};
}

}  // namespace legofeup::ui
