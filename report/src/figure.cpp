#include "legofeup/report/figure.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "cairo_stream.hpp"
#include "legofeup/fileio/atomic_file.hpp"

namespace legofeup::plot {
namespace {

constexpr double kFontSize = 13.0;
constexpr double kTitleSize = 15.0;
constexpr double kMarginLeft = 78.0;
constexpr double kMarginRight = 24.0;
constexpr double kMarginTop = 30.0;
constexpr double kMarginBottom = 44.0;
constexpr double kFigureTitleHeight = 30.0;

struct Range {
    double low = std::numeric_limits<double>::infinity();
    double high = -std::numeric_limits<double>::infinity();

    void include(double value) {
        if (std::isfinite(value)) {
            low = std::min(low, value);
            high = std::max(high, value);
        }
    }
    bool valid() const { return low <= high; }
    double span() const { return high - low; }
};

struct Rect {
    double x, y, w, h;
};

// Data → pixel mapping of one panel.
struct Mapping {
    Rect area;
    Range x;
    Range y;  // in log10 units when log_y
    bool log_y;

    double px(double value) const { return area.x + (value - x.low) / x.span() * area.w; }
    double py(double value) const {
        const double v = log_y ? std::log10(value) : value;
        return area.y + area.h - (v - y.low) / y.span() * area.h;
    }
};

void set_color(cairo_t* cr, const Color& c) {
    cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a);
}

// Tick positions at 1, 2 or 5 × 10^k covering [low, high] with about `target` ticks.
std::vector<double> nice_ticks(double low, double high, int target) {
    const double raw = (high - low) / target;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        step = factor * magnitude;
        if (raw <= step) {
            break;
        }
    }
    std::vector<double> ticks;
    for (double t = std::ceil(low / step) * step; t <= high + 1e-9 * step; t += step) {
        ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    }
    return ticks;
}

std::string tick_label(double value, bool log_y) {
    char text[32];
    if (log_y) {
        const double exponent = std::floor(value + 1e-9);
        const double mantissa = std::pow(10.0, value - exponent);
        std::snprintf(text, sizeof text, "%.0fe%d", mantissa, static_cast<int>(exponent));
    } else {
        std::snprintf(text, sizeof text, "%g", value);
    }
    return text;
}

void text_at(cairo_t* cr, const std::string& text, double x, double y, double align_x,
             double align_y, double size = kFontSize, bool bold = false) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                           bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, size);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, x - align_x * extents.width - extents.x_bearing,
                  y - align_y * extents.height - extents.y_bearing);
    cairo_show_text(cr, text.c_str());
}

Range y_value_range(const Panel& panel) {
    Range y;
    const auto include = [&](double value) {
        if (panel.log_y) {
            if (value > 0.0) {
                y.include(std::log10(value));
            }
        } else {
            y.include(value);
        }
    };
    for (const Line& line : panel.lines) {
        std::for_each(line.y.begin(), line.y.end(), include);
    }
    for (const Band& band : panel.bands) {
        std::for_each(band.lower.begin(), band.lower.end(), include);
        std::for_each(band.upper.begin(), band.upper.end(), include);
    }
    for (const Ellipse& e : panel.ellipses) {
        include(e.cy - e.semi_major);
        include(e.cy + e.semi_major);
    }
    for (const Segment& s : panel.segments) {
        include(s.y0);
        include(s.y1);
    }
    if (panel.y_min) {
        y.low = panel.log_y ? std::log10(*panel.y_min) : *panel.y_min;
    }
    if (panel.y_max) {
        y.high = panel.log_y ? std::log10(*panel.y_max) : *panel.y_max;
    }
    return y;
}

