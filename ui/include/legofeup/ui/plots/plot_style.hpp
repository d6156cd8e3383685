#pragma once
// How the plots look: colours from the widget palette (light and dark themes), fonts scaled
// for the projector, the look of each kind of series.

#include <QColor>
#include <QFont>
#include <QPalette>
#include <QString>
#include <array>

#include "legofeup/ui/plots/plot_series.hpp"

class QCustomPlot;
class QCPGraph;

namespace legofeup::ui {

inline constexpr int kSeriesColourCount = 5;

struct PlotLook {
    QColor text;        ///< axes, tick labels, titles, reference lines
    QColor background;  ///< the plot's background
    QColor grid;
    QColor sub_grid;
    QColor legend_background;
    /// Series colours with contrast on `background`: darker shades on a light theme,
    /// lighter ones on a dark theme.
    std::array<QColor, kSeriesColourCount> series;
    QFont font;        ///< tick and axis labels
    QFont small_font;  ///< legend and reference-line labels
    QFont title_font;
    double line_width = 1.5;  ///< px
};

/// The look for `palette` (Base = background, WindowText = text) and the widget font `base`
/// scaled by `text_scale` (1 = normal, ~1.6 = projector).
PlotLook plot_look(const QPalette& palette, const QFont& base, double text_scale);

/// Background, axes, grid, title, legend and the plot's reference lines and their labels.
void apply_look(QCustomPlot& plot, const PlotLook& look);

/// A header row above the axes: `title` on the left, the legend (shown, in one row) on the
/// right.
void add_header(QCustomPlot& plot, const QString& title);

/// Wraps the legend (beside the title) into as few rows as fit a plot `width` px wide.
void fit_legend(QCustomPlot& plot, int width);

/// Pen, scatter and fill of one series.
void apply_look(QCPGraph& graph, const SeriesDefinition& series, const PlotLook& look);

}  // namespace legofeup::ui
