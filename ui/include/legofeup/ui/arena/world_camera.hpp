#pragma once
// Which part of the world the arena view shows: a centre in world coordinates (metres, y up)
// and a scale in device-independent pixels per metre, aspect 1:1. The world → widget
// transform flips y so that world y points up on the screen.

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QTransform>

namespace legofeup::ui {

class WorldCamera {
  public:
    static constexpr double kMinScale = 10.0;     ///< px/m: 10 m across 100 px
    static constexpr double kMaxScale = 20000.0;  ///< px/m: 1 mm across 20 px

    /// world → widget for a widget of `viewport` size (device-independent pixels).
    QTransform transform(const QSizeF& viewport) const;
    /// The world rectangle the widget shows.
    QRectF visible_world(const QSizeF& viewport) const;

    /// Shows `world` whole, centred in `area` (widget pixels) of a widget of `viewport` size.
    void fit(const QRectF& world, const QRectF& area, const QSizeF& viewport);
    /// Multiplies the scale by `factor`, keeping the world point under `anchor` (widget
    /// pixels) where it is.
    void zoom_about(double factor, const QPointF& anchor, const QSizeF& viewport);
    /// Moves the view by a drag of `pixels` (the world follows the mouse).
    void pan_by(const QPointF& pixels);

    void set_centre(const QPointF& centre) { centre_ = centre; }
    QPointF centre() const { return centre_; }
    double scale() const { return scale_; }

  private:
    QPointF centre_{0.0, 0.0};
    double scale_ = 200.0;  ///< px per metre
};

}  // namespace legofeup::ui