Mapping make_mapping(const Panel& panel, const Rect& area) {
    Range x;
    for (const Line& line : panel.lines) {
        std::for_each(line.x.begin(), line.x.end(), [&](double v) { x.include(v); });
    }
    for (const Band& band : panel.bands) {
        std::for_each(band.x.begin(), band.x.end(), [&](double v) { x.include(v); });
    }
    for (const Ellipse& e : panel.ellipses) {
        x.include(e.cx - e.semi_major);
        x.include(e.cx + e.semi_major);
    }
    for (const Segment& s : panel.segments) {
        x.include(s.x0);
        x.include(s.x1);
    }
    Range y = y_value_range(panel);
    for (Range* r : {&x, &y}) {
        if (!r->valid()) {
            *r = {0.0, 1.0};
        }
        if (r->span() <= 0.0) {
            const double pad = std::max(std::abs(r->low) * 0.1, 1e-9);
            *r = {r->low - pad, r->high + pad};
        }
    }
    if (!panel.y_min && !panel.y_max) {
        const double pad = 0.05 * y.span();
        y = {y.low - pad, y.high + pad};
    }
    if (panel.equal_aspect) {
        const double pad = 0.05 * std::max(x.span(), y.span());
        x = {x.low - pad, x.high + pad};
        y = {y.low - pad, y.high + pad};
        // Grow the narrower range so a metre is as long on both axes.
        const double x_scale = area.w / x.span();
        const double y_scale = area.h / y.span();
        if (x_scale > y_scale) {
            const double extra = (area.w / y_scale - x.span()) / 2.0;
            x = {x.low - extra, x.high + extra};
        } else {
            const double extra = (area.h / x_scale - y.span()) / 2.0;
            y = {y.low - extra, y.high + extra};
        }
    }
    return {area, x, y, panel.log_y};
}

void draw_axes(cairo_t* cr, const Panel& panel, const Mapping& m) {
    cairo_set_line_width(cr, 1.0);
    // Grid and tick labels.
    const auto x_ticks = nice_ticks(m.x.low, m.x.high, 8);
    std::vector<double> y_ticks;
    if (m.log_y) {
        // Decades; on axes spanning less than two of them, also 2× and 5× each decade.
        const bool short_axis = m.y.span() < 2.0;
        for (double k = std::floor(m.y.low); k <= m.y.high; k += 1.0) {
            for (double factor : {1.0, 2.0, 5.0}) {
                const double tick = k + std::log10(factor);
                if ((factor == 1.0 || short_axis) && tick >= m.y.low && tick <= m.y.high) {
                    y_ticks.push_back(tick);
                }
            }
        }
    } else {
        y_ticks = nice_ticks(m.y.low, m.y.high, 6);
    }
    set_color(cr, {0.88, 0.88, 0.88});
    for (double t : x_ticks) {
        cairo_move_to(cr, m.px(t), m.area.y);
        cairo_line_to(cr, m.px(t), m.area.y + m.area.h);
    }
    for (double t : y_ticks) {
        const double y = m.log_y ? m.py(std::pow(10.0, t)) : m.py(t);
        cairo_move_to(cr, m.area.x, y);
        cairo_line_to(cr, m.area.x + m.area.w, y);
    }
    cairo_stroke(cr);
    set_color(cr, {0.15, 0.15, 0.15});
    for (double t : x_ticks) {
        text_at(cr, tick_label(t, false), m.px(t), m.area.y + m.area.h + 6.0, 0.5, 0.0);
    }
    for (double t : y_ticks) {
        const double y = m.log_y ? m.py(std::pow(10.0, t)) : m.py(t);
        text_at(cr, tick_label(t, m.log_y), m.area.x - 6.0, y, 1.0, 0.5);
    }
    cairo_rectangle(cr, m.area.x, m.area.y, m.area.w, m.area.h);
    cairo_stroke(cr);
    // Labels and title.
    text_at(cr, panel.x_label, m.area.x + m.area.w / 2.0, m.area.y + m.area.h + 24.0, 0.5, 0.0);
    cairo_save(cr);
    cairo_translate(cr, m.area.x - 62.0, m.area.y + m.area.h / 2.0);
    cairo_rotate(cr, -M_PI / 2.0);
    text_at(cr, panel.y_label, 0.0, 0.0, 0.5, 0.5);
    cairo_restore(cr);
    text_at(cr, panel.title, m.area.x, m.area.y - 8.0, 0.0, 1.0, kTitleSize, true);
}

void draw_polyline(cairo_t* cr, const std::vector<double>& xs, const std::vector<double>& ys,
                   const Mapping& m) {
    bool pen_down = false;
    for (std::size_t i = 0; i < xs.size() && i < ys.size(); ++i) {
        const bool usable = std::isfinite(xs[i]) && std::isfinite(ys[i]) && (!m.log_y || ys[i] > 0);
        if (!usable) {
            pen_down = false;
            continue;
        }
        if (pen_down) {
            cairo_line_to(cr, m.px(xs[i]), m.py(ys[i]));
        } else {
            cairo_move_to(cr, m.px(xs[i]), m.py(ys[i]));
            pen_down = true;
        }
    }
}

