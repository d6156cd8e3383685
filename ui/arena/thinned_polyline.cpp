#include "legofeup/ui/arena/thinned_polyline.hpp"

#include <cmath>
#include <utility>
#include <vector>

namespace legofeup::ui {

namespace {

double squared_distance(const QPointF& a, const QPointF& b) {
    const QPointF d = a - b;
    return d.x() * d.x() + d.y() * d.y();
}

/// Squared distance of p from the segment [a, b].
double squared_segment_distance(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double length2 = ab.x() * ab.x() + ab.y() * ab.y();
    if (length2 <= 0.0) {
        return squared_distance(p, a);
    }
    const QPointF ap = p - a;
    double t = (ap.x() * ab.x() + ap.y() * ab.y()) / length2;
    t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
    return squared_distance(p, a + t * ab);
}

}  // namespace

void ThinnedPolyline::append(const QPointF& point) {
    if (!std::isfinite(point.x()) || !std::isfinite(point.y())) {
        return;
    }
    const qsizetype n = points_.size();
    // The last point is the path's moving end. It is kept once it is min_spacing away from
    // the kept point before it; until then the next point replaces it.
    if (n >= 2 && squared_distance(points_[n - 2], points_[n - 1]) < min_spacing_ * min_spacing_) {
        points_[n - 1] = point;
        return;
    }
    points_.append(point);
}

void ThinnedPolyline::clear() {
    points_.clear();
    simplified_.clear();
    tolerance_ = -1.0;
    frozen_end_ = 0;
    frozen_count_ = 0;
}

const QPolygonF& ThinnedPolyline::simplified(double tolerance) {
    if (tolerance != tolerance_) {
        tolerance_ = tolerance;
        frozen_end_ = 0;
        frozen_count_ = 0;
        simplified_.clear();
    }
    simplified_.resize(frozen_count_);
    const qsizetype n = points_.size();
    if (n == 0) {
        return simplified_;
    }
    // Freeze whole chunks; the newest point (which may still move) is never in one.
    while (n - 1 - frozen_end_ > kChunk) {
        simplify_polyline(points_, frozen_end_, frozen_end_ + kChunk, tolerance, simplified_);
        frozen_end_ += kChunk;
        frozen_count_ = simplified_.size();
    }
    simplify_polyline(points_, frozen_end_, n - 1, tolerance, simplified_);
    simplified_.append(points_[n - 1]);
    return simplified_;
}

void simplify_polyline(const QPolygonF& in, qsizetype first, qsizetype last, double tolerance,
                       QPolygonF& out) {
    if (last <= first) {
        return;
    }
    const double tolerance2 = tolerance * tolerance;
    // Iterative RDP: keep[i] marks the points that stay.
    std::vector<bool> keep(static_cast<std::size_t>(last - first + 1), false);
    keep.front() = true;
    keep.back() = true;
    std::vector<std::pair<qsizetype, qsizetype>> stack{{first, last}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        double worst = -1.0;
        qsizetype worst_index = -1;
        for (qsizetype i = a + 1; i < b; ++i) {
            const double d2 = squared_segment_distance(in[i], in[a], in[b]);
            if (d2 > worst) {
                worst = d2;
                worst_index = i;
            }
        }
        if (worst_index >= 0 && worst > tolerance2) {
            keep[static_cast<std::size_t>(worst_index - first)] = true;
            stack.emplace_back(a, worst_index);
            stack.emplace_back(worst_index, b);
        }
    }
    for (qsizetype i = first; i < last; ++i) {
        if (keep[static_cast<std::size_t>(i - first)]) {
            out.append(in[i]);
        }
    }
}

}  // namespace legofeup::ui
