#include "legofeup/ui/arena/arena_cache.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <variant>

#include "arena_drawing.hpp"
#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/map_image.hpp"

namespace legofeup::ui {

namespace {

using arena_drawing::to_point;

}  // namespace

void WorldBounds::add(const QPointF& point) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
        return;
    }
    min_x_ = std::min(min_x_, point.x());
    min_y_ = std::min(min_y_, point.y());
    max_x_ = std::max(max_x_, point.x());
    max_y_ = std::max(max_y_, point.y());
}

CovarianceEllipse sample_ellipse(const RunSample& sample, EllipseConfidence level) {
    const StateVector& x = sample.snapshot.estimate;
    const Eigen::Matrix2d position_block = sample.snapshot.covariance.block<2, 2>(kX, kX);
    return covariance_ellipse(Vector2(x(kX), x(kY)), position_block, level);
}

CovarianceEllipse sample_ellipse(const StepRecord& record, EllipseConfidence level) {
    Eigen::Matrix2d position_block;
    position_block << widen(record.pxx), widen(record.pxy), widen(record.pxy), widen(record.pyy);
    return covariance_ellipse(position_of(record.estimate), position_block, level);
}

QPolygonF ellipse_qpolygon(const CovarianceEllipse& ellipse, int count) {
    QPolygonF polygon;
    const std::vector<Vector2> points = ellipse_polygon(ellipse, count);
    polygon.reserve(static_cast<qsizetype>(points.size()) + 1);
    for (const Vector2& p : points) {
        polygon.append(to_point(p));
    }
    if (!polygon.isEmpty()) {
        polygon.append(polygon.front());
    }
    return polygon;
}

QPainterPath intended_painter_path(const std::vector<PathSegment>& path, const Vector2& start) {
    QPainterPath painter_path;
    Vector2 cursor = start;
    bool first = true;
    for (const PathSegment& segment : path) {
        if (const auto* line = std::get_if<LineSegment>(&segment)) {
            if (first || (line->from - cursor).norm() > 1e-9) {
                painter_path.moveTo(to_point(line->from));
            }
            painter_path.lineTo(to_point(line->to));
            cursor = line->to;
        } else if (const auto* arc = std::get_if<ArcSegment>(&segment)) {
            // The arc starts at the centre's bearing of where the robot begins it.
            const Vector2 offset = cursor - arc->centre;
            const double start_angle =
                offset.squaredNorm() > 0.0 ? std::atan2(offset.y(), offset.x()) : 0.0;
            const double sweep = arc->sweep > 0.0 ? arc->sweep : 2.0 * kPi;
            const double direction = arc->counter_clockwise ? 1.0 : -1.0;
            const int steps = std::max(8, static_cast<int>(std::ceil(sweep / (kPi / 48.0))));
            for (int i = 0; i <= steps; ++i) {
                const double angle = start_angle + direction * sweep * i / steps;
                const QPointF point(arc->centre.x() + arc->radius * std::cos(angle),
                                    arc->centre.y() + arc->radius * std::sin(angle));
                if (i == 0) {
                    painter_path.moveTo(point);
                } else {
                    painter_path.lineTo(point);
                }
            }
            const double end_angle = start_angle + direction * sweep;
            cursor = arc->centre + arc->radius * Vector2(std::cos(end_angle), std::sin(end_angle));
        }
        first = false;
    }
    return painter_path;
}

void ArenaCache::build_scene(const RunHistory& history) {
    const ArenaScene& scene = history.scene();
    Vector2 start = Vector2::Zero();
    if (!history.empty()) {
        start = position_of(history.record(0).estimate);
    } else if (!scene.path.empty()) {
        if (const auto* line = std::get_if<LineSegment>(&scene.path.back())) {
            start = line->to;  // a closed path starts where it ends
        }
    }
    intended_ = intended_painter_path(scene.path, start);
    scene_bounds_ = WorldBounds();
    if (!intended_.isEmpty()) {
        const QRectF box = intended_.boundingRect();
        scene_bounds_.add(box.topLeft());
        scene_bounds_.add(box.bottomRight());
    }
    for (const Wall& wall : scene.walls) {
        scene_bounds_.add(to_point(wall.start));
        scene_bounds_.add(to_point(wall.end));
    }
    for (const Beacon& beacon : scene.beacons) {
        scene_bounds_.add(to_point(beacon.position));
    }
    if (scene.map) {
        const QRectF map = map_world_bounds(*scene.map);
        scene_bounds_.add(map.topLeft());
        scene_bounds_.add(map.bottomRight());
    }
}

void ArenaCache::rebuild(const RunHistory& history, EllipseConfidence level) {
    epoch_ = history.epoch();
    seen_ = 0;
    truth_.clear();
    truth_before_jumps_.clear();
    truth_teleports_ = 0;
    estimate_.clear();
    odometry_.clear();
    trail_.clear();
    trail_path_.clear();
    data_bounds_ = WorldBounds();
    next_trail_time_ = -std::numeric_limits<double>::infinity();
    build_scene(history);
    update(history, level);
}

void ArenaCache::update(const RunHistory& history, EllipseConfidence level) {
    if (history.epoch() != epoch_ || history.size() < seen_) {
        rebuild(history, level);
        return;
    }
    const std::vector<StepRecord>& records = history.records();
    if (seen_ == 0 && !records.empty()) {
        build_scene(history);  // arcs start where the robot starts
    }
    for (std::size_t i = seen_; i < records.size(); ++i) {
        take_sample(records[i], i, level);
    }
    seen_ = records.size();
}

void ArenaCache::take_sample(const StepRecord& record, std::size_t index, EllipseConfidence level) {
    const QPointF estimate(record.estimate.x, record.estimate.y);
    estimate_.append(estimate);
    odometry_.append({widen(record.odometry.x()), widen(record.odometry.y())});
    data_bounds_.add(estimate);
    if (record.has_truth) {
        if (record.teleports != truth_teleports_ && truth_.size() > 0) {
            // Kidnapped (or displaced) since the last truth: the path starts again there.
            truth_before_jumps_.push_back(truth_.points());
            truth_.clear();
        }
        truth_teleports_ = record.teleports;
        truth_.append({record.truth.x, record.truth.y});
    }
    if (record.time >= next_trail_time_) {
        next_trail_time_ = record.time + kTrailPeriod;
        const CovarianceEllipse ellipse = sample_ellipse(record, level);
        if (ellipse.valid) {
            TrailEllipse trail{index, ellipse_qpolygon(ellipse, kTrailPoints)};
            trail_path_.addPolygon(trail.polygon);
            trail_.push_back(std::move(trail));
        }
    }
}

void ArenaCache::set_confidence(const RunHistory& history, EllipseConfidence level) {
    const std::vector<StepRecord>& records = history.records();
    trail_path_.clear();
    for (TrailEllipse& trail : trail_) {
        if (trail.sample >= records.size()) {
            continue;
        }
        const CovarianceEllipse ellipse = sample_ellipse(records[trail.sample], level);
        trail.polygon = ellipse_qpolygon(ellipse, kTrailPoints);
        trail_path_.addPolygon(trail.polygon);
    }
}

}  // namespace legofeup::ui