void draw_contents(cairo_t* cr, const Panel& panel, const Mapping& m) {
    cairo_save(cr);
    cairo_rectangle(cr, m.area.x, m.area.y, m.area.w, m.area.h);
    cairo_clip(cr);
    for (const Band& band : panel.bands) {
        set_color(cr, band.color);
        draw_polyline(cr, band.x, band.upper, m);
        for (std::size_t i = band.x.size(); i-- > 0;) {
            if (std::isfinite(band.x[i]) && std::isfinite(band.lower[i])) {
                cairo_line_to(cr, m.px(band.x[i]), m.py(band.lower[i]));
            }
        }
        cairo_close_path(cr);
        cairo_fill(cr);
    }
    for (const Segment& s : panel.segments) {
        set_color(cr, s.color);
        cairo_set_line_width(cr, s.width);
        cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
        cairo_move_to(cr, m.px(s.x0), m.py(s.y0));
        cairo_line_to(cr, m.px(s.x1), m.py(s.y1));
        cairo_stroke(cr);
    }
    cairo_set_line_width(cr, 1.0);
    for (const Ellipse& e : panel.ellipses) {
        set_color(cr, e.color);
        constexpr int kSegments = 48;
        for (int k = 0; k <= kSegments; ++k) {
            const double t = 2.0 * M_PI * k / kSegments;
            const double ex = e.semi_major * std::cos(t);
            const double ey = e.semi_minor * std::sin(t);
            const double x = e.cx + ex * std::cos(e.angle) - ey * std::sin(e.angle);
            const double y = e.cy + ex * std::sin(e.angle) + ey * std::cos(e.angle);
            if (k == 0) {
                cairo_move_to(cr, m.px(x), m.py(y));
            } else {
                cairo_line_to(cr, m.px(x), m.py(y));
            }
        }
        cairo_stroke(cr);
    }
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (const Line& line : panel.lines) {
        set_color(cr, line.color);
        cairo_set_line_width(cr, line.width);
        const double dash[] = {6.0, 4.0};
        cairo_set_dash(cr, dash, line.dashed ? 2 : 0, 0.0);
        draw_polyline(cr, line.x, line.y, m);
        cairo_stroke(cr);
    }
    cairo_set_dash(cr, nullptr, 0, 0.0);
    cairo_restore(cr);
}

void draw_legend(cairo_t* cr, const Panel& panel, const Mapping& m) {
    struct Entry {
        std::string label;
        Color color;
        bool dashed;
        bool filled;
    };
    std::vector<Entry> entries;
    for (const Band& band : panel.bands) {
        if (!band.label.empty()) {
            entries.push_back({band.label, band.color, false, true});
        }
    }
    for (const Line& line : panel.lines) {
        if (!line.label.empty()) {
            entries.push_back({line.label, line.color, line.dashed, false});
        }
    }
    if (entries.empty()) {
        return;
    }
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, kFontSize);
    double widest = 0.0;
    for (const Entry& entry : entries) {
        cairo_text_extents_t extents;
        cairo_text_extents(cr, entry.label.c_str(), &extents);
        widest = std::max(widest, extents.x_advance);
    }
    const double row = 18.0;
    const double box_w = widest + 46.0;
    const double box_h = row * static_cast<double>(entries.size()) + 8.0;
    const double x = m.area.x + m.area.w - box_w - 8.0;
    const double y = m.area.y + 8.0;
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
    cairo_rectangle(cr, x, y, box_w, box_h);
    cairo_fill(cr);
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const Entry& entry = entries[i];
        const double cy = y + 4.0 + row * (static_cast<double>(i) + 0.5);
        set_color(cr, entry.color);
        if (entry.filled) {
            cairo_rectangle(cr, x + 8.0, cy - 5.0, 24.0, 10.0);
            cairo_fill(cr);
        } else {
            const double dash[] = {6.0, 4.0};
            cairo_set_dash(cr, dash, entry.dashed ? 2 : 0, 0.0);
            cairo_set_line_width(cr, 2.0);
            cairo_move_to(cr, x + 8.0, cy);
            cairo_line_to(cr, x + 32.0, cy);
            cairo_stroke(cr);
            cairo_set_dash(cr, nullptr, 0, 0.0);
        }
        set_color(cr, {0.1, 0.1, 0.1});
        text_at(cr, entry.label, x + 38.0, cy, 0.0, 0.5);
    }
}

