// The arena's layers for the further lessons: bearing-only beacons and their rays
// (paper 002), the second filter kind's estimate run beside the first (EKF vs UKF), and the
// laser scans (paper 001).
#include <QFontMetricsF>
#include <algorithm>
#include <cmath>

#include "arena_drawing.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::to_point;
using arena_drawing::with_alpha;

bool finite_pose(const Pose2& pose) {
    return std::isfinite(pose.x) && std::isfinite(pose.y) && std::isfinite(pose.theta);
}

constexpr double kRayOvershoot = 1.15;  ///< rays end 15 % past their beacon
constexpr double kMinRayLength = 0.1;   ///< m

}  // namespace

BearingRay bearing_ray(const Pose2& pose, double bearing, double length) {
    // The bearing is measured from the robot's heading, counter-clockwise: the ray's world
    // direction is θ + bearing.
    const double direction = pose.theta + bearing;
    const Vector2 from(pose.x, pose.y);
    return {from, from + length * Vector2(std::cos(direction), std::sin(direction))};
}

double beacon_ray_length(const Pose2& pose, const Beacon& beacon) {
    const double distance = std::hypot(beacon.position.x() - pose.x, beacon.position.y() - pose.y);
    return std::max(kMinRayLength, kRayOvershoot * distance);
}

void ArenaPainter::beacons(const BeaconMap& beacons) {
    if (beacons.empty()) {
        return;
    }
    use_widget();
    const double s = style_.line_scale;
    const double half = 7.0 * s;
    const QFontMetricsF metrics(style_.font);
    for (const Beacon& beacon : beacons) {
        if (!std::isfinite(beacon.position.x()) || !std::isfinite(beacon.position.y())) {
            continue;
        }
        const QPointF centre = world_to_widget_.map(to_point(beacon.position));
        QPolygonF diamond;
        diamond << centre + QPointF(0.0, -half) << centre + QPointF(half, 0.0)
                << centre + QPointF(0.0, half) << centre + QPointF(-half, 0.0);
        painter_.setPen(pen(style_.colors.background, 1.5));
        painter_.setBrush(style_.colors.beacon);
        painter_.drawPolygon(diamond);
        const QString text = QStringLiteral("B%1").arg(beacon.id);
        const QRectF box(centre + QPointF(half + 3.0, -half - metrics.height()),
                         QSizeF(metrics.horizontalAdvance(text) + 2.0, metrics.height()));
        painter_.setPen(style_.colors.beacon);
        painter_.drawText(box, Qt::AlignLeft | Qt::AlignVCenter, text);
    }
}

void ArenaPainter::beacon_rays(const LoopSnapshot& snapshot, const BeaconMap& beacons) {
    const Pose2 pose = to_pose(snapshot.estimate);
    if (!finite_pose(pose)) {
        return;
    }
    use_world();
    const int count = std::min<int>(snapshot.beacons.count, kMaxBeaconSightings);
    for (int i = 0; i < count; ++i) {
        const BeaconUpdate& update = snapshot.beacons.updates[static_cast<std::size_t>(i)];
        const Beacon* beacon = find_beacon(beacons, update.id);
        if (!update.known || beacon == nullptr || update.status == StepStatus::NotAttempted
            || !std::isfinite(update.bearing)) {
            continue;  // a sighting the filter could not use: nothing to compare
        }
        const double length = beacon_ray_length(pose, *beacon);
        if (std::isfinite(update.predicted)) {
            const BearingRay expected = bearing_ray(pose, update.predicted, length);
            painter_.setPen(pen(with_alpha(style_.colors.foreground, 90), 1.0, Qt::DashLine));
            painter_.drawLine(to_point(expected.from), to_point(expected.to));
        }
        const bool applied = update.status == StepStatus::Applied;
        const BearingRay measured = bearing_ray(pose, update.bearing, length);
        painter_.setPen(
            pen(with_alpha(applied ? style_.colors.associated : style_.colors.rejected, 220), 1.5));
        painter_.drawLine(to_point(measured.from), to_point(measured.to));
    }
}

void ArenaPainter::shadow_estimate(const Pose2& pose, const CovarianceEllipse& ellipse) {
    if (ellipse.valid) {
        use_world();
        painter_.setPen(pen(style_.colors.shadow, 2.0, Qt::DashLine));
        painter_.setBrush(with_alpha(style_.colors.shadow, 30));
        painter_.drawPolygon(ellipse_qpolygon(ellipse, 72));
    }
    heading_marker(pose, style_.colors.shadow);
}

void ArenaPainter::scan_points(const QPolygonF& points, const QColor& color, double diameter) {
    if (points.isEmpty()) {
        return;
    }
    // In widget pixels: dots of the same size at any zoom, one drawPoints call.
    use_widget();
    QPen dot(color, diameter * style_.line_scale, Qt::SolidLine, Qt::RoundCap);
    dot.setCosmetic(true);
    painter_.setPen(dot);
    painter_.drawPoints(world_to_widget_.map(points));
}

}  // namespace legofeup::ui
