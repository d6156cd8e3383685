#pragma once
// What the arena view keeps between frames, in world coordinates, so a paint costs the same
// after 30 minutes as after 30 seconds: the three paths (truth, estimate, odometry) thinned
// as they grow, the trail of past covariance ellipses (one per second of run time) as
// ready-made polygons, and the intended path. Updated incrementally as samples arrive.

#include <QPainterPath>
#include <QPolygonF>
#include <QRectF>
#include <cstdint>
#include <limits>
#include <vector>

#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "legofeup/ui/arena/thinned_polyline.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// A growing bounding box (empty until the first point).
class WorldBounds {
  public:
    void add(const QPointF& point);
    bool empty() const { return min_x_ > max_x_; }
    QRectF rect() const {
        return empty() ? QRectF() : QRectF(min_x_, min_y_, max_x_ - min_x_, max_y_ - min_y_);
    }

  private:
    double min_x_ = std::numeric_limits<double>::infinity();
    double min_y_ = std::numeric_limits<double>::infinity();
    double max_x_ = -std::numeric_limits<double>::infinity();
    double max_y_ = -std::numeric_limits<double>::infinity();
};

/// A past covariance ellipse of the trail, ready to draw.
struct TrailEllipse {
    std::size_t sample = 0;  ///< index into the history's steps
    QPolygonF polygon;       ///< world coordinates
};

class ArenaCache {
  public:
    static constexpr double kTrailPeriod = 1.0;  ///< s of run time between trail ellipses
    static constexpr int kTrailPoints = 24;      ///< polygon points per trail ellipse

    /// Drops everything and rebuilds from the whole history.
    void rebuild(const RunHistory& history, EllipseConfidence level);
    /// Takes in the samples not seen yet (rebuilds instead when the history restarted).
    void update(const RunHistory& history, EllipseConfidence level);
    /// Recomputes the trail's polygons for another confidence level.
    void set_confidence(const RunHistory& history, EllipseConfidence level);

    ThinnedPolyline& truth_path() { return truth_; }
    /// The truth's path before each jump (a kidnapping: the simulator's teleport count went
    /// up), one finished polyline each, so the path is never drawn across the jump.
    const std::vector<QPolygonF>& truth_before_jumps() const { return truth_before_jumps_; }
    ThinnedPolyline& estimate_path() { return estimate_; }
    ThinnedPolyline& odometry_path() { return odometry_; }
    const ThinnedPolyline& estimate_path() const { return estimate_; }
    const std::vector<TrailEllipse>& trail() const { return trail_; }
    /// Every trail ellipse as one closed subpath, drawn in one call.
    const QPainterPath& trail_path() const { return trail_path_; }
    /// The intended path (lines and arcs) in world coordinates.
    const QPainterPath& intended_path() const { return intended_; }
    /// What "fit the arena" shows: the walls, the map and the intended path, or, without
    /// any, every estimate seen.
    QRectF world_bounds() const {
        return scene_bounds_.empty() ? data_bounds_.rect() : scene_bounds_.rect();
    }

  private:
    void take_sample(const StepRecord& record, std::size_t index, EllipseConfidence level);
    void build_scene(const RunHistory& history);

    std::uint64_t epoch_ = 0;
    std::size_t seen_ = 0;
    ThinnedPolyline truth_;
    ThinnedPolyline estimate_;
    ThinnedPolyline odometry_;
    std::vector<QPolygonF> truth_before_jumps_;
    std::uint32_t truth_teleports_ = 0;  ///< the simulator's teleport count at the last truth
    std::vector<TrailEllipse> trail_;
    QPainterPath trail_path_;
    double next_trail_time_ = 0.0;
    QPainterPath intended_;
    WorldBounds scene_bounds_;
    WorldBounds data_bounds_;
};

/// The intended path as a painter path: lines, and arcs that start where the previous
/// segment ended (the first one where `start` is).
QPainterPath intended_painter_path(const std::vector<PathSegment>& path, const Vector2& start);

/// The ellipse of a sample's position covariance (P's x–y block) at its estimate.
CovarianceEllipse sample_ellipse(const RunSample& sample, EllipseConfidence level);
CovarianceEllipse sample_ellipse(const StepRecord& record, EllipseConfidence level);

/// An ellipse as a closed polygon of `count` points in world coordinates.
QPolygonF ellipse_qpolygon(const CovarianceEllipse& ellipse, int count);

}  // namespace legofeup::ui
