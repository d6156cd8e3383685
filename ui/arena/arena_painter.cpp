#include "legofeup/ui/arena/arena_painter.hpp"

#include <QFontMetricsF>
#include <algorithm>
#include <cmath>

#include "arena_drawing.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/core/ir_geometry.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::to_point;
using arena_drawing::with_alpha;

QString length_text(double metres) {
    if (metres >= 0.1) {
        return QStringLiteral("%1 m").arg(metres, 0, 'g', 3);
    }
    if (metres >= 0.01) {
        return QStringLiteral("%1 cm").arg(metres * 100.0, 0, 'g', 3);
    }
    return QStringLiteral("%1 mm").arg(metres * 1000.0, 0, 'g', 3);
}

}  // namespace

double scale_bar_length(double pixels_per_metre, double target_pixels) {
    if (!(pixels_per_metre > 0.0) || !(target_pixels > 0.0)) {
        return 0.0;
    }
    const double raw = target_pixels / pixels_per_metre;  // metres
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    double best = decade;
    for (const double step : {1.0, 2.0, 5.0, 10.0}) {
        if (std::abs(std::log(step * decade / raw)) < std::abs(std::log(best / raw))) {
            best = step * decade;
        }
    }
    return best;
}

ArenaPainter::ArenaPainter(QPainter& painter, const QTransform& world_to_widget,
                           const ArenaStyle& style)
    : painter_(painter), world_to_widget_(world_to_widget), style_(style) {
    painter_.setFont(style_.font);
}

QPen ArenaPainter::pen(const QColor& color, double width, Qt::PenStyle style) const {
    QPen result(color, width * style_.line_scale, style, Qt::RoundCap, Qt::RoundJoin);
    result.setCosmetic(true);
    return result;
}

void ArenaPainter::use_world() {
    painter_.setTransform(world_to_widget_);
}

void ArenaPainter::use_widget() {
    painter_.resetTransform();
}

void ArenaPainter::grid(const QRectF& visible_world, double spacing) {
    if (!(spacing > 0.0)) {
        return;
    }
    const double first_x = std::ceil(visible_world.left() / spacing);
    const double last_x = std::floor(visible_world.right() / spacing);
    const double first_y = std::ceil(visible_world.top() / spacing);
    const double last_y = std::floor(visible_world.bottom() / spacing);
    if (last_x - first_x > 200.0 || last_y - first_y > 200.0) {
        return;  // too dense to help
    }
    use_world();
    painter_.setRenderHint(QPainter::Antialiasing, false);
    QPen grid_pen(style_.colors.grid, 1.0);
    grid_pen.setCosmetic(true);
    painter_.setPen(grid_pen);
    for (double i = first_x; i <= last_x; i += 1.0) {
        painter_.drawLine(QPointF(i * spacing, visible_world.top()),
                          QPointF(i * spacing, visible_world.bottom()));
    }
    for (double j = first_y; j <= last_y; j += 1.0) {
        painter_.drawLine(QPointF(visible_world.left(), j * spacing),
                          QPointF(visible_world.right(), j * spacing));
    }
    painter_.setRenderHint(QPainter::Antialiasing, true);
}

void ArenaPainter::map(const QImage& image, const QTransform& image_to_world) {
    if (image.isNull()) {
        return;
    }
    painter_.setTransform(image_to_world * world_to_widget_);
    // Nearest-neighbour: each cell a crisp square at any zoom.
    painter_.setRenderHint(QPainter::SmoothPixmapTransform, false);
    painter_.drawImage(QPointF(0.0, 0.0), image);
}

void ArenaPainter::intended_path(const QPainterPath& path) {
    if (path.isEmpty()) {
        return;
    }
    use_world();
    painter_.setBrush(Qt::NoBrush);
    // One pixel (at normal line scale) keeps the dashes on the raster engine's fast path.
    painter_.setPen(pen(style_.colors.path, 1.0, Qt::DashLine));
    painter_.drawPath(path);
}

