#pragma once
// What the plots panel draws: the plots, the series of each plot and how each series' value
// is read from a RunSample. Plain data without Qt: one table, so a new series is one new row.

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
};
inline constexpr int kPlotKindCount = 7;

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
};
inline constexpr int kSeriesCount = 20;

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
};

/// The value of a series at one sample: nullopt adds no point (NIS without an update), NaN
/// adds a gap in the line (an IR reading out of range, an error without truth).
using SeriesValue = std::optional<double> (*)(const RunSample&);

struct SeriesDefinition {
    Series series;
    PlotKind plot;
    const char* name;  ///< legend text (UTF-8)
    SeriesValue value;
    int colour;  ///< index into the plot colours' series set (plot_style.hpp)
    SeriesLook look;
    Series fill_to;  ///< Band: the BandEdge it is filled to (otherwise the series itself)
};

const PlotDefinition& plot_definition(PlotKind kind);
const SeriesDefinition& series_definition(Series series);
/// Every series, in Series order.
std::span<const SeriesDefinition> series_definitions();

/// The two-sided 95 % consistency interval of one χ²(dof) value: [q(0.025), q(0.975)].
ChiSquareInterval consistency_bounds(int dof);

}  // namespace legofeup::ui
