#pragma once
// Where the arena's legend goes: in the top-right corner, beside the fitted arena or above
// it (whichever leaves the arena larger), in as many columns as that needs; folded into a
// "Legend ◂" tab when the widget is too small for both, the tab opening the whole legend
// while the mouse is over it.

#include <QFont>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <QStringList>
#include <vector>

#include "legofeup/ui/arena/arena_legend.hpp"

namespace legofeup::ui {

class LegendPlacement {
  public:
    /// Lays `rows` out for a widget of `viewport` size in which the arena, `world` (metres),
    /// would be fitted into `area` without a legend; returns the area it is fitted into with
    /// the legend. Without `shown` (or rows) the legend takes no room.
    QRectF place(const std::vector<LegendRow>& rows, bool shown, const QFont& font,
                 const QSizeF& viewport, const QRectF& area, const QRectF& world);

    const LegendLayout& layout() const { return layout_; }
    /// The texts of the rows last placed (shown or not), row by row.
    const QStringList& texts() const { return texts_; }
    /// There was no room: the legend is a tab.
    bool folded() const { return folded_; }
    bool open() const { return open_; }
    /// Opens or closes a folded legend; false when it already was so.
    bool set_open(bool open);
    /// Only the tab is drawn: folded and not open.
    bool tab_only() const { return folded_ && !open_; }

    /// The legend's box in widget pixels (the tab's when tab_only(), its text in
    /// `tab_font`); empty when not shown.
    QRectF box(bool shown, double widget_width, const QFont& tab_font) const;
    /// "Legend ◂", the tab's text.
    static QString tab_text();

  private:
    LegendLayout layout_;
    QStringList texts_;
    bool folded_ = false;
    bool open_ = false;
};

/// The legend's texts, row by row and left to right.
QStringList legend_texts(const std::vector<LegendRow>& rows);

}  // namespace legofeup::ui