void ArenaPainter::walls(const std::vector<Wall>& walls, int highlighted) {
    use_world();
    if (highlighted >= 0 && highlighted < static_cast<int>(walls.size())) {
        // The wall matched by this step's update: a wide band under the wall itself.
        const Wall& wall = walls[static_cast<std::size_t>(highlighted)];
        QPen band = pen(with_alpha(style_.colors.associated, 140), 12.0);
        band.setCapStyle(Qt::FlatCap);
        painter_.setPen(band);
        painter_.drawLine(to_point(wall.start), to_point(wall.end));
    }
    QPen wall_pen = pen(style_.colors.foreground, 4.0);
    wall_pen.setCapStyle(Qt::SquareCap);
    painter_.setPen(wall_pen);
    for (const Wall& wall : walls) {
        painter_.drawLine(to_point(wall.start), to_point(wall.end));
    }
}

void ArenaPainter::trail(const QPainterPath& trail) {
    if (trail.isEmpty()) {
        return;
    }
    use_world();
    painter_.setBrush(Qt::NoBrush);
    // One pixel wide: the raster engine's fast path for thin cosmetic lines, and one call for
    // every ellipse.
    QPen trail_pen(style_.colors.trail, 1.0);
    trail_pen.setCosmetic(true);
    painter_.setPen(trail_pen);
    painter_.drawPath(trail);
}

void ArenaPainter::polyline(const QPolygonF& points, const QColor& color, double width) {
    if (points.size() < 2) {
        return;
    }
    use_world();
    painter_.setPen(pen(color, width));
    painter_.drawPolyline(points);
}

void ArenaPainter::robot(const Pose2& pose, const IrMount& mount, const QColor& color, bool ghost) {
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
        return;
    }
    // Robot frame: x forward from the axle midpoint, y to the left.
    painter_.setTransform(QTransform().translate(pose.x, pose.y).rotateRadians(pose.theta)
                          * world_to_widget_);
    const double rear = RobotOutline::kLength - RobotOutline::kAhead;
    const double half_width = RobotOutline::kWidth / 2.0;
    const QRectF chassis(-rear, -half_width, RobotOutline::kLength, RobotOutline::kWidth);
    painter_.setPen(ghost ? pen(with_alpha(color, 190), 1.0, Qt::DashLine) : pen(color, 1.5));
    painter_.setBrush(with_alpha(color, ghost ? 25 : 45));
    painter_.drawRect(chassis);
    // Wheels at the chassis' sides, on the axle.
    painter_.setPen(Qt::NoPen);
    painter_.setBrush(with_alpha(color, ghost ? 90 : 200));
    const double wheel_width = 0.022;
    const double r = RobotOutline::kWheelRadius;
    painter_.drawRect(QRectF(-r, half_width - wheel_width, 2.0 * r, wheel_width));
    painter_.drawRect(QRectF(-r, -half_width, 2.0 * r, wheel_width));
    // The IR sensors on the right side (−y).
    for (int sensor = 0; sensor < kIrSensorCount; ++sensor) {
        painter_.drawEllipse(QPointF(mount.longitudinal(sensor), -mount.lateral_offset), 0.009,
                             0.009);
    }
    // Heading: axle midpoint to an arrowhead at the front.
    painter_.setPen(pen(with_alpha(color, ghost ? 170 : 255), 1.5));
    painter_.setBrush(Qt::NoBrush);
    painter_.drawLine(QPointF(0.0, 0.0), QPointF(RobotOutline::kAhead, 0.0));
    QPolygonF notch;
    notch << QPointF(RobotOutline::kAhead, 0.0) << QPointF(RobotOutline::kAhead - 0.035, 0.025)
          << QPointF(RobotOutline::kAhead - 0.035, -0.025) << QPointF(RobotOutline::kAhead, 0.0);
    painter_.drawPolyline(notch);
}

void ArenaPainter::ir_rays(const LoopSnapshot& snapshot, const IrMount& mount, double max_range) {
    const Pose2 pose = to_pose(snapshot.estimate);
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
        return;
    }
    const bool associated = snapshot.association.associated();
    for (int sensor = 0; sensor < kIrSensorCount; ++sensor) {
        const IrBeam beam = ir_beam(pose, mount, sensor);
        const IrDistance& reading = snapshot.ir[static_cast<std::size_t>(sensor)].reading;
        const QPointF origin = to_point(beam.origin);
        use_world();
        if (reading.in_range() && std::isfinite(reading.distance)) {
            const QColor color = associated ? style_.colors.associated : style_.colors.rejected;
            const QPointF hit = to_point(beam.origin + reading.distance * beam.direction);
            painter_.setPen(pen(color, 2.0));
            painter_.drawLine(origin, hit);
            use_widget();
            painter_.setPen(Qt::NoPen);
            painter_.setBrush(color);
            const double radius = 3.0 * style_.line_scale;
            painter_.drawEllipse(world_to_widget_.map(hit), radius, radius);
        } else {
            const QPointF end = to_point(beam.origin + max_range * beam.direction);
            painter_.setPen(pen(style_.colors.out_of_range, 1.0, Qt::DashLine));
            painter_.drawLine(origin, end);
        }
    }
}

