#pragma once
// The arena view's history (trail of past ellipses and the three paths) kept as a picture.
//
// While the view stands still, each frame only draws what is new since the last one onto the
// picture and copies it to the screen, so a paint costs the same after 30 minutes as after 30
// seconds. Any change of view, colours, line widths, settings or run redraws the picture in
// full. Each path's newest point can still move (ThinnedPolyline), so the picture holds the
// path up to the point before it and the last stretch is drawn live.

#include <QImage>
#include <QPainter>
#include <QSize>
#include <QTransform>
#include <array>
#include <cstdint>
#include <optional>

#include "legofeup/ui/arena/arena_cache.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"

namespace legofeup::ui {

class HistoryLayer {
  public:
    /// Everything the picture depends on; a change redraws it in full.
    struct Settings {
        QTransform world_to_widget;
        QSize size;  ///< device-independent pixels
        double device_pixel_ratio = 1.0;
        double line_scale = 1.0;
        QRgb trail = 0;
        QRgb odometry = 0;
        QRgb truth = 0;
        QRgb estimate = 0;
        bool show_trail = true;
        bool show_odometry = true;
        bool show_truth = true;
        std::uint64_t epoch = 0;
        EllipseConfidence confidence = EllipseConfidence::OneSigma;

        friend bool operator==(const Settings&, const Settings&) = default;
    };

    /// Brings the picture up to date with `cache` and draws it (and the paths' moving ends)
    /// with `painter`, which draws in widget coordinates.
    void paint(QPainter& painter, const Settings& settings, ArenaCache& cache,
               const ArenaStyle& style);
    /// Forgets the picture (the next paint redraws it).
    void clear();

  private:
    enum Path { kOdometry = 0, kTruth = 1, kEstimate = 2 };

    void redraw(const Settings& settings);

    QImage image_;
    std::optional<Settings> settings_;
    std::array<qsizetype, 3> drawn_{};  ///< index of the last point of each path in the picture
    std::size_t trail_drawn_ = 0;       ///< trail ellipses in the picture
    std::size_t jumps_drawn_ = 0;       ///< the truth's paths before its jumps in the picture
};

}  // namespace legofeup::ui
