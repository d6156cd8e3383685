#include "legofeup/ui/arena/arena_camera.hpp"

#include <cmath>

namespace legofeup::ui {

WorldCamera ArenaCamera::shown(const std::optional<QPointF>& robot) const {
    WorldCamera camera = camera_;
    if (following_ && robot) {
        camera.set_centre(*robot);
    }
    return camera;
}

bool ArenaCamera::set_following(bool on, const std::optional<QPointF>& robot) {
    if (on == following_) {
        return false;
    }
    if (!on) {
        camera_ = shown(robot);  // stay where following left the view
    }
    following_ = on;
    fitted_ = false;
    return true;
}

void ArenaCamera::fit(const QRectF& world, const QRectF& area, const QSizeF& viewport) {
    camera_.fit(world, area, viewport);
    fitted_ = true;
}

void ArenaCamera::zoom_by(double factor, const QPointF& anchor, const QSizeF& viewport,
                          const std::optional<QPointF>& robot) {
    camera_ = shown(robot);
    const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
    camera_.zoom_about(factor, following_ ? centre : anchor, viewport);
    fitted_ = false;
}

void ArenaCamera::pan_by(const QPointF& pixels) {
    camera_.pan_by(pixels);
    fitted_ = false;
}

std::optional<QPointF> follow_point(const RunHistory& history) {
    if (history.empty()) {
        return std::nullopt;
    }
    const StateVector& x = history.latest().snapshot.estimate;
    if (!std::isfinite(x(kX)) || !std::isfinite(x(kY))) {
        return std::nullopt;
    }
    return QPointF(x(kX), x(kY));
}

}  // namespace legofeup::ui
