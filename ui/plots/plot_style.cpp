#include "legofeup/ui/plots/plot_style.hpp"

#include <qcustomplot.h>
#include <algorithm>
#include <cmath>
#include <vector>

#include <QFontMetrics>
#include <QPainter>
#include <QPixmap>

namespace legofeup::ui {

namespace {

/// `a` blended towards `b` by `t` in [0, 1].
QColor blend_towards(const QColor& a, const QColor& b, double t) {
    // QColor's components are floats; the blend is worked in double and rounded back once.
    const auto blend = [t](float x, float y) {
        const double from = static_cast<double>(x);
        return static_cast<float>(from + (static_cast<double>(y) - from) * t);
    };
    return QColor::fromRgbF(blend(a.redF(), b.redF()), blend(a.greenF(), b.greenF()),
                            blend(a.blueF(), b.blueF()));
}

QColor with_alpha(QColor colour, int alpha) {
    colour.setAlpha(alpha);
    return colour;
}

/// A filled circle of `diameter` px, antialiased, centred in its pixmap.
QPixmap disc(const QColor& colour, double diameter) {
    const int side = static_cast<int>(std::ceil(diameter)) + 2;
    QPixmap pixmap(side, side);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(colour);
    const double margin = 0.5 * (side - diameter);
    painter.drawEllipse(QRectF(margin, margin, diameter, diameter));
    return pixmap;
}

QFont scaled(const QFont& base, double factor) {
    QFont font = base;
    if (base.pointSizeF() > 0.0) {
        font.setPointSizeF(base.pointSizeF() * factor);
    } else {
        font.setPixelSize(std::max(1, static_cast<int>(std::lround(base.pixelSize() * factor))));
    }
    return font;
}

void style_axis(QCPAxis& axis, const PlotLook& look) {
    const QPen pen(look.text, 1.0);
    axis.setBasePen(pen);
    axis.setTickPen(pen);
    axis.setSubTickPen(pen);
    axis.setTickLabelColor(look.text);
    axis.setLabelColor(look.text);
    axis.setTickLabelFont(look.font);
    axis.setLabelFont(look.font);
    axis.grid()->setPen(QPen(look.grid, 1.0, Qt::DotLine));
    axis.grid()->setSubGridPen(QPen(look.sub_grid, 1.0, Qt::DotLine));
    axis.grid()->setZeroLinePen(QPen(look.grid, 1.0));
}

}  // namespace

PlotLook plot_look(const QPalette& palette, const QFont& base, double text_scale) {
    PlotLook look;
    look.background = palette.color(QPalette::Base);
    look.text = palette.color(QPalette::WindowText);
    look.grid = blend_towards(look.background, look.text, 0.30);
    look.sub_grid = blend_towards(look.background, look.text, 0.14);
    look.legend_background = with_alpha(look.background, 215);
    const bool dark = look.background.lightnessF() < 0.5F;
    // Blue, vermilion, green, purple, teal: saturated shades on white, pale ones on black.
    if (dark) {
        look.series = {QColor(0x6e, 0xb6, 0xff), QColor(0xff, 0x8a, 0x5c), QColor(0x7f, 0xd8, 0x7f),
                       QColor(0xd6, 0x9c, 0xf2), QColor(0x4d, 0xd6, 0xe6)};
    } else {
        look.series = {QColor(0x15, 0x5f, 0xc0), QColor(0xd0, 0x3b, 0x0a), QColor(0x1e, 0x7d, 0x32),
                       QColor(0x7b, 0x1f, 0xa2), QColor(0x00, 0x79, 0x86)};
    }
    const double scale = std::clamp(text_scale, 0.5, 4.0);
    look.font = scaled(base, scale);
    look.small_font = scaled(base, 0.92 * scale);
    look.title_font = scaled(base, 1.05 * scale);
    look.title_font.setBold(true);
    look.line_width = 1.5 * std::sqrt(scale);
    return look;
}

void apply_look(QCustomPlot& plot, const PlotLook& look) {
    plot.setBackground(QBrush(look.background));
    plot.axisRect()->setBackground(Qt::NoBrush);
    // The same left margin on every plot (wide enough for "−0.025" and the axis label), so
    // the time axes of stacked plots line up.
    const QFontMetrics metrics(look.font);
    plot.axisRect()->setMinimumMargins(QMargins(
        metrics.horizontalAdvance(QStringLiteral("−0.025")) + metrics.height() + 24, 0, 0, 0));
    for (QCPAxis* axis : plot.axisRect()->axes()) {
        style_axis(*axis, look);
    }
    plot.legend->setBrush(QBrush(look.legend_background));
    plot.legend->setBorderPen(Qt::NoPen);
    plot.legend->setTextColor(look.text);
    plot.legend->setFont(look.small_font);
    for (QCPLayoutElement* element : plot.plotLayout()->elements(true)) {
        if (auto* title = qobject_cast<QCPTextElement*>(element)) {
            title->setTextColor(look.text);
            title->setFont(look.title_font);
        }
    }
    // Reference lines (χ² bounds, the IR range) and their labels.
    for (int i = 0; i < plot.itemCount(); ++i) {
        QCPAbstractItem* item = plot.item(i);
        if (auto* line = qobject_cast<QCPItemStraightLine*>(item)) {
            line->setPen(QPen(blend_towards(look.background, look.text, 0.75), look.line_width,
                              Qt::DashLine));
        } else if (auto* label = qobject_cast<QCPItemText*>(item)) {
            label->setColor(look.text);
            label->setFont(look.small_font);
            label->setBrush(QBrush(look.legend_background));
        }
    }
}

void add_header(QCustomPlot& plot, const QString& title) {
    plot.plotLayout()->insertRow(0);
    auto* header = new QCPLayoutGrid;
    plot.plotLayout()->addElement(0, 0, header);
    plot.plotLayout()->setRowStretchFactor(0, 0.001);
    plot.plotLayout()->setRowSpacing(0);
    header->setColumnSpacing(12);
    header->setMinimumMargins(QMargins(0, 3, 6, 0));  // off the widget's top and right edges
    auto* label = new QCPTextElement(&plot, title);
    label->setTextFlags(Qt::AlignLeft | Qt::AlignVCenter);
    label->setMargins(QMargins(8, 4, 8, 0));
    header->addElement(0, 0, label);
    plot.legend->setVisible(true);
    plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot.legend->setMargins(QMargins(4, 2, 4, 2));
    plot.legend->setRowSpacing(0);
    plot.legend->setColumnSpacing(10);
    header->addElement(0, 1, plot.legend);
    header->setColumnStretchFactors({1.0, 0.001});
}

void fit_legend(QCustomPlot& plot, int width) {
    QCPLegend& legend = *plot.legend;
    // The entries' widths (a wrapped legend's grid also has empty cells).
    std::vector<int> widths;
    for (int i = 0; i < legend.itemCount(); ++i) {
        if (const QCPLayoutElement* item = legend.item(i)) {
            widths.push_back(item->minimumOuterSizeHint().width());
        }
    }
    const auto count = static_cast<int>(widths.size());
    if (count == 0) {
        return;
    }
    int available = width - legend.margins().left() - legend.margins().right() - 16;
    for (QCPLayoutElement* element : plot.plotLayout()->elements(true)) {
        if (auto* title = qobject_cast<QCPTextElement*>(element)) {
            available -=
                static_cast<const QCPLayoutElement*>(title)->minimumOuterSizeHint().width();
        }
    }
    // The most entries per row whose columns (as wide as their widest entry) fit.
    int wrap = count;
    for (; wrap > 1; --wrap) {
        int total = legend.columnSpacing() * (wrap - 1);
        for (int column = 0; column < wrap; ++column) {
            int widest = 0;
            for (int i = column; i < count; i += wrap) {
                widest = std::max(widest, widths[static_cast<std::size_t>(i)]);
            }
            total += widest;
        }
        if (total <= available) {
            break;
        }
    }
    if (legend.wrap() != wrap || legend.columnCount() != std::min(wrap, count)) {
        legend.setWrap(wrap);
        legend.setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
    }
}

void apply_look(QCPGraph& graph, const SeriesDefinition& series, const PlotLook& look) {
    const QColor colour = look.series[static_cast<std::size_t>(series.colour)];
    graph.setScatterStyle(QCPScatterStyle());
    graph.setLineStyle(QCPGraph::lsLine);
    graph.setBrush(Qt::NoBrush);
    switch (series.look) {
        case SeriesLook::Line:
            graph.setPen(QPen(colour, look.line_width));
            break;
        case SeriesLook::ThinLine:
            graph.setPen(QPen(with_alpha(colour, 170), std::max(1.0, 0.6 * look.line_width)));
            break;
        case SeriesLook::Points:
            // A pre-rendered disc: thousands of antialiased ellipses would take ~50 ms.
            graph.setPen(QPen(colour, 1.0));
            graph.setLineStyle(QCPGraph::lsNone);
            graph.setScatterStyle(QCPScatterStyle(disc(colour, 2.5 * look.line_width)));
            break;
        case SeriesLook::BandEdge:
            graph.setPen(QPen(with_alpha(colour, 110), 1.0));
            break;
        case SeriesLook::Band:
            graph.setPen(QPen(with_alpha(colour, 110), 1.0));
            graph.setBrush(QBrush(with_alpha(colour, 48)));
            break;
    }
}

}  // namespace legofeup::ui
