#include "legofeup/ui/arena/arena_renderer.hpp"

#include <QFontMetricsF>
#include <algorithm>

#include "arena_drawing.hpp"
#include "arena_text.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"
#include "legofeup/ui/arena/legend_placement.hpp"
#include "legofeup/ui/arena/map_image.hpp"

namespace legofeup::ui {

double grid_spacing(double pixels_per_metre) {
    double spacing = 0.5;
    for (const double step : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
        if (spacing * pixels_per_metre >= kArenaSizes.min_grid_spacing) {
            break;
        }
        spacing = step;
    }
    return spacing;
}

namespace {

using arena_drawing::finite_position;

/// One frame being painted: the stages in the order they are drawn.
class FramePainter {
  public:
    FramePainter(QPainter& painter, const QRectF& widget, const RunHistory& history,
                 const ArenaCaches& caches, const ArenaFrameSettings& settings,
                 std::span<const ArenaLayer* const> layers)
        : painter_(painter),
          widget_(widget),
          history_(history),
          caches_(caches),
          settings_(settings),
          layers_(layers),
          transform_(settings.camera.transform(widget.size())),
          arena_(painter, transform_, settings.style),
          latest_(history.empty() ? nullptr : &history.latest()),
          layer_frame_{
              history, latest_, settings.style, widget, settings.legend_box, settings.show_truth} {}

    void paint() {
        painter_.fillRect(widget_, colors().background);
        fixed_scene();
        run_history();
        draw_layers(ArenaStage::Marks);
        latest_step();
        texts();
        overlays();
    }

  private:
    const ArenaColors& colors() const { return settings_.style.colors; }
    double scale() const { return settings_.camera.scale(); }

    void draw_layers(ArenaStage stage) {
        for (const ArenaLayer* layer : layers_) {
            layer->draw(stage, arena_, layer_frame_);
        }
    }

    /// The grid, the maps over it (their free cells let the grid show), the path, the walls.
    void fixed_scene() {
        const ArenaScene& scene = history_.scene();
        arena_.grid(settings_.camera.visible_world(widget_.size()), grid_spacing(scale()));
        caches_.maps.update(scene, colors());
        if (scene.map) {
            arena_.map(caches_.maps.world_map(), image_to_world(*scene.map));
        }
        if (scene.filter_map) {
            arena_.map(caches_.maps.filter_map(), image_to_world(*scene.filter_map));
        }
        arena_.intended_path(caches_.paths.intended_path());
        const int matched_wall = latest_ != nullptr && latest_->snapshot.association.associated()
                                     ? latest_->snapshot.association.wall
                                     : -1;
        arena_.walls(scene.walls, matched_wall);
    }

    /// The trail and the three paths. A still view keeps them as a picture and adds only
    /// what is new; while following, the view moves every frame, so they are drawn
    /// directly, simplified to half a pixel.
    void run_history() {
        if (latest_ == nullptr) {
            return;
        }
        if (!settings_.following) {
            HistoryLayer::Settings picture;
            picture.world_to_widget = transform_;
            picture.size = widget_.size().toSize();
            picture.device_pixel_ratio = painter_.device()->devicePixelRatioF();
            picture.line_scale = settings_.style.line_scale;
            picture.trail = colors().trail.rgba();
            picture.odometry = colors().odometry.rgba();
            picture.truth = colors().truth.rgba();
            picture.estimate = colors().estimate.rgba();
            picture.show_trail = settings_.show_trail;
            picture.show_odometry = settings_.show_odometry;
            picture.show_truth = settings_.show_truth;
            picture.epoch = history_.epoch();
            picture.confidence = settings_.confidence;
            caches_.history_picture.paint(painter_, picture, caches_.paths, settings_.style);
            return;
        }
        const double tolerance = 0.5 / scale();
        ArenaCache& paths = caches_.paths;
        if (settings_.show_trail) {
            arena_.trail(paths.trail_path());
        }
        if (settings_.show_odometry) {
            arena_.polyline(paths.odometry_path().simplified(tolerance), colors().odometry, 1.0);
        }
        if (settings_.show_truth) {
            for (const QPolygonF& before : paths.truth_before_jumps()) {
                arena_.polyline(before, colors().truth, 1.0);
            }
            arena_.polyline(paths.truth_path().simplified(tolerance), colors().truth, 1.0);
        }
        arena_.polyline(paths.estimate_path().simplified(tolerance), colors().estimate, 1.0);
    }

    /// The ghost, the real robot, the lesson's measurements, the other filter kind's
    /// estimate, the ellipse, the estimate.
    void latest_step() {
        if (latest_ == nullptr) {
            return;
        }
        const LoopSnapshot& snapshot = latest_->snapshot;
        const IrMount& mount = history_.scene().ir_mount;
        if (settings_.show_odometry) {
            arena_.robot(snapshot.odometry_pose, mount, colors().odometry, true);
        }
        if (settings_.show_truth && latest_->truth) {
            arena_.robot(latest_->truth->pose, mount, colors().truth, false);
        }
        draw_layers(ArenaStage::Measurements);
        if (snapshot.shadow.active) {
            const StateVector& shadow = snapshot.shadow.estimate;
            shadow_ellipse_ = covariance_ellipse(
                Vector2(shadow(kX), shadow(kY)),
                snapshot.shadow.covariance.topLeftCorner<2, 2>().eval(), settings_.confidence);
            arena_.shadow_estimate(to_pose(shadow), shadow_ellipse_);
        }
        ellipse_ = sample_ellipse(*latest_, settings_.confidence);
        arena_.ellipse(ellipse_);
        arena_.estimate_marker(to_pose(snapshot.estimate));
    }