// Colour maps, as control points interpolated linearly in RGB.
Color interpolate(const std::vector<Color>& stops, double t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - static_cast<double>(i);
    const Color& a = stops[i];
    const Color& b = stops[i + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), 1.0};
}
// Dark to bright, perceptually ordered (after matplotlib's viridis).
const std::vector<Color> kSequential = {{0.267, 0.005, 0.329},
                                        {0.230, 0.322, 0.546},
                                        {0.128, 0.567, 0.551},
                                        {0.369, 0.789, 0.383},
                                        {0.993, 0.906, 0.144}};
// Blue, white, red (after Moreland's cool-warm).
const std::vector<Color> kDiverging = {
    {0.230, 0.299, 0.754}, {0.865, 0.865, 0.865}, {0.706, 0.016, 0.150}};

// The value a heat-map cell is coloured by.
double colour_value(const HeatMap& map, double value) {
    if (!map.log_scale) {
        return value;
    }
    return value > 0.0 ? std::log10(value) : std::numeric_limits<double>::quiet_NaN();
}

// The colour range [low, high] of a heat map, in colour_value units.
Range colour_range(const HeatMap& map) {
    Range range;
    for (const double value : map.values) {
        range.include(colour_value(map, value));
    }
    if (map.min) {
        range.low = colour_value(map, *map.min);
    }
    if (map.max) {
        range.high = colour_value(map, *map.max);
    }
    if (!range.valid()) {
        range = {0.0, 1.0};
    }
    if (map.diverging && !map.min && !map.max) {
        const double centre = colour_value(map, map.centre);
        const double half = std::max(std::abs(range.low - centre), std::abs(range.high - centre));
        range = {centre - half, centre + half};
    }
    if (range.span() <= 0.0) {
        range = {range.low - 0.5, range.high + 0.5};
    }
    return range;
}

Color cell_colour(const HeatMap& map, const Range& range, double value) {
    const double v = colour_value(map, value);
    if (!std::isfinite(v)) {
        return {0.75, 0.75, 0.75};
    }
    return interpolate(map.diverging ? kDiverging : kSequential, (v - range.low) / range.span());
}

// Ticks of a colour bar, in colour units: on a log scale at 1, 2 and 5 × 10^k (only 10^k when
// that gives enough), otherwise at round numbers.
std::vector<double> colour_bar_ticks(const Range& range, bool log_scale) {
    if (!log_scale) {
        return nice_ticks(range.low, range.high, 5);
    }
    std::vector<double> decades;
    std::vector<double> all;
    for (double k = std::floor(range.low); k <= range.high; k += 1.0) {
        for (const double factor : {1.0, 2.0, 5.0}) {
            const double tick = k + std::log10(factor);
            if (tick >= range.low && tick <= range.high) {
                all.push_back(tick);
                if (factor == 1.0) {
                    decades.push_back(tick);
                }
            }
        }
    }
    return decades.size() >= 3 ? decades : all;
}

