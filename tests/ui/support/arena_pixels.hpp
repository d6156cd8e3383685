#pragma once
// Showing an ArenaView and reading what it drew: its picture as ARGB32, and how close the
// pixels around a point come to a colour (for "the scan is drawn there in cyan" checks).

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "legofeup/ui/arena/arena_view.hpp"

namespace legofeup::ui::testing {

/// Shows `view` at `size` and fits the arena into it.
inline void show_fitted(ArenaView& view, QSize size) {
    view.resize(size);
    view.show();
    if (!QTest::qWaitForWindowExposed(&view)) {
        qWarning("window not exposed");
    }
    view.fitArena();
}

inline QImage render(ArenaView& view) {
    return view.grab().toImage().convertToFormat(QImage::Format_ARGB32);
}

/// The smallest colour distance (largest channel difference) to `target` among the pixels
/// within 1 px of `point` (widget coordinates; the image may be at a device pixel ratio).
inline int nearest_colour_distance(const QImage& image, const QPointF& point,
                                   const QColor& target) {
    const double ratio = image.devicePixelRatio();
    int best = 1000;
    for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
            const QPoint p(static_cast<int>(std::floor(point.x() * ratio)) + dx,
                           static_cast<int>(std::floor(point.y() * ratio)) + dy);
            if (!image.rect().contains(p)) {
                continue;
            }
            const QColor c = image.pixelColor(p);
            best = std::min(best, std::max({std::abs(c.red() - target.red()),
                                            std::abs(c.green() - target.green()),
                                            std::abs(c.blue() - target.blue())}));
        }
    }
    return best;
}

}  // namespace legofeup::ui::testing
