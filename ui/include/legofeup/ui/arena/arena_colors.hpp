#pragma once
// The arena view's colours, derived from the widget's palette so that the view works in
// light and dark themes: background and foreground come from the palette, and each series
// has a darker shade for light backgrounds and a lighter one for dark backgrounds. The faint
// colours (grid, path, trail) are opaque mixes with the background rather than translucent:
// the raster engine draws long opaque lines several times faster than blended ones.

#include <QColor>
#include <QPalette>

namespace legofeup::ui {

struct ArenaColors {
    bool dark = false;     ///< the background is dark
    QColor background;     ///< the canvas (palette Base)
    QColor foreground;     ///< walls, text (the palette's text colour that contrasts most)
    QColor grid;           ///< faint 0.5 m grid
    QColor path;           ///< the intended path
    QColor truth;          ///< the real robot and its path
    QColor estimate;       ///< the filter's estimate and its path
    QColor odometry;       ///< odometry-only dead reckoning
    QColor ellipse;        ///< covariance ellipses
    QColor trail;          ///< past ellipses: the ellipse colour faded into the background
    QColor associated;     ///< IR rays used by an update, and the wall they were matched to
    QColor rejected;       ///< IR rays measured but not used
    QColor out_of_range;   ///< IR rays that saw nothing within range
    QColor beacon;         ///< bearing-only beacons (paper 002) and their ids
    QColor shadow;         ///< the other filter kind's estimate run beside it (EKF vs UKF)
    QColor map_occupied;   ///< an occupancy grid's occupied cells (paper 001)
    QColor map_unknown;    ///< its unknown cells (free ones show the floor)
    QColor filter_map;     ///< the laser filter's own map when it is not the world's
    QColor expected_scan;  ///< the scan the filter expected (ray-cast in its map)
    QColor truth_scan;     ///< the measured scan placed at the true pose
    QColor particles;      ///< the particle filter's cloud (drawn at the weight's opacity)
    QColor label_background;
};

ArenaColors arena_colors(const QPalette& palette);

/// `a` mixed with `b`: a·t + b·(1 − t), opaque.
QColor mix(const QColor& a, const QColor& b, double t);

/// WCAG contrast ratio of two colours (1 … 21).
double contrast_ratio(const QColor& a, const QColor& b);

}  // namespace legofeup::ui
