#pragma once
// Paints one frame of the arena view, back to front: the fixed scene (grid, maps, path,
// walls), the history (trail and paths, from the HistoryLayer's picture while the view
// stands still), the latest step (robots, the other filter, ellipse, estimate), the texts
// (wall names, labels, legend, scale bar) and the overlays (kidnapping, "No run yet", frame
// times). Between these stages it draws the layers of the run's lesson (arena_layer.hpp).

#include <QPainter>
#include <QRectF>
#include <optional>
#include <span>
#include <vector>

#include "legofeup/ui/arena/arena_cache.hpp"
#include "legofeup/ui/arena/arena_layer.hpp"
#include "legofeup/ui/arena/arena_legend.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "legofeup/ui/arena/history_layer.hpp"
#include "legofeup/ui/arena/map_pictures.hpp"
#include "legofeup/ui/arena/world_camera.hpp"
#include "legofeup/ui/frame_stats.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

/// What the view decided for this frame.
struct ArenaFrameSettings {
    WorldCamera camera;
    bool following = false;  ///< the camera moves every frame: no picture of the history
    ArenaStyle style;
    bool show_trail = true;
    bool show_odometry = true;
    bool show_truth = true;
    EllipseConfidence confidence = EllipseConfidence::OneSigma;
    bool show_legend = true;
    bool legend_tab_only = false;  ///< folded and closed: only its tab
    std::vector<LegendRow> legend_rows;
    LegendLayout legend_layout;
    QRectF legend_box;                               ///< as drawn, widget pixels; empty when hidden
    bool picking = false;                            ///< a pose is being picked for a kidnapping
    std::optional<Pose2> picked_pose;                ///< the pose being aimed, once pressed
    std::optional<FrameStats::Summary> frame_times;  ///< the frame-time overlay, when shown
};

/// The view's caches a frame reads and brings up to date.
struct ArenaCaches {
    ArenaCache& paths;
    HistoryLayer& history_picture;
    MapPictures& maps;
};

void paint_arena(QPainter& painter, const QRectF& widget, const RunHistory& history,
                 const ArenaCaches& caches, const ArenaFrameSettings& settings,
                 std::span<const ArenaLayer* const> layers);

/// The grid's spacing: 0.5 m, or 1, 2, 5, 10 … m when the lines would be too dense.
double grid_spacing(double pixels_per_metre);

}  // namespace legofeup::ui
