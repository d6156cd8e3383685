#include "legofeup/ui/arena/legend_placement.hpp"

#include <QFontMetricsF>
#include <algorithm>

#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"

namespace legofeup::ui {

QStringList legend_texts(const std::vector<LegendRow>& rows) {
    QStringList texts;
    for (const LegendRow& row : rows) {
        for (const LegendEntry& entry : row) {
            texts << entry.text;
        }
    }
    return texts;
}

QString LegendPlacement::tab_text() {
    return arena_text::tr("Legend ◂");
}

QRectF LegendPlacement::place(const std::vector<LegendRow>& rows, bool shown, const QFont& font,
                              const QSizeF& viewport, const QRectF& area, const QRectF& world) {
    texts_ = legend_texts(rows);
    layout_ = {};
    folded_ = false;
    if (!shown || rows.empty()) {
        return area;
    }
    // The legend's box sits corner_inset from the top-right corner. Beside the arena: one
    // column as tall as the widget allows; above it: a strip as wide as the widget, as flat
    // as fits.
    const double inset = kArenaSizes.corner_inset;
    const LegendLayout beside = legend_layout(rows, font, viewport.height() - 2.0 * inset);
    const LegendLayout above =
        legend_layout_within_width(rows, font, viewport.width() - 2.0 * inset);
    // The margin (room for the wall names) is kept between the legend and the arena too.
    const double gap = kArenaSizes.legend_to_arena;
    const QRectF beside_area = area.adjusted(0.0, 0.0, -(beside.size.width() + gap), 0.0);
    const QRectF above_area = area.adjusted(0.0, above.size.height() + gap, 0.0, 0.0);
    const auto fit_scale = [&world](const QRectF& r) {
        if (r.width() <= 0.0 || r.height() <= 0.0) {
            return 0.0;
        }
        return std::min(r.width() / std::max(world.width(), 1e-9),
                        r.height() / std::max(world.height(), 1e-9));
    };
    const bool use_beside = fit_scale(beside_area) >= fit_scale(above_area);
    layout_ = use_beside ? beside : above;
    const QRectF best = use_beside ? beside_area : above_area;
    // A widget too small to give the legend room without shrinking the arena a lot keeps the
    // arena whole and folds the legend into a tab that opens while the mouse is over it.
    folded_ = fit_scale(best) < kArenaSizes.legend_fold_ratio * fit_scale(area);
    if (folded_) {
        layout_ = legend_layout(rows, font, viewport.height() - 2.0 * inset);
        return area;
    }
    return best;
}

bool LegendPlacement::set_open(bool open) {
    if (open == open_) {
        return false;
    }
    open_ = open;
    return true;
}

QRectF LegendPlacement::box(bool shown, double widget_width, const QFont& tab_font) const {
    if (!shown || layout_.empty()) {
        return {};
    }
    const double inset = kArenaSizes.corner_inset;
    if (tab_only()) {
        // The tab: ArenaPainter::corner_text's box for tab_text().
        const QFontMetricsF metrics(tab_font);
        const QSizeF size(
            metrics.horizontalAdvance(tab_text()) + kArenaSizes.corner_box_padding.width(),
            metrics.height() + kArenaSizes.corner_box_padding.height());
        return {QPointF(widget_width - inset - size.width(), inset), size};
    }
    return {QPointF(widget_width - inset - layout_.size.width(), inset), layout_.size};
}

}  // namespace legofeup::ui
