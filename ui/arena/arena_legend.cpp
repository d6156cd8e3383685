#include "legofeup/ui/arena/arena_legend.hpp"

#include <QFontMetricsF>
#include <QStringList>
#include <algorithm>
#include <numeric>

#include "arena_drawing.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::with_alpha;

QStringList lines_of(const QString& text) {
    return text.split(QLatin1Char('\n'));
}

double text_width(const QString& text, const QFontMetricsF& metrics) {
    double width = 0.0;
    for (const QString& line : lines_of(text)) {
        width = std::max(width, metrics.horizontalAdvance(line));
    }
    return width;
}

double entry_width(const LegendEntry& entry, const QFontMetricsF& metrics, const LegendMetrics& m) {
    const double swatch = entry.swatch == LegendEntry::Swatch::None ? 0.0 : m.swatch + m.gap;
    return swatch + text_width(entry.text, metrics);
}

double row_height(const LegendRow& row, const LegendMetrics& m) {
    qsizetype lines = 1;
    for (const LegendEntry& entry : row) {
        lines = std::max(lines, lines_of(entry.text).size());
    }
    return m.line * static_cast<double>(lines);
}

}  // namespace

LegendMetrics legend_metrics(const QFont& font) {
    const QFontMetricsF metrics(font);
    LegendMetrics m;
    m.line = metrics.height() * 1.3;
    m.swatch = metrics.height() * 1.8;
    return m;
}

double legend_row_width(const LegendRow& row, const QFont& font) {
    const QFontMetricsF metrics(font);
    const LegendMetrics m = legend_metrics(font);
    double width = 0.0;
    for (const LegendEntry& entry : row) {
        width += entry_width(entry, metrics, m);
    }
    return width + m.entry_gap * static_cast<double>(std::max<std::size_t>(row.size(), 1) - 1)
           + 2.0;
}

LegendLayout legend_layout(const std::vector<LegendRow>& rows, const QFont& font,
                           double max_height) {
    LegendLayout layout;
    if (rows.empty()) {
        return layout;
    }
    const LegendMetrics m = legend_metrics(font);
    const double room = max_height - 2.0 * m.pad;  // for the rows of one column
    double column_height = 0.0;
    double tallest = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const double height = row_height(rows[i], m);
        const double width = legend_row_width(rows[i], font);
        layout.row_heights.push_back(height);
        if (layout.column_starts.empty()
            || (column_height > 0.0 && column_height + height > room)) {
            layout.column_starts.push_back(i);
            layout.column_widths.push_back(0.0);
            column_height = 0.0;
        }
        column_height += height;
        tallest = std::max(tallest, column_height);
        layout.column_widths.back() = std::max(layout.column_widths.back(), width);
    }
    const double widths =
        std::accumulate(layout.column_widths.begin(), layout.column_widths.end(), 0.0);
    layout.size =
        QSizeF(2.0 * m.pad + widths + m.column_gap * static_cast<double>(layout.columns() - 1),
               2.0 * m.pad + tallest);
    return layout;
}

LegendLayout legend_layout_within_width(const std::vector<LegendRow>& rows, const QFont& font,
                                        double max_width) {
    if (rows.empty()) {
        return {};
    }
    const LegendMetrics m = legend_metrics(font);
    // From one row per column upwards, one line at a time: the first layout that fits the
    // width is the least tall one.
    double total = 0.0;
    double tallest_row = 0.0;
    for (const LegendRow& row : rows) {
        const double height = row_height(row, m);
        total += height;
        tallest_row = std::max(tallest_row, height);
    }
    for (double height = tallest_row; height < total + m.line; height += m.line) {
        LegendLayout layout = legend_layout(rows, font, height + 2.0 * m.pad + 0.5);
        if (layout.size.width() <= max_width || layout.columns() == 1) {
            return layout;
        }
    }
    return legend_layout(rows, font, total + 2.0 * m.pad + 1.0);
}

// ---- painting ---------------------------------------------------------------------------

