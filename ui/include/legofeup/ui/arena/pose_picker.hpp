#pragma once
// Picking a pose in the arena for a kidnapping: a press picks the place, the drag from there
// the heading (towards the cursor), the release ends it. A click without a drag (shorter
// than ArenaSizes::pick_drag) keeps the heading it is given (the robot's).

#include <QPointF>
#include <QTransform>
#include <optional>

#include "legofeup/core/state.hpp"

namespace legofeup::ui {

class PosePicker {
  public:
    /// The next press picks a place.
    void begin();
    /// Ends without a pose; false when no pick was going on.
    bool cancel();
    bool active() const { return active_; }
    /// A place was pressed and the drag goes on.
    bool pressed() const { return pressed_; }

    void press(const QPointF& at);
    void move_to(const QPointF& cursor);
    /// Ends the pick at `cursor` and returns its pose; nullopt when nothing was pressed.
    std::optional<Pose2> release(const QPointF& cursor, const QTransform& widget_to_world,
                                 double heading);

    /// The pose of a drag from the press to `cursor` (widget pixels): at the press, facing
    /// the cursor; `heading` for a drag too short to aim. θ wrapped to (−π, π].
    Pose2 pose(const QPointF& cursor, const QTransform& widget_to_world, double heading) const;
    /// The pose as the drag is now.
    Pose2 pose_now(const QTransform& widget_to_world, double heading) const {
        return pose(cursor_, widget_to_world, heading);
    }

  private:
    bool active_ = false;
    bool pressed_ = false;
    QPointF from_;    ///< widget pixels: where the press picked the place
    QPointF cursor_;  ///< widget pixels: where the drag is
};

}  // namespace legofeup::ui
