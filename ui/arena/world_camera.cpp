#include "legofeup/ui/arena/world_camera.hpp"

#include <algorithm>
#include <cmath>

namespace legofeup::ui {

QTransform WorldCamera::transform(const QSizeF& viewport) const {
    // x' = s·(x − cx) + w/2,  y' = −s·(y − cy) + h/2
    return {scale_,
            0.0,
            0.0,
            -scale_,
            viewport.width() / 2.0 - scale_ * centre_.x(),
            viewport.height() / 2.0 + scale_ * centre_.y()};
}

QRectF WorldCamera::visible_world(const QSizeF& viewport) const {
    const double half_width = viewport.width() / (2.0 * scale_);
    const double half_height = viewport.height() / (2.0 * scale_);
    return {centre_.x() - half_width, centre_.y() - half_height, 2.0 * half_width,
            2.0 * half_height};
}

void WorldCamera::fit(const QRectF& world, const QRectF& area, const QSizeF& viewport) {
    if (world.width() > 0.0 || world.height() > 0.0) {
        const double width = std::max(area.width(), 1.0);
        const double height = std::max(area.height(), 1.0);
        const double sx = world.width() > 0.0 ? width / world.width() : kMaxScale;
        const double sy = world.height() > 0.0 ? height / world.height() : kMaxScale;
        scale_ = std::clamp(std::min(sx, sy), kMinScale, kMaxScale);
    }
    // world.center() maps to area.center().
    centre_.setX(world.center().x() - (area.center().x() - viewport.width() / 2.0) / scale_);
    centre_.setY(world.center().y() + (area.center().y() - viewport.height() / 2.0) / scale_);
}

void WorldCamera::zoom_about(double factor, const QPointF& anchor, const QSizeF& viewport) {
    if (!std::isfinite(factor) || factor <= 0.0) {
        return;
    }
    bool invertible = false;
    const QPointF world_anchor = transform(viewport).inverted(&invertible).map(anchor);
    scale_ = std::clamp(scale_ * factor, kMinScale, kMaxScale);
    // Keep world_anchor under the anchor pixel: solve transform(world_anchor) = anchor.
    centre_.setX(world_anchor.x() - (anchor.x() - viewport.width() / 2.0) / scale_);
    centre_.setY(world_anchor.y() + (anchor.y() - viewport.height() / 2.0) / scale_);
}

void WorldCamera::pan_by(const QPointF& pixels) {
    centre_ -= QPointF(pixels.x() / scale_, -pixels.y() / scale_);
}

}  // namespace legofeup::ui
