#pragma once
// Small conversions the arena's painters share (private to ui/arena).
#include <QColor>
#include <QPointF>
#include <cmath>

#include "legofeup/core/state.hpp"

namespace legofeup::ui::arena_drawing {

inline QColor with_alpha(QColor color, int alpha) {
    color.setAlpha(alpha);
    return color;
}

inline QPointF to_point(const Vector2& v) {
    return {v.x(), v.y()};
}

/// The state's position is finite (a diverged filter's is not: nothing to draw there).
inline bool finite_position(const StateVector& x) {
    return std::isfinite(x(kX)) && std::isfinite(x(kY));
}

}  // namespace legofeup::ui::arena_drawing
