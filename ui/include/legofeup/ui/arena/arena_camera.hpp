#pragma once
// The arena view's camera as the user steers it: a WorldCamera that the wheel zooms and a
// drag pans, fitted to the arena (and refitted when the widget is resized) until either
// happens, and that can follow the robot (centred on the latest estimate every frame).

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <optional>

#include "legofeup/ui/arena/world_camera.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

class ArenaCamera {
  public:
    /// The camera as drawn: centred on `robot` while following, when there is one.
    WorldCamera shown(const std::optional<QPointF>& robot) const;
    bool following() const { return following_; }
    /// The view shows the fitted arena: a resize fits it again.
    bool fitted() const { return fitted_; }

    /// Starts or stops following; stopping keeps the view where following left it. False
    /// when it already was so.
    bool set_following(bool on, const std::optional<QPointF>& robot);
    /// Shows `world` whole in `area` (widget pixels) of a widget of `viewport` size.
    void fit(const QRectF& world, const QRectF& area, const QSizeF& viewport);
    /// Multiplies the scale by `factor` keeping the world point under `anchor` (widget
    /// pixels) in place; while following, about the widget's centre (the robot stays there).
    void zoom_by(double factor, const QPointF& anchor, const QSizeF& viewport,
                 const std::optional<QPointF>& robot);
    /// A drag of `pixels` (the caller stops following first).
    void pan_by(const QPointF& pixels);

  private:
    WorldCamera camera_;
    bool following_ = false;
    bool fitted_ = true;
};

/// Where a following camera centres: the latest estimate, when there is a finite one.
std::optional<QPointF> follow_point(const RunHistory& history);

}  // namespace legofeup::ui
