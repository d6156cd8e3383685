#pragma once
// The arena view's drawing, one layer per call. World layers are drawn through the
// world → widget transform with cosmetic pens (widths in device-independent pixels, so lines
// stay thin at any zoom and any device pixel ratio); text and overlays are drawn in widget
// pixels so they are never mirrored or scaled by the zoom.

#include <QFont>
#include <QImage>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QString>
#include <QTransform>
#include <vector>

#include "legofeup/core/beacons.hpp"
#include "legofeup/core/loop_snapshot.hpp"
#include "legofeup/core/walls.hpp"
#include "legofeup/ui/arena/arena_cache.hpp"
#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_legend.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"

namespace legofeup::ui {

struct ArenaStyle {
    ArenaColors colors;
    QFont font;               ///< labels, already scaled by the text scale
    QFont legend_font;        ///< the legend (grows more slowly than the labels)
    double line_scale = 1.0;  ///< multiplies every line width (projector mode)
};

/// The robot's footprint for drawing (the LEGO NXT robot of the paper), metres.
struct RobotOutline {
    static constexpr double kAhead = 0.106;  ///< chassis ahead of the axle
    static constexpr double kLength = 0.21;  ///< whole chassis
    static constexpr double kWidth = 0.16;   ///< including the wheels
    static constexpr double kWheelRadius = 0.028;
};

class ArenaPainter {
  public:
    ArenaPainter(QPainter& painter, const QTransform& world_to_widget, const ArenaStyle& style);

    // World layers.
    void grid(const QRectF& visible_world, double spacing);
    /// An occupancy-grid map's picture (map_image.hpp), cells drawn crisp.
    void map(const QImage& image, const QTransform& image_to_world);
    void intended_path(const QPainterPath& path);
    void walls(const std::vector<Wall>& walls, int highlighted);
    /// The trail of past ellipses, all in one path.
    void trail(const QPainterPath& trail);
    void polyline(const QPolygonF& points, const QColor& color, double width);
    /// The chassis outline with its heading; `ghost` draws it faint and dashed.
    void robot(const Pose2& pose, const IrMount& mount, const QColor& color, bool ghost);
    void ir_rays(const LoopSnapshot& snapshot, const IrMount& mount, double max_range);
    void ellipse(const CovarianceEllipse& ellipse);
    /// The estimate: a dot and an arrow along its heading.
    void estimate_marker(const Pose2& pose);
    /// The same marker in another colour (the pose being picked for a kidnapping).
    void pose_marker(const Pose2& pose, const QColor& color) { heading_marker(pose, color); }

    // The further lessons' layers (arena_painter_lessons.cpp).
    /// Each beacon: a filled diamond and its id.
    void beacons(const BeaconMap& beacons);
    /// This step's bearings from the estimated pose: the measured one along θ̂ + z (solid,
    /// coloured as the IR rays: applied or not), the expected one along θ̂ + h(X̂) (faint,
    /// dashed). Each is drawn a little past the distance to its beacon.
    void beacon_rays(const LoopSnapshot& snapshot, const BeaconMap& beacons);
    /// The other filter kind's estimate: its ellipse (dashed) and its heading arrow.
    void shadow_estimate(const Pose2& pose, const CovarianceEllipse& ellipse);
    /// Laser scan points (world coordinates) as dots `diameter` px wide (arena_painter_laser.cpp).
    void scan_points(const QPolygonF& points, const QColor& color, double diameter);

    // Widget-pixel layers.
    void wall_names(const std::vector<Wall>& walls, const QRectF& arena);
    /// A text in a box whose bottom-left corner is at `anchor` (kept inside the widget).
    void label(const QPointF& anchor, const QString& text, const QColor& color);
    /// The legend's rows in `layout`, its box's top-right corner at `top_right`
    /// (arena_legend.cpp).
    void legend(const std::vector<LegendRow>& rows, const LegendLayout& layout,
                const QPointF& top_right);
    void scale_bar(double pixels_per_metre, const QRectF& widget);
    void corner_text(const QString& text, const QRectF& widget, Qt::Alignment corner);
    /// A text in a box at the bottom centre (what a mode such as kidnapping expects), clear
    /// of the legend (top right) and the scale bar (bottom left) in a wide enough arena.
    void banner(const QString& text, const QRectF& widget);
    void centred_text(const QString& text, const QRectF& widget);

  private:
    /// One swatch from `left` to `right` (its vertical middle), for rows `line_height` tall.
    void legend_swatch(const LegendEntry& entry, const QPointF& left, const QPointF& right,
                       double line_height);
    void heading_marker(const Pose2& pose, const QColor& color);
    QPen pen(const QColor& color, double width, Qt::PenStyle style = Qt::SolidLine) const;
    void use_world();
    void use_widget();

    QPainter& painter_;
    QTransform world_to_widget_;
    const ArenaStyle& style_;
};

/// A bearing drawn from a pose: from (x, y) along θ + bearing, `length` metres.
struct BearingRay {
    Vector2 from = Vector2::Zero();
    Vector2 to = Vector2::Zero();
};
BearingRay bearing_ray(const Pose2& pose, double bearing, double length);

/// How long a beacon's rays are drawn from `pose`: 15 % past the beacon, so a ray that
/// misses it shows by how much (at least 0.1 m).
double beacon_ray_length(const Pose2& pose, const Beacon& beacon);

/// A "nice" scale-bar length (1, 2 or 5 × 10ⁿ metres) close to `target_pixels` long.
double scale_bar_length(double pixels_per_metre, double target_pixels);

}  // namespace legofeup::ui
