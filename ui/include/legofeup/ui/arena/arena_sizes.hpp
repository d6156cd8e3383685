#pragma once
// Every size the arena view lays itself out with, in one table. Lengths are device-independent
// pixels unless the field says otherwise; "× line scale" marks a size that grows with the
// projector mode's line scale (ArenaStyle::line_scale), the others stay as they are.

#include <QSize>
#include <QSizeF>

namespace legofeup::ui {

struct ArenaSizes {
    // ---- the widget ---------------------------------------------------------------------
    QSize preferred{640, 560};
    QSize minimum{240, 200};
    double min_text_scale = 0.5;  ///< projector mode's text scale, lowest
    double max_text_scale = 4.0;  ///< and highest
    /// Lines grow this share as fast as the text (1 + growth·(text scale − 1)).
    double line_growth = 0.5;

    // ---- the camera ---------------------------------------------------------------------
    double zoom_step = 1.25;  ///< factor per wheel notch and per zoom in / out
    /// The grid's lines at least this far apart (the spacing steps up 0.5, 1, 2, 5 … m).
    double min_grid_spacing = 24.0;

    // ---- fitting the arena and its legend ------------------------------------------------
    /// Kept free around the fitted arena (for the wall names: this plus their text's line).
    double fit_margin = 16.0;
    double wall_name_font = 0.85;   ///< the wall names' font, × the labels' font size
    double wall_name_lines = 1.4;   ///< lines of wall-name text kept free outside the walls
    double corner_inset = 10.0;     ///< the legend, its tab and corner texts from the edges
    double legend_to_arena = 10.0;  ///< between the legend's box and the arena's margin
    /// The legend folds into a tab when giving it room would leave the arena less than this
    /// share of the scale it has without it.
    double legend_fold_ratio = 0.7;
    QSizeF corner_box_padding{12.0, 6.0};  ///< a corner text's box (and the tab) beyond its text

    // ---- labels at the estimate -----------------------------------------------------------
    double label_clearance = 18.0;  ///< × line scale: the least radius a label keeps clear
    double robot_clearance = 0.6;   ///< share of the robot's length a label keeps clear (m/m)
    double label_reach = 0.75;      ///< a label's corner at this share of the radius …
    double label_offset = 6.0;      ///< … plus this, diagonally away from the estimate
    /// The other filter's name: this much further left than its own width, and lower than
    /// its height, so it sits below-left of its estimate.
    QSizeF shadow_label_offset{8.0, 4.0};

    // ---- the laser lesson -------------------------------------------------------------------
    QSizeF status_padding{8.0, 4.0};   ///< the scan matching's status box beyond its text
    double status_below_legend = 6.0;  ///< the status under a legend strip across the top
    double scan_dot = 3.0;             ///< × line scale: a measured or expected scan's dots
    double truth_scan_dot = 2.5;       ///< × line scale: the scan at the true pose's dots

    // ---- the particle filter -------------------------------------------------------------------
    double particle_dot = 3.0;  ///< × line scale: one particle of the cloud

    // ---- kidnapping ---------------------------------------------------------------------------
    double pick_drag = 8.0;  ///< a drag at least this long aims the robot; less is a click
};

inline constexpr ArenaSizes kArenaSizes{};

}  // namespace legofeup::ui