void ArenaPainter::ellipse(const CovarianceEllipse& ellipse) {
    if (!ellipse.valid) {
        return;
    }
    use_world();
    painter_.setPen(pen(style_.colors.ellipse, 2.0));
    painter_.setBrush(with_alpha(style_.colors.ellipse, 45));
    painter_.drawPolygon(ellipse_qpolygon(ellipse, 72));
}

void ArenaPainter::estimate_marker(const Pose2& pose) {
    heading_marker(pose, style_.colors.estimate);
}

void ArenaPainter::heading_marker(const Pose2& pose, const QColor& color) {
    if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta)) {
        return;
    }
    use_widget();
    const double s = style_.line_scale;
    const QPointF centre = world_to_widget_.map(QPointF(pose.x, pose.y));
    const QPointF direction(std::cos(pose.theta), -std::sin(pose.theta));  // widget y is down
    const QPointF normal(-direction.y(), direction.x());
    const double length = std::max(0.15 * std::abs(world_to_widget_.m11()), 28.0 * s);
    const QPointF tip = centre + length * direction;
    const QPointF base = tip - 11.0 * s * direction;
    painter_.setPen(pen(color, 2.5));
    painter_.drawLine(centre, base);
    QPolygonF head;
    head << tip << base + 5.5 * s * normal << base - 5.5 * s * normal;
    painter_.setPen(Qt::NoPen);
    painter_.setBrush(color);
    painter_.drawPolygon(head);
    painter_.setPen(pen(style_.colors.background, 1.5));
    painter_.drawEllipse(centre, 4.5 * s, 4.5 * s);
}

void ArenaPainter::wall_names(const std::vector<Wall>& walls, const QRectF& arena) {
    use_widget();
    QFont font = style_.font;
    font.setPointSizeF(font.pointSizeF() * kArenaSizes.wall_name_font);
    painter_.setFont(font);
    const QFontMetricsF metrics(font);
    painter_.setPen(with_alpha(style_.colors.foreground, 170));
    const Vector2 arena_centre(arena.center().x(), arena.center().y());
    for (const Wall& wall : walls) {
        if (wall.name.empty()) {
            continue;
        }
        const Vector2 along = wall.end - wall.start;
        if (along.norm() <= 0.0) {
            continue;
        }
        const Vector2 middle = 0.5 * (wall.start + wall.end);
        Vector2 outward = Vector2(-along.y(), along.x()).normalized();
        if (outward.dot(middle - arena_centre) < 0.0) {
            outward = -outward;
        }
        const QString text = QString::fromStdString(wall.name);
        const QSizeF size(metrics.horizontalAdvance(text), metrics.height());
        // Along the wall, reading left to right (or bottom to top), just outside it.
        const QPointF direction(outward.x(), -outward.y());  // widget y is down
        const double clearance = 3.0 * style_.line_scale + 4.0 + size.height() / 2.0;
        const QPointF centre = world_to_widget_.map(to_point(middle)) + clearance * direction;
        double angle = std::atan2(-along.y(), along.x());  // the wall's angle on the screen
        if (angle > kPi / 2.0 - 1e-9) {                    // vertical walls read bottom to top
            angle -= kPi;
        } else if (angle <= -kPi / 2.0 - 1e-9) {
            angle += kPi;
        }
        painter_.save();
        painter_.translate(centre);
        painter_.rotate(radians_to_degrees(angle));
        painter_.drawText(QRectF(QPointF(-size.width() / 2.0, -size.height() / 2.0), size),
                          Qt::AlignCenter, text);
        painter_.restore();
    }
    painter_.setFont(style_.font);
}

