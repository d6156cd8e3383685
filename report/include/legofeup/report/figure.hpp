#pragma once
// Minimal scientific figures drawn with cairo, written as PNG and SVG from the same drawing
// code: panels with axes, ticks, grid, lines, ±σ bands, ellipses and a legend, or heat maps.
// Only what the CLI's run plots, the analysis plots and the student report need; the GUI plots with
// QCustomPlot. A figure can be written to files, returned as an SVG document, or drawn onto any
// cairo context (the report's PDF pages).

#include <optional>
#include <string>
#include <vector>

// cairo's context, declared as cairo.h does, so users of figures need not see cairo's headers.
typedef struct _cairo cairo_t;  // NOLINT(modernize-use-using): must match cairo.h

namespace legofeup::plot {

struct Color {
    double r = 0.0, g = 0.0, b = 0.0, a = 1.0;
};

namespace colors {
inline constexpr Color kTruth{0.10, 0.10, 0.10};
inline constexpr Color kEstimate{0.12, 0.40, 0.80};
inline constexpr Color kOdometry{0.90, 0.45, 0.05};
inline constexpr Color kWall{0.45, 0.45, 0.45};
inline constexpr Color kFront{0.80, 0.15, 0.20};
inline constexpr Color kRear{0.15, 0.60, 0.30};
inline constexpr Color kBand{0.12, 0.40, 0.80, 0.18};
}  // namespace colors

struct Line {
    std::vector<double> x;
    std::vector<double> y;  ///< NaN breaks the line
    Color color;
    double width = 1.5;
    bool dashed = false;
    std::string label;  ///< empty: not in the legend
};

/// A shaded band between two curves (e.g. ±σ).
struct Band {
    std::vector<double> x;
    std::vector<double> lower;
    std::vector<double> upper;
    Color color = colors::kBand;
    std::string label;
};

struct Ellipse {
    double cx = 0.0, cy = 0.0;
    double semi_major = 0.0, semi_minor = 0.0;
    double angle = 0.0;  ///< of the major axis, rad
    Color color = colors::kEstimate;
};

struct Segment {
    double x0, y0, x1, y1;
    Color color = colors::kWall;
    double width = 4.0;
};

/// A grid of coloured cells, e.g. a parameter sweep, with a colour bar at the right. A panel
/// with a heat map shows only it (its lines, bands, … are ignored).
struct HeatMap {
    std::vector<std::string> column_labels;  ///< along x, left to right
    std::vector<std::string> row_labels;     ///< along y, bottom to top
    /// Row-major, values[row · columns + column]; NaN cells are grey.
    std::vector<double> values;
    std::vector<std::string> cell_text;  ///< written in the cells (same layout); empty: none
    bool log_scale = false;              ///< colour by log₁₀(value) (values > 0)
    /// Blue–white–red around `centre` (a signed quantity, e.g. log₁₀(NEES/3)); otherwise a
    /// dark-to-bright ramp (small to large).
    bool diverging = false;
    double centre = 0.0;
    std::optional<double> min;  ///< colour range (default: the values'; symmetric if diverging)
    std::optional<double> max;
    std::string colour_label;  ///< the colour bar's label
};

struct Panel {
    std::string title;
    std::string x_label;
    std::string y_label;
    std::vector<Band> bands;
    std::vector<Segment> segments;
    std::vector<Ellipse> ellipses;
    std::vector<Line> lines;
    bool equal_aspect = false;  ///< one metre is as long on both axes (maps)
    bool log_y = false;
    std::optional<double> y_min;  ///< clip the y range
    std::optional<double> y_max;
    std::optional<HeatMap> heat_map;
};

class Figure {
  public:
    /// A figure of `rows` panels stacked vertically, `width` × `height` pixels.
    Figure(std::string title, int rows, int width, int height);

    Panel& panel(int row) { return panels_.at(static_cast<std::size_t>(row)); }

    /// Writes `<base>.png` and `<base>.svg`. Throws std::runtime_error when it cannot.
    void write(const std::string& base) const;

    /// The figure as a standalone SVG document (text as glyph outlines, no fonts needed).
    std::string svg() const;

    /// Draws the figure onto `cr` in its own units (0 … width × 0 … height): scale and
    /// translate the context first to place it.
    void draw(cairo_t* cr) const;

    const std::string& title() const { return title_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    std::string title_;
    std::vector<Panel> panels_;
    int width_;
    int height_;
};

}  // namespace legofeup::plot