void ArenaPainter::legend_swatch(const LegendEntry& entry, const QPointF& left,
                                 const QPointF& right, double line_height) {
    const double middle = left.y();
    const QPointF centre((left.x() + right.x()) / 2.0, middle);
    const double width = right.x() - left.x();
    painter_.setBrush(Qt::NoBrush);
    switch (entry.swatch) {
        case LegendEntry::Swatch::None:
            break;
        case LegendEntry::Swatch::Line:
            painter_.setPen(pen(entry.color, 2.0));
            painter_.drawLine(left, right);
            break;
        case LegendEntry::Swatch::Dashed:
            painter_.setPen(pen(entry.color, 1.5, Qt::DashLine));
            painter_.drawLine(left, right);
            break;
        case LegendEntry::Swatch::Ellipse:
            painter_.setPen(pen(entry.color, 1.5));
            painter_.setBrush(with_alpha(entry.color, 45));
            painter_.drawEllipse(centre, width / 2.0, line_height * 0.32);
            break;
        case LegendEntry::Swatch::DashedEllipse:
            painter_.setPen(pen(entry.color, 1.5, Qt::DashLine));
            painter_.setBrush(with_alpha(entry.color, 30));
            painter_.drawEllipse(centre, width / 2.0, line_height * 0.32);
            break;
        case LegendEntry::Swatch::Diamond: {
            const double h = line_height * 0.3;
            QPolygonF diamond;
            diamond << centre + QPointF(0.0, -h) << centre + QPointF(h, 0.0)
                    << centre + QPointF(0.0, h) << centre + QPointF(-h, 0.0);
            painter_.setPen(Qt::NoPen);
            painter_.setBrush(entry.color);
            painter_.drawPolygon(diamond);
            break;
        }
        case LegendEntry::Swatch::Band: {
            QPen band = pen(with_alpha(entry.color, 140), 8.0);
            band.setCapStyle(Qt::FlatCap);
            painter_.setPen(band);
            painter_.drawLine(left, right);
            QPen wall_pen = pen(style_.colors.foreground, 3.0);
            wall_pen.setCapStyle(Qt::FlatCap);
            painter_.setPen(wall_pen);
            painter_.drawLine(left, right);
            break;
        }
        case LegendEntry::Swatch::Dots: {
            // A few scan points along a slight curve, as a scan draws them.
            QPen dot = pen(entry.color, 3.5);
            dot.setCapStyle(Qt::RoundCap);
            painter_.setPen(dot);
            for (int i = 0; i < 5; ++i) {
                const double t = (i + 0.5) / 5.0;
                const double bend = 0.18 * line_height * (1.0 - 4.0 * (t - 0.5) * (t - 0.5));
                painter_.drawPoint(QPointF(left.x() + t * width, middle + bend));
            }
            break;
        }
        case LegendEntry::Swatch::Box: {
            const double h = line_height * 0.55;
            painter_.setPen(pen(with_alpha(style_.colors.foreground, 90), 1.0));
            painter_.setBrush(entry.color);
            painter_.drawRect(QRectF(centre - QPointF(h / 2.0, h / 2.0), QSizeF(h, h)));
            break;
        }
    }
}

void ArenaPainter::legend(const std::vector<LegendRow>& rows, const LegendLayout& layout,
                          const QPointF& top_right) {
    if (rows.empty() || layout.row_heights.size() != rows.size()) {
        return;
    }
    use_widget();
    painter_.setFont(style_.legend_font);
    const QFontMetricsF metrics(style_.legend_font);
    const LegendMetrics m = legend_metrics(style_.legend_font);
    const QRectF box(top_right - QPointF(layout.size.width(), 0.0), layout.size);
    painter_.setPen(pen(with_alpha(style_.colors.foreground, 70), 1.0));
    painter_.setBrush(style_.colors.label_background);
    painter_.drawRoundedRect(box, 4.0, 4.0);

    double x = box.left() + m.pad;
    for (std::size_t column = 0; column < layout.columns(); ++column) {
        const std::size_t end =
            column + 1 < layout.columns() ? layout.column_starts[column + 1] : rows.size();
        double y = box.top() + m.pad;
        for (std::size_t r = layout.column_starts[column]; r < end; ++r) {
            double cursor = x;
            for (const LegendEntry& entry : rows[r]) {
                const double middle = y + m.line / 2.0;
                if (entry.swatch != LegendEntry::Swatch::None) {
                    legend_swatch(entry, QPointF(cursor, middle),
                                  QPointF(cursor + m.swatch, middle), m.line);
                    cursor += m.swatch + m.gap;
                }
                painter_.setPen(style_.colors.foreground);
                double line_y = y;
                double width = 0.0;
                for (const QString& line : lines_of(entry.text)) {
                    const double advance = metrics.horizontalAdvance(line);
                    painter_.drawText(QRectF(cursor, line_y, advance + 2.0, m.line),
                                      Qt::AlignLeft | Qt::AlignVCenter, line);
                    width = std::max(width, advance);
                    line_y += m.line;
                }
                cursor += width + m.entry_gap;
            }
            y += layout.row_heights[r];
        }
        x += layout.column_widths[column] + m.column_gap;
    }
    painter_.setFont(style_.font);
}

}  // namespace legofeup::ui
