#include "legofeup/ui/arena/history_layer.hpp"

#include <cmath>

namespace legofeup::ui {

void HistoryLayer::clear() {
    image_ = QImage();
    settings_.reset();
    drawn_ = {};
    trail_drawn_ = 0;
    jumps_drawn_ = 0;
}

void HistoryLayer::redraw(const Settings& settings) {
    const QSize pixels(
        static_cast<int>(std::ceil(settings.size.width() * settings.device_pixel_ratio)),
        static_cast<int>(std::ceil(settings.size.height() * settings.device_pixel_ratio)));
    if (image_.size() != pixels) {
        image_ = QImage(pixels, QImage::Format_ARGB32_Premultiplied);
    }
    image_.setDevicePixelRatio(settings.device_pixel_ratio);
    image_.fill(Qt::transparent);
    settings_ = settings;
    drawn_ = {};
    trail_drawn_ = 0;
    jumps_drawn_ = 0;
}

void HistoryLayer::paint(QPainter& painter, const Settings& settings, ArenaCache& cache,
                         const ArenaStyle& style) {
    ThinnedPolyline* const paths[] = {&cache.odometry_path(), &cache.truth_path(),
                                      &cache.estimate_path()};
    const bool shown[] = {settings.show_odometry, settings.show_truth, true};
    const QColor colours[] = {style.colors.odometry, style.colors.truth, style.colors.estimate};

    bool stale = !settings_ || !(*settings_ == settings) || cache.trail().size() < trail_drawn_
                 || cache.truth_before_jumps().size() < jumps_drawn_;
    for (int i = 0; i < 3 && !stale; ++i) {
        stale = drawn_[static_cast<std::size_t>(i)] > paths[i]->size();
    }
    if (stale) {
        redraw(settings);
    }

    // 1. Draw what is new onto the picture: trail ellipses, then each path up to the point
    //    before its moving end.
    {
        QPainter layer(&image_);
        layer.setRenderHint(QPainter::Antialiasing);
        ArenaPainter arena(layer, settings.world_to_widget, style);
        const std::vector<TrailEllipse>& trail = cache.trail();
        if (settings.show_trail && trail_drawn_ < trail.size()) {
            QPainterPath fresh;
            for (std::size_t i = trail_drawn_; i < trail.size(); ++i) {
                fresh.addPolygon(trail[i].polygon);
            }
            arena.trail(fresh);
        }
        trail_drawn_ = trail.size();
        // The truth's finished paths (before each jump). A jump restarts the live truth path,
        // which makes the picture stale, so each is drawn once into a fresh picture.
        const std::vector<QPolygonF>& jumps = cache.truth_before_jumps();
        for (; jumps_drawn_ < jumps.size(); ++jumps_drawn_) {
            if (settings.show_truth) {
                arena.polyline(jumps[jumps_drawn_], style.colors.truth, 1.0);
            }
        }
        for (int i = 0; i < 3; ++i) {
            const QPolygonF& points = paths[i]->points();
            qsizetype& drawn = drawn_[static_cast<std::size_t>(i)];
            const qsizetype settled = points.size() - 2;  // the last point may still move
            if (shown[i] && settled > drawn) {
                arena.polyline(points.mid(drawn, settled - drawn + 1), colours[i], 1.0);
            }
            drawn = std::max(drawn, settled);
        }
    }

    // 2. The picture, then the moving ends.
    painter.save();
    painter.resetTransform();
    painter.drawImage(QPointF(0.0, 0.0), image_);
    painter.restore();
    ArenaPainter arena(painter, settings.world_to_widget, style);
    for (int i = 0; i < 3; ++i) {
        const QPolygonF& points = paths[i]->points();
        const qsizetype drawn = drawn_[static_cast<std::size_t>(i)];
        if (shown[i] && points.size() - drawn >= 2) {
            arena.polyline(points.mid(drawn), colours[i], 1.0);
        }
    }
}

}  // namespace legofeup::ui
