#pragma once
// The arena's legend: rows of swatches and texts laid out in one or more columns, so that it
// can sit beside or above the arena instead of over it. A row may hold several entries side
// by side ("IR rays ━ used ━ not used ┄ out of range"), which keeps the legend short.

#include <QColor>
#include <QFont>
#include <QSizeF>
#include <QString>
#include <vector>

namespace legofeup::ui {

/// One swatch and its text; Swatch::None is a caption (text only).
struct LegendEntry {
    enum class Swatch { None, Line, Dashed, Ellipse, DashedEllipse, Band, Diamond, Dots, Box };
    Swatch swatch = Swatch::Line;
    QColor color;
    QString text;  ///< may hold line breaks
};

/// One line of the legend: its entries side by side.
using LegendRow = std::vector<LegendEntry>;

/// Where each row goes: columns of consecutive rows, filled top to bottom, left to right.
struct LegendLayout {
    std::vector<std::size_t> column_starts;  ///< first row of each column
    std::vector<double> column_widths;       ///< px, without the padding
    std::vector<double> row_heights;         ///< px, one per row
    QSizeF size;                             ///< the whole box, padding included

    bool empty() const { return row_heights.empty(); }
    std::size_t columns() const { return column_starts.size(); }
};

/// Sizes of the legend's parts for `font` (px).
struct LegendMetrics {
    double line = 0.0;         ///< height of one text line's row
    double swatch = 0.0;       ///< width of a swatch
    double pad = 8.0;          ///< inside the box
    double gap = 6.0;          ///< swatch to text
    double entry_gap = 12.0;   ///< between entries of one row
    double column_gap = 16.0;  ///< between columns
};
LegendMetrics legend_metrics(const QFont& font);

/// The width of one row (px).
double legend_row_width(const LegendRow& row, const QFont& font);

/// Rows in columns no taller than `max_height` (px, padding included; a row taller than
/// that gets a column of its own).
LegendLayout legend_layout(const std::vector<LegendRow>& rows, const QFont& font,
                           double max_height);

/// The least tall layout whose box is at most `max_width` wide (one column when none is): a
/// strip above the arena.
LegendLayout legend_layout_within_width(const std::vector<LegendRow>& rows, const QFont& font,
                                        double max_width);

}  // namespace legofeup::ui