// Cells left to right and bottom to top, each value written in its cell, labels under and
// left of the grid, and a colour bar with ticks at the right.
void draw_heat_map(cairo_t* cr, const Panel& panel, const Rect& area) {
    const HeatMap& map = *panel.heat_map;
    const std::size_t columns = std::max<std::size_t>(map.column_labels.size(), 1);
    const std::size_t rows = std::max<std::size_t>(map.row_labels.size(), 1);
    constexpr double kBarGap = 24.0;
    constexpr double kBarWidth = 18.0;
    constexpr double kBarLabels = 80.0;
    const Rect grid{area.x, area.y, area.w - kBarGap - kBarWidth - kBarLabels, area.h};
    const double cell_w = grid.w / static_cast<double>(columns);
    const double cell_h = grid.h / static_cast<double>(rows);
    const Range range = colour_range(map);
    for (std::size_t row = 0; row < rows; ++row) {
        for (std::size_t column = 0; column < columns; ++column) {
            const std::size_t k = row * columns + column;
            const double value =
                k < map.values.size() ? map.values[k] : std::numeric_limits<double>::quiet_NaN();
            const Color colour = cell_colour(map, range, value);
            const double x = grid.x + cell_w * static_cast<double>(column);
            const double y = grid.y + grid.h - cell_h * static_cast<double>(row + 1);
            set_color(cr, colour);
            cairo_rectangle(cr, x, y, cell_w, cell_h);
            cairo_fill(cr);
            if (k < map.cell_text.size()) {
                // Dark text on bright cells, white on dark ones (relative luminance).
                const double luminance = 0.2126 * colour.r + 0.7152 * colour.g + 0.0722 * colour.b;
                set_color(cr, luminance > 0.5 ? Color{0.05, 0.05, 0.05} : Color{1.0, 1.0, 1.0});
                text_at(cr, map.cell_text[k], x + cell_w / 2.0, y + cell_h / 2.0, 0.5, 0.5);
            }
        }
    }
    set_color(cr, {1.0, 1.0, 1.0});
    cairo_set_line_width(cr, 1.0);
    for (std::size_t column = 1; column < columns; ++column) {
        cairo_move_to(cr, grid.x + cell_w * static_cast<double>(column), grid.y);
        cairo_line_to(cr, grid.x + cell_w * static_cast<double>(column), grid.y + grid.h);
    }
    for (std::size_t row = 1; row < rows; ++row) {
        cairo_move_to(cr, grid.x, grid.y + cell_h * static_cast<double>(row));
        cairo_line_to(cr, grid.x + grid.w, grid.y + cell_h * static_cast<double>(row));
    }
    cairo_stroke(cr);
    set_color(cr, {0.15, 0.15, 0.15});
    for (std::size_t column = 0; column < map.column_labels.size(); ++column) {
        text_at(cr, map.column_labels[column],
                grid.x + cell_w * (static_cast<double>(column) + 0.5), grid.y + grid.h + 6.0, 0.5,
                0.0);
    }
    for (std::size_t row = 0; row < map.row_labels.size(); ++row) {
        text_at(cr, map.row_labels[row], grid.x - 6.0,
                grid.y + grid.h - cell_h * (static_cast<double>(row) + 0.5), 1.0, 0.5);
    }
    cairo_rectangle(cr, grid.x, grid.y, grid.w, grid.h);
    cairo_stroke(cr);
    text_at(cr, panel.x_label, grid.x + grid.w / 2.0, grid.y + grid.h + 24.0, 0.5, 0.0);
    cairo_save(cr);
    cairo_translate(cr, grid.x - 62.0, grid.y + grid.h / 2.0);
    cairo_rotate(cr, -M_PI / 2.0);
    text_at(cr, panel.y_label, 0.0, 0.0, 0.5, 0.5);
    cairo_restore(cr);
    text_at(cr, panel.title, grid.x, grid.y - 8.0, 0.0, 1.0, kTitleSize, true);

    // The colour bar: the map from bottom (low) to top (high), ticked in value units.
    const Rect bar{grid.x + grid.w + kBarGap, grid.y, kBarWidth, grid.h};
    constexpr int kBarSteps = 64;
    for (int i = 0; i < kBarSteps; ++i) {
        const double t = (i + 0.5) / kBarSteps;
        set_color(cr, interpolate(map.diverging ? kDiverging : kSequential, t));
        cairo_rectangle(cr, bar.x, bar.y + bar.h * (1.0 - (i + 1.0) / kBarSteps), bar.w,
                        bar.h / kBarSteps + 0.5);
        cairo_fill(cr);
    }
    set_color(cr, {0.15, 0.15, 0.15});
    cairo_rectangle(cr, bar.x, bar.y, bar.w, bar.h);
    cairo_stroke(cr);
    for (const double tick : colour_bar_ticks(range, map.log_scale)) {
        const double y = bar.y + bar.h * (1.0 - (tick - range.low) / range.span());
        cairo_move_to(cr, bar.x + bar.w, y);
        cairo_line_to(cr, bar.x + bar.w + 4.0, y);
        cairo_stroke(cr);
        char label[32];
        std::snprintf(label, sizeof label, "%.3g", map.log_scale ? std::pow(10.0, tick) : tick);
        text_at(cr, label, bar.x + bar.w + 6.0, y, 0.0, 0.5);
    }
    cairo_save(cr);
    cairo_translate(cr, bar.x + bar.w + kBarLabels, bar.y + bar.h / 2.0);
    cairo_rotate(cr, -M_PI / 2.0);
    text_at(cr, map.colour_label, 0.0, 0.0, 0.5, 1.0);
    cairo_restore(cr);
}