    /// In widget pixels: the wall names, the labels at the estimates, the lesson's texts,
    /// the legend (or its tab) and the scale bar.
    void texts() {
        arena_.wall_names(history_.scene().walls, caches_.paths.world_bounds());
        if (latest_ != nullptr && finite_position(latest_->snapshot.estimate)) {
            estimate_label();
            shadow_label();
        }
        draw_layers(ArenaStage::Labels);
        if (settings_.show_legend && settings_.legend_tab_only) {
            arena_.corner_text(LegendPlacement::tab_text(), widget_, Qt::AlignRight | Qt::AlignTop);
        } else if (settings_.show_legend) {
            arena_.legend(
                settings_.legend_rows, settings_.legend_layout,
                QPointF(widget_.right() - kArenaSizes.corner_inset, kArenaSizes.corner_inset));
        }
        arena_.scale_bar(scale(), widget_);
    }

    /// The ellipse's label above-right of the estimate, clear of the ellipse and of the
    /// robot drawn around it.
    void estimate_label() {
        const StateVector& x = latest_->snapshot.estimate;
        const QPointF at = transform_.map(QPointF(x(kX), x(kY)));
        const double radius =
            std::max({ellipse_.valid ? ellipse_.semi_major * scale() : 0.0,
                      RobotOutline::kLength * kArenaSizes.robot_clearance * scale(),
                      kArenaSizes.label_clearance * settings_.style.line_scale});
        const double reach = radius * kArenaSizes.label_reach + kArenaSizes.label_offset;
        QString text = QString::fromUtf8(confidence_label(settings_.confidence));
        if (!ellipse_.valid) {
            text += QStringLiteral(" (P not positive semi-definite)");
        }
        arena_.label(at + QPointF(reach, -reach), text, colors().ellipse);
    }

    /// The other filter's name below-left of its estimate, clear of the label above.
    void shadow_label() {
        const ShadowEstimate& shadow = latest_->snapshot.shadow;
        if (!shadow.active || !finite_position(shadow.estimate)) {
            return;
        }
        const double radius =
            std::max(shadow_ellipse_.valid ? shadow_ellipse_.semi_major * scale() : 0.0,
                     kArenaSizes.label_clearance * settings_.style.line_scale);
        const QPointF at = transform_.map(QPointF(shadow.estimate(kX), shadow.estimate(kY)));
        const double away = radius * kArenaSizes.label_reach + kArenaSizes.label_offset;
        const QFontMetricsF metrics(settings_.style.font);
        const QString name = arena_text::kind_text(shadow.kind);
        const QSizeF offset = kArenaSizes.shadow_label_offset;
        arena_.label(at
                         + QPointF(-away - metrics.horizontalAdvance(name) - offset.width(),
                                   away + metrics.height() + offset.height()),
                     name, colors().shadow);
    }

    /// The pose being picked and what to do, "No run yet", the frame times.
    void overlays() {
        if (settings_.picking) {
            if (settings_.picked_pose) {
                arena_.robot(*settings_.picked_pose, history_.scene().ir_mount, colors().truth,
                             true);
                arena_.pose_marker(*settings_.picked_pose, colors().truth);
            }
            arena_.banner(arena_text::tr(
                              "Kidnap: click where to put the robot, drag to aim it · Esc cancels"),
                          widget_);
        }
        if (latest_ == nullptr) {
            arena_.centred_text(arena_text::tr("No run yet"), widget_);
        }
        if (settings_.frame_times) {
            const FrameStats::Summary& summary = *settings_.frame_times;
            arena_.corner_text(arena_text::tr("frame mean %1 ms · p99 %2 ms · max %3 ms")
                                   .arg(summary.mean_ms, 0, 'f', 1)
                                   .arg(summary.p99_ms, 0, 'f', 1)
                                   .arg(summary.max_ms, 0, 'f', 1),
                               widget_, Qt::AlignRight | Qt::AlignBottom);
        }
    }

    QPainter& painter_;
    const QRectF widget_;
    const RunHistory& history_;
    const ArenaCaches& caches_;
    const ArenaFrameSettings& settings_;
    std::span<const ArenaLayer* const> layers_;
    const QTransform transform_;
    ArenaPainter arena_;
    const RunSample* latest_;
    const ArenaFrame layer_frame_;
    CovarianceEllipse ellipse_;
    CovarianceEllipse shadow_ellipse_;
};

}  // namespace

void paint_arena(QPainter& painter, const QRectF& widget, const RunHistory& history,
                 const ArenaCaches& caches, const ArenaFrameSettings& settings,
                 std::span<const ArenaLayer* const> layers) {
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    FramePainter(painter, widget, history, caches, settings, layers).paint();
}

}  // namespace legofeup::ui
