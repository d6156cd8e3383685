#pragma once
// A path in world coordinates that grows one point per step and is drawn every frame.
//
// Appending thins the points (a point closer than `min_spacing` to the last kept one only
// moves the path's end), so a 30-minute run keeps one point per couple of millimetres.
// simplified() gives the path for drawing at a given tolerance (about half a pixel in world
// units): Ramer–Douglas–Peucker over fixed chunks, kept between frames and redone only for
// the newest chunk, or in full when the tolerance (the zoom) changes.

#include <QPolygonF>

namespace legofeup::ui {

class ThinnedPolyline {
  public:
    explicit ThinnedPolyline(double min_spacing = 0.002) : min_spacing_(min_spacing) {}

    void append(const QPointF& point);
    void clear();

    /// The thinned points; the last one is always the latest appended point.
    const QPolygonF& points() const { return points_; }
    qsizetype size() const { return points_.size(); }

    /// The points simplified so that no thinned point is farther than `tolerance` from the
    /// drawn line. The reference stays valid until the next call or append.
    const QPolygonF& simplified(double tolerance);

  private:
    static constexpr qsizetype kChunk = 512;  ///< points per frozen simplification chunk

    double min_spacing_;
    QPolygonF points_;
    // Simplification cache: chunks [0, frozen_end_) of points_ are simplified into
    // simplified_[0, frozen_count_); the rest is redone on every call.
    double tolerance_ = -1.0;
    qsizetype frozen_end_ = 0;
    qsizetype frozen_count_ = 0;
    QPolygonF simplified_;
};

/// Ramer–Douglas–Peucker: appends to `out` the kept points of `in[first, last]` except `last`.
void simplify_polyline(const QPolygonF& in, qsizetype first, qsizetype last, double tolerance,
                       QPolygonF& out);

}  // namespace legofeup::ui