void render(cairo_t* cr, const std::string& title, const std::vector<Panel>& panels, int width,
            int height) {
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    set_color(cr, {0.1, 0.1, 0.1});
    text_at(cr, title, width / 2.0, 8.0, 0.5, 0.0, kTitleSize + 2.0, true);
    const double panel_height = (height - kFigureTitleHeight) / static_cast<double>(panels.size());
    for (std::size_t i = 0; i < panels.size(); ++i) {
        const double top = kFigureTitleHeight + panel_height * static_cast<double>(i);
        const Rect area{kMarginLeft, top + kMarginTop, width - kMarginLeft - kMarginRight,
                        panel_height - kMarginTop - kMarginBottom};
        if (panels[i].heat_map) {
            draw_heat_map(cr, panels[i], area);
            continue;
        }
        const Mapping mapping = make_mapping(panels[i], area);
        draw_contents(cr, panels[i], mapping);
        draw_axes(cr, panels[i], mapping);
        draw_legend(cr, panels[i], mapping);
    }
}

void check(cairo_status_t status, const std::string& what) {
    if (status != CAIRO_STATUS_SUCCESS) {
        throw std::runtime_error("cannot write " + what + ": " + cairo_status_to_string(status));
    }
}

}  // namespace

Figure::Figure(std::string title, int rows, int width, int height)
    : title_(std::move(title)),
      panels_(static_cast<std::size_t>(rows)),
      width_(width),
      height_(height) {}

void Figure::write(const std::string& base) const {
    using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
    using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

    // Both files are written whole through AtomicFiles and renamed once both are complete.
    fileio::AtomicFile png(base + ".png");
    SurfacePtr image(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_, height_),
                     cairo_surface_destroy);
    {
        ContextPtr cr(cairo_create(image.get()), cairo_destroy);
        draw(cr.get());
        check(cairo_status(cr.get()), png.path().string());
    }
    std::ostream* png_out = &png.stream();
    check(cairo_surface_write_to_png_stream(image.get(), report::write_to_stream, png_out),
          png.path().string());

    fileio::AtomicFile svg(base + ".svg");
    std::ostream* svg_out = &svg.stream();
    SurfacePtr vector(
        cairo_svg_surface_create_for_stream(report::write_to_stream, svg_out, width_, height_),
        cairo_surface_destroy);
    check(cairo_surface_status(vector.get()), svg.path().string());
    {
        ContextPtr cr(cairo_create(vector.get()), cairo_destroy);
        draw(cr.get());
        check(cairo_status(cr.get()), svg.path().string());
    }
    cairo_surface_finish(vector.get());
    check(cairo_surface_status(vector.get()), svg.path().string());
    png.commit();
    svg.commit();
}

std::string Figure::svg() const {
    using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
    using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

    std::string document;
    const cairo_write_func_t append = [](void* closure, const unsigned char* data,
                                         unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
    };
    SurfacePtr vector(cairo_svg_surface_create_for_stream(append, &document, width_, height_),
                      cairo_surface_destroy);
    check(cairo_surface_status(vector.get()), "SVG of " + title_);
    {
        ContextPtr cr(cairo_create(vector.get()), cairo_destroy);
        draw(cr.get());
        check(cairo_status(cr.get()), "SVG of " + title_);
    }
    cairo_surface_finish(vector.get());
    check(cairo_surface_status(vector.get()), "SVG of " + title_);
    return document;
}

void Figure::draw(cairo_t* cr) const {
    cairo_save(cr);
    cairo_rectangle(cr, 0.0, 0.0, width_, height_);
    cairo_clip(cr);
    render(cr, title_, panels_, width_, height_);
    cairo_restore(cr);
}

}  // namespace legofeup::plot
