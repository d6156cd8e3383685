#pragma once
// What the plots panel draws: the plots, the series of each plot and how each series' value
// is read from a step's record (run_history.hpp: a new series reads one of its numbers, or a
// new one added there). Plain data without Qt: one table, so a new series is one new row.

#include <cstdint>
#include <optional>
#include <span>

#include "legofeup/core/chi_square.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// The plots, in the order of the panel's tabs (and of the exported files).
enum class PlotKind : int {
    Covariance,     ///< Px, Py, Pθ: the diagonal of P, log scale
    PositionError,  ///< x̂ − x, ŷ − y with ±σx, ±σy bands
    HeadingError,   ///< θ̂ − θ (wrapped, degrees) with the ±σθ band
    WheelSpeeds,    ///< V1, V2 commands (and the true wheel surface speeds)
    IrDistances,    ///< ds1, ds2 as measured (gaps when out of range)
    Nis,            ///< NIS of each wall update with the χ²(2) 95 % bounds, log scale
    Nees,           ///< NEES with the χ²(3) 95 % bounds, log scale
    // The further lessons' plots (papers 002–004): shown only once the run has their data.
    Bearings,             ///< beacon bearing innovations z − h(X̂), applied and gated
    HeadingSensors,       ///< heading errors against the truth: estimate, gyro, compass
    TurnRate,             ///< ω: truth, gyroscope, encoders, the 5-state EKF
    WheelSpeedEstimates,  ///< wheel surface speeds: truth, per-wheel KF, differentiated encoders
    ShadowError,          ///< position error of the filters run side by side (EKF, UKF, PF)
    FilterCost,           ///< wall-clock µs per step of each filter, smoothed
    // The laser lesson's (paper 001): one point per scan.
    LaserMatches,     ///< ICP matched points, used or a mismatch, with min_matched_points
    LaserMismatches,  ///< consecutive mismatches with the recovery threshold; recoveries
    LaserInnovation,  ///< V = Z − Ẑ of the ICP pose observation: x, y (cm), θ (°)
    // The particle filter's (filter.kind = "pf").
    Particles,  ///< N_eff and the particle count, linear scale (0 … N)
};
inline constexpr int kPlotKindCount = 17;

/// Every drawn series. The order is the drawing order within a plot: bands first, so the
/// lines sit on top of them.
enum class Series : int {
    Px,
    Py,
    Ptheta,
    SigmaXUpper,
    SigmaXLower,
    SigmaYUpper,
    SigmaYLower,
    ErrorX,
    ErrorY,
    SigmaThetaUpper,
    SigmaThetaLower,
    ErrorTheta,
    V1Command,
    V2Command,
    V1True,
    V2True,
    Ds1,
    Ds2,
    Nis,
    Nees,
    BearingApplied,
    BearingGated,
    HeadingErrorEstimate,
    HeadingErrorGyro,
    HeadingErrorCompass,
    TurnRateTrue,
    TurnRateGyro,
    TurnRateEncoders,
    TurnRateFused,
    WheelRightTrue,
    WheelLeftTrue,
    WheelRightKf,
    WheelLeftKf,
    WheelRightDifferentiated,
    WheelLeftDifferentiated,
    EkfPositionError,
    UkfPositionError,
    PfPositionError,
    EkfCost,
    UkfCost,
    PfCost,
    LaserMatchedUsed,
    LaserMatchedMismatch,
    LaserConsecutiveMismatches,
    LaserRecoveries,
    LaserInnovationX,
    LaserInnovationY,
    LaserInnovationTheta,
    ParticleCount,
    ParticleEffective,
};
inline constexpr int kSeriesCount = 50;

/// At most this many points of one series per sample (one per beacon sighting).
inline constexpr int kMaxPointsPerSample = kMaxBeaconSightings;

enum class SeriesLook : std::uint8_t {
    Line,
    ThinLine,  ///< a secondary line (the true wheel speeds); solid: dashes over 36,000 points
               ///< cost the rasteriser ~200 ms a frame
    Points,
    BandEdge,  ///< one edge of a ±σ band: a faint line, not in the legend
    Band,      ///< the other edge, filled to its `fill_to` edge; the band's legend entry
};

struct PlotDefinition {
    PlotKind kind;
    const char* title;       ///< UTF-8
    const char* y_label;     ///< UTF-8, with the unit
    const char* file_stem;   ///< exported file name without its extension
    bool log_y;              ///< logarithmic y axis (values ≤ 0 are not drawn)
    int chi_square_dof = 0;  ///< > 0: the plot shows the two-sided 95 % bounds of χ²(dof)
    /// Shown only once one of its series has a point (the further lessons' sensors and the
    /// side-by-side filters); the others are always shown.
    bool optional = false;
};

/// The value of a series at one step: nullopt adds no point (NIS without an update), NaN
/// adds a gap in the line (an IR reading out of range, an error without truth).
using SeriesValue = std::optional<double> (*)(const StepRecord&);
/// Several values of a series at one step (one per beacon sighting): writes them to `out`
/// and returns how many.
using SeriesValues = int (*)(const StepRecord&, std::span<double, kMaxPointsPerSample> out);

struct SeriesDefinition {
    Series series;
    PlotKind plot;
    const char* name;  ///< legend text (UTF-8)
    SeriesValue value;
    int colour;  ///< index into the plot colours' series set (plot_style.hpp)
    SeriesLook look;
    Series fill_to;  ///< Band: the BandEdge it is filled to (otherwise the series itself)
    /// When set, used instead of `value`: several points per sample.
    SeriesValues values = nullptr;
    /// Exponential smoothing of the drawn value, s = s + a·(v − s) with a = `smoothing`
    /// (0: none). For noisy timings only.
    double smoothing = 0.0;
};

const PlotDefinition& plot_definition(PlotKind kind);
const SeriesDefinition& series_definition(Series series);
/// Every series, in Series order.
std::span<const SeriesDefinition> series_definitions();

/// The two-sided 95 % consistency interval of one χ²(dof) value: [q(0.025), q(0.975)].
ChiSquareInterval consistency_bounds(int dof);

}  // namespace legofeup::ui
