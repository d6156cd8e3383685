#include "legofeup/ui/arena/pose_picker.hpp"

#include <cmath>

#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"

namespace legofeup::ui {

void PosePicker::begin() {
    active_ = true;
    pressed_ = false;
}

bool PosePicker::cancel() {
    if (!active_) {
        return false;
    }
    active_ = false;
    pressed_ = false;
    return true;
}

void PosePicker::press(const QPointF& at) {
    pressed_ = true;
    from_ = at;
    cursor_ = at;
}

void PosePicker::move_to(const QPointF& cursor) {
    if (pressed_) {
        cursor_ = cursor;
    }
}

std::optional<Pose2> PosePicker::release(const QPointF& cursor, const QTransform& widget_to_world,
                                         double heading) {
    if (!active_ || !pressed_) {
        return std::nullopt;
    }
    const Pose2 picked = pose(cursor, widget_to_world, heading);
    active_ = false;
    pressed_ = false;
    return picked;
}

Pose2 PosePicker::pose(const QPointF& cursor, const QTransform& widget_to_world,
                       double heading) const {
    const QPointF at = widget_to_world.map(from_);
    Pose2 picked{at.x(), at.y(), heading};
    // θ = atan2(Δy, Δx) in the world, from the place to the cursor (the world's y is up:
    // the transform takes care of the screen's y pointing down).
    const QPointF drag = cursor - from_;
    if (std::hypot(drag.x(), drag.y()) >= kArenaSizes.pick_drag) {
        const QPointF to = widget_to_world.map(cursor);
        picked.theta = std::atan2(to.y() - at.y(), to.x() - at.x());
    }
    picked.theta = wrap_angle(picked.theta);
    return picked;
}

}  // namespace legofeup::ui
