#include "legofeup/ui/plots/plot_series.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "legofeup/core/angles.hpp"

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

double variance(const RunSample& s, int i) {
    return s.snapshot.covariance(i, i);
}
double sigma(const RunSample& s, int i) {
    return std::sqrt(std::max(variance(s, i), 0.0));
}
/// x̂ − x (or ŷ − y), m; NaN without truth.
double position_error(const RunSample& s, int i) {
    if (!s.truth) {
        return kNaN;
    }
    const StateVector truth = to_state(s.truth->pose);
    return s.snapshot.estimate(i) - truth(i);
}
/// The measured IR distance, m; NaN (a gap) when the reading is out of range.
double ir_distance(const RunSample& s, int sensor) {
    const IrDistance& reading = s.snapshot.ir[static_cast<std::size_t>(sensor)].reading;
    return reading.in_range() ? reading.distance : kNaN;
}

std::optional<double> px(const RunSample& s) {
    return variance(s, kX);
}
std::optional<double> py(const RunSample& s) {
    return variance(s, kY);
}
std::optional<double> ptheta(const RunSample& s) {
    return variance(s, kTheta);
}
std::optional<double> sigma_x_upper(const RunSample& s) {
    return sigma(s, kX);
}
std::optional<double> sigma_x_lower(const RunSample& s) {
    return -sigma(s, kX);
}
std::optional<double> sigma_y_upper(const RunSample& s) {
    return sigma(s, kY);
}
std::optional<double> sigma_y_lower(const RunSample& s) {
    return -sigma(s, kY);
}
std::optional<double> error_x(const RunSample& s) {
    return position_error(s, kX);
}
std::optional<double> error_y(const RunSample& s) {
    return position_error(s, kY);
}
std::optional<double> sigma_theta_upper(const RunSample& s) {
    return radians_to_degrees(sigma(s, kTheta));
}
std::optional<double> sigma_theta_lower(const RunSample& s) {
    return -radians_to_degrees(sigma(s, kTheta));
}
/// θ̂ − θ wrapped to (−180°, 180°]: an estimate of π − 0.01 against a truth of −π + 0.01
/// is 0.02 rad off, not 2π − 0.02.
std::optional<double> error_theta(const RunSample& s) {
    if (!s.truth) {
        return kNaN;
    }
    return radians_to_degrees(wrap_angle(s.snapshot.estimate(kTheta) - s.truth->pose.theta));
}
std::optional<double> v1_true(const RunSample& s) {
    return s.truth ? s.truth->wheel_surface_speeds.right : kNaN;
}
std::optional<double> v2_true(const RunSample& s) {
    return s.truth ? s.truth->wheel_surface_speeds.left : kNaN;
}
std::optional<double> v1_command(const RunSample& s) {
    return s.snapshot.wheels.right;
}
std::optional<double> v2_command(const RunSample& s) {
    return s.snapshot.wheels.left;
}
std::optional<double> ds1(const RunSample& s) {
    return ir_distance(s, kFrontSensor);
}
std::optional<double> ds2(const RunSample& s) {
    return ir_distance(s, kRearSensor);
}
/// One point per wall update that computed an NIS (applied or rejected by the gate).
std::optional<double> nis(const RunSample& s) {
    const WallUpdateReport& update = s.snapshot.update;
    if (update.status == StepStatus::NotAttempted || !std::isfinite(update.nis)) {
        return std::nullopt;
    }
    return update.nis;
}
std::optional<double> nees(const RunSample& s) {
    return s.nees;
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