void ArenaPainter::label(const QPointF& anchor, const QString& text, const QColor& color) {
    use_widget();
    const QFontMetricsF metrics(style_.font);
    const double pad = 4.0;
    const QSizeF size(metrics.horizontalAdvance(text) + 2.0 * pad, metrics.height() + pad);
    QRectF box(anchor - QPointF(0.0, size.height()), size);
    const QRectF window = painter_.window();
    box.moveLeft(std::clamp(box.left(), window.left() + 2.0,
                            std::max(window.left() + 2.0, window.right() - size.width() - 2.0)));
    box.moveTop(std::clamp(box.top(), window.top() + 2.0,
                           std::max(window.top() + 2.0, window.bottom() - size.height() - 2.0)));
    painter_.setPen(pen(color, 1.0));
    painter_.setBrush(style_.colors.label_background);
    painter_.drawRoundedRect(box, 3.0, 3.0);
    painter_.setPen(color);
    painter_.drawText(box, Qt::AlignCenter, text);
}

void ArenaPainter::scale_bar(double pixels_per_metre, const QRectF& widget) {
    const double s = style_.line_scale;
    const double metres = scale_bar_length(pixels_per_metre, 110.0 * s);
    if (!(metres > 0.0)) {
        return;
    }
    use_widget();
    const QFontMetricsF metrics(style_.font);
    const double length = metres * pixels_per_metre;
    const QPointF left(widget.left() + 14.0, widget.bottom() - 12.0);
    const QPointF right = left + QPointF(length, 0.0);
    const double tick = 5.0 * s;
    const QString text = length_text(metres);
    const double text_width = std::max(length, metrics.horizontalAdvance(text));
    const QRectF box(left.x() - 6.0, left.y() - metrics.height() - tick - 8.0, text_width + 12.0,
                     metrics.height() + tick + 14.0);
    painter_.setPen(Qt::NoPen);
    painter_.setBrush(style_.colors.label_background);
    painter_.drawRoundedRect(box, 3.0, 3.0);
    QPen bar = pen(style_.colors.foreground, 2.0);
    bar.setCapStyle(Qt::FlatCap);
    painter_.setPen(bar);
    painter_.drawLine(left, right);
    painter_.drawLine(left, left - QPointF(0.0, tick));
    painter_.drawLine(right, right - QPointF(0.0, tick));
    painter_.setPen(style_.colors.foreground);
    painter_.drawText(
        QRectF(left.x(), left.y() - tick - metrics.height() - 2.0, text_width, metrics.height()),
        Qt::AlignLeft | Qt::AlignVCenter, text);
}

void ArenaPainter::corner_text(const QString& text, const QRectF& widget, Qt::Alignment corner) {
    use_widget();
    const QFontMetricsF metrics(style_.font);
    const QSizeF padding = kArenaSizes.corner_box_padding;
    const QSizeF size(metrics.horizontalAdvance(text) + padding.width(),
                      metrics.height() + padding.height());
    const double inset = kArenaSizes.corner_inset;
    const double x = corner.testFlag(Qt::AlignRight) ? widget.right() - size.width() - inset
                                                     : widget.left() + inset;
    const double y = corner.testFlag(Qt::AlignBottom) ? widget.bottom() - size.height() - inset
                                                      : widget.top() + inset;
    const QRectF box(QPointF(x, y), size);
    painter_.setPen(Qt::NoPen);
    painter_.setBrush(style_.colors.label_background);
    painter_.drawRoundedRect(box, 3.0, 3.0);
    painter_.setPen(style_.colors.foreground);
    painter_.drawText(box, Qt::AlignCenter, text);
}

void ArenaPainter::banner(const QString& text, const QRectF& widget) {
    use_widget();
    const QFontMetricsF metrics(style_.font);
    const QSizeF size(metrics.horizontalAdvance(text) + 16.0, metrics.height() + 10.0);
    const QRectF box(
        QPointF(widget.center().x() - size.width() / 2.0, widget.bottom() - 10.0 - size.height()),
        size);
    painter_.setPen(pen(style_.colors.truth, 1.5));
    painter_.setBrush(style_.colors.label_background);
    painter_.drawRoundedRect(box, 4.0, 4.0);
    painter_.setPen(style_.colors.foreground);
    painter_.drawText(box, Qt::AlignCenter, text);
}

void ArenaPainter::centred_text(const QString& text, const QRectF& widget) {
    use_widget();
    painter_.setPen(with_alpha(style_.colors.foreground, 170));
    painter_.drawText(widget, Qt::AlignCenter, text);
}

}  // namespace legofeup::ui
