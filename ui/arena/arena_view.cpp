#include "legofeup/ui/arena/arena_view.hpp"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <vector>

#include "legofeup/core/angles.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/arena/map_image.hpp"

namespace legofeup::ui {

namespace {

constexpr double kZoomStep = 1.25;  ///< per wheel notch and per zoomIn()/zoomOut()
/// The legend folds into a tab when giving it room would leave the arena less than this
/// share of the scale it has without it.
constexpr double kLegendFoldRatio = 0.7;
constexpr double kMinGridPixels = 24.0;  ///< the grid's lines at least this far apart

/// The grid's spacing: 0.5 m, or 1, 2, 5, 10 … m when the lines would be too dense.
double grid_spacing(double pixels_per_metre) {
    double spacing = 0.5;
    for (const double step : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0}) {
        if (spacing * pixels_per_metre >= kMinGridPixels) {
            break;
        }
        spacing = step;
    }
    return spacing;
}

bool finite_position(const StateVector& x) {
    return std::isfinite(x(kX)) && std::isfinite(x(kY));
}

QString kind_text(FilterKind kind) {
    return kind == FilterKind::Ukf ? QStringLiteral("UKF") : QStringLiteral("EKF");
}

/// What the primary estimate is, for the legend: "EKF", "UKF" or "5-state EKF".
QString estimator_text(Localisation localisation, FilterKind kind) {
    return localisation == Localisation::GyroFusion ? QStringLiteral("5-state EKF")
                                                    : kind_text(kind);
}

}  // namespace

ArenaView::ArenaView(const RunHistory& history, QWidget* parent)
    : QWidget(parent), history_(history) {
    setFocusPolicy(Qt::ClickFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent fills every pixel
    setMouseTracking(true);                 // a folded legend opens under the mouse
    setToolTip(ellipseNote());
    cache_.rebuild(history_, confidence_);
    fitToArena();
}

QSize ArenaView::sizeHint() const {
    return {640, 560};
}

QSize ArenaView::minimumSizeHint() const {
    return {240, 200};
}

// ---- settings ---------------------------------------------------------------------------

void ArenaView::setEllipseConfidence(EllipseConfidence level) {
    if (level == confidence_) {
        return;
    }
    confidence_ = level;
    cache_.set_confidence(history_, confidence_);
    setToolTip(ellipseNote());
    update();
}

void ArenaView::setFollowRobot(bool on) {
    if (on == follow_) {
        return;
    }
    if (!on) {
        camera_ = effectiveCamera();  // stay where following left the view
    }
    follow_ = on;
    fitted_ = false;
    update();
    emit followRobotChanged(on);
}

void ArenaView::setShowTrail(bool on) {
    show_trail_ = on;
    layoutChanged();
}

void ArenaView::setShowOdometry(bool on) {
    show_odometry_ = on;
    layoutChanged();
}

void ArenaView::setShowTruth(bool on) {
    show_truth_ = on;
    layoutChanged();
}

void ArenaView::setShowLegend(bool on) {
    show_legend_ = on;
    layoutChanged();
}

void ArenaView::setShowFrameTimes(bool on) {
    show_frame_times_ = on;
    update();
}

void ArenaView::setTextScale(double scale) {
    if (!std::isfinite(scale)) {
        return;
    }
    text_scale_ = std::clamp(scale, 0.5, 4.0);
    layoutChanged();  // the legend and the margin for the wall names grow with the text
}

void ArenaView::layoutChanged() {
    if (fitted_) {
        fitToArena();  // the legend's size changed
    }
    update();
}

double ArenaView::lineScale() const {
    // Lines grow half as fast as text, and never get thinner than normal.
    return std::max(1.0, 1.0 + 0.5 * (text_scale_ - 1.0));
}

// ---- accessors --------------------------------------------------------------------------

QString ArenaView::ellipseLabel() const {
    return QString::fromUtf8(confidence_label(confidence_));
}

QString ArenaView::ellipseNote() const {
    return QString::fromUtf8(confidence_note(confidence_));
}

WorldCamera ArenaView::effectiveCamera() const {
    WorldCamera camera = camera_;
    if (follow_ && !history_.empty() && finite_position(history_.latest().snapshot.estimate)) {
        const StateVector& x = history_.latest().snapshot.estimate;
        camera.set_centre(QPointF(x(kX), x(kY)));
    }
    return camera;
}

QTransform ArenaView::worldToWidget() const {
    return effectiveCamera().transform(QSizeF(size()));
}

QRectF ArenaView::visibleWorldRect() const {
    return effectiveCamera().visible_world(QSizeF(size()));
}

qsizetype ArenaView::cachedPathPointCount() const {
    return cache_.estimate_path().size();
}

int ArenaView::trailEllipseCount() const {
    return static_cast<int>(cache_.trail().size());
}

// ---- history ----------------------------------------------------------------------------

void ArenaView::historyRestarted() {
    cache_.rebuild(history_, confidence_);
    layer_.clear();
    fitToArena();
    update();
}

void ArenaView::samplesAppended(int first, int count) {
    if (count <= 0 || first < 0) {
        return;
    }
    // The cache takes every sample it has not seen (and rebuilds if the history restarted
    // behind our back), so a skipped or repeated notification cannot corrupt it.
    cache_.update(history_, confidence_);
    // The legend changes when the run turns out to have a second filter or no IR: lay it
    // out again (and refit).
    if (legendTexts() != legend_texts_) {
        if (fitted_) {
            fitToArena();
        } else {
            layoutLegend();
        }
    }
    update();
}

// ---- view -------------------------------------------------------------------------------

QFont ArenaView::scaledFont() const {
    QFont scaled = font();
    scaled.setPointSizeF(scaled.pointSizeF() * text_scale_);
    return scaled;
}

QFont ArenaView::legendFont() const {
    QFont scaled = font();
    scaled.setPointSizeF(scaled.pointSizeF() * lineScale());
    return scaled;
}

double ArenaView::fitMargin() const {
    // Room for the wall names outside the walls.
    return 16.0 + QFontMetricsF(scaledFont()).height() * 0.85 * 1.4;
}

QRectF ArenaView::layoutLegend() {
    QRectF world = cache_.world_bounds();
    if (world.isNull()) {
        world = QRectF(-1.5, -1.5, 3.0, 3.0);
    }
    const QSizeF viewport(size());
    const double margin = fitMargin();
    const QRectF area =
        QRectF(QPointF(0.0, 0.0), viewport).adjusted(margin, margin, -margin, -margin);
    const std::vector<LegendRow> rows = show_legend_ ? legendRows() : std::vector<LegendRow>{};
    legend_texts_ = legendTexts();
    legend_layout_ = {};
    legend_folded_ = false;
    if (rows.empty()) {
        return area;
    }
    // The legend's box sits 10 px from the top-right corner. Beside the arena: one column as
    // tall as the widget allows; above it: a strip as wide as the widget, as flat as fits.
    const QFont font = legendFont();
    const LegendLayout beside = legend_layout(rows, font, viewport.height() - 20.0);
    const LegendLayout above = legend_layout_within_width(rows, font, viewport.width() - 20.0);
    // The margin (room for the wall names) is kept between the legend and the arena too.
    const QRectF beside_area = area.adjusted(0.0, 0.0, -(beside.size.width() + 10.0), 0.0);
    const QRectF above_area = area.adjusted(0.0, above.size.height() + 10.0, 0.0, 0.0);
    const auto fit_scale = [&world](const QRectF& r) {
        if (r.width() <= 0.0 || r.height() <= 0.0) {
            return 0.0;
        }
        return std::min(r.width() / std::max(world.width(), 1e-9),
                        r.height() / std::max(world.height(), 1e-9));
    };
    const bool use_beside = fit_scale(beside_area) >= fit_scale(above_area);
    legend_layout_ = use_beside ? beside : above;
    const QRectF best = use_beside ? beside_area : above_area;
    // A widget too small to give the legend room without shrinking the arena a lot keeps the
    // arena whole and folds the legend into a tab that opens while the mouse is over it.
    legend_folded_ = fit_scale(best) < kLegendFoldRatio * fit_scale(area);
    if (legend_folded_) {
        legend_layout_ = legend_layout(rows, font, viewport.height() - 20.0);
        return area;
    }
    return best;
}

void ArenaView::fitToArena() {
    QRectF world = cache_.world_bounds();
    if (world.isNull()) {
        world = QRectF(-1.5, -1.5, 3.0, 3.0);
    }
    camera_.fit(world, layoutLegend(), QSizeF(size()));
    fitted_ = true;
}

void ArenaView::fitArena() {
    setFollowRobot(false);
    fitToArena();
    update();
}

void ArenaView::zoomBy(double factor, const QPointF& anchor) {
    camera_ = effectiveCamera();
    camera_.zoom_about(factor, follow_ ? QPointF(width() / 2.0, height() / 2.0) : anchor,
                       QSizeF(size()));
    fitted_ = false;
    update();
}

void ArenaView::zoomIn() {
    zoomBy(kZoomStep, QPointF(width() / 2.0, height() / 2.0));
}

void ArenaView::zoomOut() {
    zoomBy(1.0 / kZoomStep, QPointF(width() / 2.0, height() / 2.0));
}

// ---- painting ---------------------------------------------------------------------------

void ArenaView::paintEvent(QPaintEvent* /*event*/) {
    const FrameTimer timer(stats_);
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);

    ArenaStyle style;
    style.colors = arena_colors(palette());
    style.font = scaledFont();
    style.legend_font = legendFont();
    style.line_scale = lineScale();
    const ArenaColors& colors = style.colors;

    const QRectF widget_rect(rect());
    painter.fillRect(widget_rect, colors.background);

    const WorldCamera camera = effectiveCamera();
    const QTransform transform = camera.transform(widget_rect.size());
    const QRectF visible = camera.visible_world(widget_rect.size());
    const ArenaScene& scene = history_.scene();
    ArenaPainter arena(painter, transform, style);

    const RunSample* latest = history_.empty() ? nullptr : &history_.latest();
    const int matched_wall = latest != nullptr && latest->snapshot.association.associated()
                                 ? latest->snapshot.association.wall
                                 : -1;

    // 1. The fixed scene: the grid, the map over it (its free cells let the grid show), the
    //    walls and the path.
    arena.grid(visible, grid_spacing(camera.scale()));
    updateMapImages(colors);
    if (scene.map) {
        arena.map(map_image_, image_to_world(*scene.map));
    }
    if (scene.filter_map) {
        arena.map(filter_map_image_, image_to_world(*scene.filter_map));
    }
    arena.intended_path(cache_.intended_path());
    arena.walls(scene.walls, matched_wall);

    // 2. History: the trail and the three paths. A still view keeps them as a picture and
    //    adds only what is new; while following, the view moves every frame, so they are
    //    drawn directly, simplified to half a pixel.
    const double tolerance = 0.5 / camera.scale();
    if (latest != nullptr && !follow_) {
        HistoryLayer::Settings settings;
        settings.world_to_widget = transform;
        settings.size = size();
        settings.device_pixel_ratio = painter.device()->devicePixelRatioF();
        settings.line_scale = style.line_scale;
        settings.trail = colors.trail.rgba();
        settings.odometry = colors.odometry.rgba();
        settings.truth = colors.truth.rgba();
        settings.estimate = colors.estimate.rgba();
        settings.show_trail = show_trail_;
        settings.show_odometry = show_odometry_;
        settings.show_truth = show_truth_;
        settings.epoch = history_.epoch();
        settings.confidence = confidence_;
        layer_.paint(painter, settings, cache_, style);
    } else if (latest != nullptr) {
        if (show_trail_) {
            arena.trail(cache_.trail_path());
        }
        if (show_odometry_) {
            arena.polyline(cache_.odometry_path().simplified(tolerance), colors.odometry, 1.0);
        }
        if (show_truth_) {
            for (const QPolygonF& before : cache_.truth_before_jumps()) {
                arena.polyline(before, colors.truth, 1.0);
            }
            arena.polyline(cache_.truth_path().simplified(tolerance), colors.truth, 1.0);
        }
        arena.polyline(cache_.estimate_path().simplified(tolerance), colors.estimate, 1.0);
    }

    // 3. The latest step: the laser scans, beacons, ghost, real robot, IR or bearing rays,
    //    the other filter kind's estimate, ellipse, estimate.
    const LaserScanPoints scan = laserScanPoints();
    arena.scan_points(scan.expected, colors.expected_scan, 3.0);
    if (show_truth_) {
        arena.scan_points(scan.measured_at_truth, colors.truth_scan, 2.5);
    }
    arena.scan_points(scan.measured, scan.matched ? colors.associated : colors.rejected, 3.0);
    arena.beacons(scene.beacons);
    CovarianceEllipse ellipse;
    CovarianceEllipse shadow_ellipse;
    if (latest != nullptr) {
        const LoopSnapshot& snapshot = latest->snapshot;
        if (show_odometry_) {
            arena.robot(snapshot.odometry_pose, scene.ir_mount, colors.odometry, true);
        }
        if (show_truth_ && latest->truth) {
            arena.robot(latest->truth->pose, scene.ir_mount, colors.truth, false);
        }
        if (snapshot.localisation == Localisation::Walls) {
            arena.ir_rays(snapshot, scene.ir_mount, scene.ir_max_range);
        }
        if (!scene.beacons.empty()) {
            arena.beacon_rays(snapshot, scene.beacons);
        }
        if (snapshot.shadow.active) {
            const StateVector& shadow = snapshot.shadow.estimate;
            shadow_ellipse = covariance_ellipse(
                Vector2(shadow(kX), shadow(kY)),
                snapshot.shadow.covariance.topLeftCorner<2, 2>().eval(), confidence_);
            arena.shadow_estimate(to_pose(shadow), shadow_ellipse);
        }
        ellipse = sample_ellipse(*latest, confidence_);
        arena.ellipse(ellipse);
        arena.estimate_marker(to_pose(snapshot.estimate));
    }

    // 4. Text and overlays, in widget pixels.
    arena.wall_names(scene.walls, cache_.world_bounds());
    if (latest != nullptr && finite_position(latest->snapshot.estimate)) {
        const StateVector& x = latest->snapshot.estimate;
        const QPointF at = transform.map(QPointF(x(kX), x(kY)));
        // Clear of the ellipse and of the robot drawn around the estimate.
        const double radius =
            std::max({ellipse.valid ? ellipse.semi_major * camera.scale() : 0.0,
                      RobotOutline::kLength * 0.6 * camera.scale(), 18.0 * style.line_scale});
        const double reach = radius * 0.75 + 6.0;
        QString text = ellipseLabel();
        if (!ellipse.valid) {
            text += QStringLiteral(" (P not positive semi-definite)");
        }
        arena.label(at + QPointF(reach, -reach), text, colors.ellipse);
        const ShadowEstimate& shadow = latest->snapshot.shadow;
        if (shadow.active && finite_position(shadow.estimate)) {
            // The other filter's name below-left of its estimate, clear of the label above.
            const double shadow_radius =
                std::max(shadow_ellipse.valid ? shadow_ellipse.semi_major * camera.scale() : 0.0,
                         18.0 * style.line_scale);
            const QPointF shadow_at =
                transform.map(QPointF(shadow.estimate(kX), shadow.estimate(kY)));
            const double away = shadow_radius * 0.75 + 6.0;
            const QFontMetricsF metrics(style.font);
            arena.label(
                shadow_at
                    + QPointF(-away - metrics.horizontalAdvance(kind_text(shadow.kind)) - 8.0,
                              away + metrics.height() + 4.0),
                kind_text(shadow.kind), colors.shadow);
        }
    }

    if (const QString status = laserStatusText(); !status.isEmpty()) {
        // Top left, clear of the scale bar (bottom left); below the legend when the legend is
        // a strip across the top.
        const LaserUpdate& laser = latest_scan_sample(history_)->snapshot.laser;
        const QColor color = laser.matched ? colors.associated : colors.rejected;
        const QFontMetricsF metrics(style.font);
        const QSizeF size(metrics.horizontalAdvance(status) + 8.0, metrics.height() + 4.0);
        double top = 10.0;
        if (const QRectF legend = legendRect();
            !legend.isEmpty() && legend.intersects(QRectF(QPointF(10.0, top), size))) {
            top = legend.bottom() + 6.0;
        }
        arena.label(QPointF(10.0, top + size.height()), status, color);
    }
    if (show_legend_ && legend_folded_ && !legend_open_) {
        arena.corner_text(tr("Legend ◂"), widget_rect, Qt::AlignRight | Qt::AlignTop);
    } else if (show_legend_) {
        arena.legend(legendRows(), legend_layout_, QPointF(widget_rect.right() - 10.0, 10.0));
    }
    arena.scale_bar(camera.scale(), widget_rect);
    if (picking_) {
        if (pick_pressed_) {
            const Pose2 pose = pickedPose(pick_cursor_);
            arena.robot(pose, scene.ir_mount, colors.truth, true);
            arena.pose_marker(pose, colors.truth);
        }
        arena.banner(tr("Kidnap: click where to put the robot, drag to aim it · Esc cancels"),
                     widget_rect);
    }

    if (latest == nullptr) {
        arena.centred_text(tr("No run yet"), widget_rect);
    }
    if (show_frame_times_) {
        const FrameStats::Summary summary = stats_.summary();
        arena.corner_text(tr("frame mean %1 ms · p99 %2 ms · max %3 ms")
                              .arg(summary.mean_ms, 0, 'f', 1)
                              .arg(summary.p99_ms, 0, 'f', 1)
                              .arg(summary.max_ms, 0, 'f', 1),
                          widget_rect, Qt::AlignRight | Qt::AlignBottom);
    }
}

QStringList ArenaView::legendTexts() const {
    QStringList texts;
    for (const LegendRow& row : legendRows()) {
        for (const LegendEntry& entry : row) {
            texts << entry.text;
        }
    }
    return texts;
}

QRectF ArenaView::legendRect() const {
    if (!show_legend_ || legend_layout_.empty()) {
        return {};
    }
    if (legend_folded_ && !legend_open_) {
        // The tab: corner_text's box for "Legend ◂".
        const QFontMetricsF metrics(scaledFont());
        const QSizeF size(metrics.horizontalAdvance(tr("Legend ◂")) + 12.0, metrics.height() + 6.0);
        return {QPointF(width() - 10.0 - size.width(), 10.0), size};
    }
    return {QPointF(width() - 10.0 - legend_layout_.size.width(), 10.0), legend_layout_.size};
}

void ArenaView::setLegendOpen(bool open) {
    if (open != legend_open_) {
        legend_open_ = open;
        update();
    }
}

LaserScanPoints ArenaView::laserScanPoints() const {
    const ArenaScene& scene = history_.scene();
    if (!scene.laser.active) {
        return {};
    }
    const RunSample* sample = latest_scan_sample(history_);
    return sample != nullptr ? laser_scan_points(*sample, scene.laser) : LaserScanPoints{};
}

QString ArenaView::laserStatusText() const {
    const ArenaScene& scene = history_.scene();
    if (!scene.laser.active) {
        return {};
    }
    const RunSample* sample = latest_scan_sample(history_);
    return sample != nullptr ? laser_status_text(sample->snapshot.laser, scene.laser) : QString();
}

void ArenaView::updateMapImages(const ArenaColors& colors) {
    const ArenaScene& scene = history_.scene();
    const QRgb colour = colors.map_occupied.rgba();
    if (scene.map.get() != map_source_ || colour != map_colour_) {
        map_source_ = scene.map.get();
        map_image_ =
            scene.map ? map_image(*scene.map, {colors.map_occupied, colors.map_unknown}) : QImage();
    }
    if (scene.filter_map.get() != filter_map_source_ || colour != map_colour_) {
        filter_map_source_ = scene.filter_map.get();
        // The filter's own (outdated) map over the world's: its walls tinted, half seen.
        filter_map_image_ = scene.filter_map
                                ? map_image(*scene.filter_map, {colors.filter_map, Qt::transparent})
                                : QImage();
    }
    map_colour_ = colour;
}

std::vector<LegendRow> ArenaView::legendRows() const {
    using Swatch = LegendEntry::Swatch;
    const ArenaColors colors = arena_colors(palette());
    const ArenaScene& scene = history_.scene();
    // Before the first sample, assume the run will have truth (so the fit leaves room).
    const bool truth = history_.empty() || history_.latest().truth.has_value();
    const LoopSnapshot* latest = history_.empty() ? nullptr : &history_.latest().snapshot;
    const bool beacons = !scene.beacons.empty();
    // The IR rays belong to the wall lesson; before the first sample, a world with beacons
    // or the laser is taken to be their lesson's.
    const bool walls = latest != nullptr ? latest->localisation == Localisation::Walls
                                         : !beacons && !scene.laser.active;
    std::vector<LegendRow> legend;
    if (show_truth_ && truth) {
        legend.push_back({{Swatch::Line, colors.truth, tr("true robot")}});
    }
    legend.push_back(
        {{Swatch::Line, colors.estimate,
          tr("estimate (%1)")
              .arg(latest != nullptr ? estimator_text(latest->localisation, latest->filter_kind)
                                     : kind_text(FilterKind::Ekf))}});
    if (latest != nullptr && latest->shadow.active) {
        legend.push_back({{Swatch::DashedEllipse, colors.shadow,
                           tr("%1 on the same frames, its ellipse dashed")
                               .arg(kind_text(latest->shadow.kind))}});
    }
    if (show_odometry_) {
        legend.push_back({{Swatch::Line, colors.odometry, tr("odometry only (ghost dashed)")}});
    }
    legend.push_back({{Swatch::Ellipse, colors.ellipse, ellipseNote()}});
    if (show_trail_) {
        legend.push_back({{Swatch::Line, colors.trail, tr("past ellipses, one per second")}});
    }
    if (walls) {
        legend.push_back({{Swatch::Band, colors.associated, tr("IR rays used; the wall matched")}});
        legend.push_back({{Swatch::Line, colors.rejected, tr("IR rays not used")},
                          {Swatch::Dashed, colors.out_of_range, tr("out of range")}});
    }
    if (beacons) {
        legend.push_back({{Swatch::Diamond, colors.beacon, tr("beacons")}});
        legend.push_back({{Swatch::Line, colors.associated, tr("bearings measured, applied")},
                          {Swatch::Line, colors.rejected, tr("not applied")}});
        legend.push_back({{Swatch::Dashed, colors.foreground, tr("bearings the filter expected")}});
    }
    if (scene.map) {
        legend.push_back({{Swatch::Box, colors.map_occupied, tr("map: occupied")},
                          {Swatch::Box, colors.map_unknown, tr("unknown")}});
    }
    if (scene.filter_map) {
        legend.push_back({{Swatch::Box, colors.filter_map, tr("the filter's map (outdated)")}});
    }
    if (scene.laser.active) {
        legend.push_back({{Swatch::Dots, colors.associated, tr("scan at the estimate: matched")},
                          {Swatch::Dots, colors.rejected, tr("mismatch")}});
        LegendRow expected{{Swatch::Dots, colors.expected_scan, tr("expected (ray-cast)")}};
        if (show_truth_ && truth) {
            expected.push_back({Swatch::Dots, colors.truth_scan, tr("scan at the true pose")});
        }
        legend.push_back(expected);
    }
    if (!scene.path.empty()) {
        legend.push_back({{Swatch::Dashed, colors.path, tr("intended path")}});
    }
    return legend;
}

// ---- kidnapping -------------------------------------------------------------------------

void ArenaView::beginPosePick() {
    picking_ = true;
    pick_pressed_ = false;
    dragging_ = false;
    setCursor(Qt::CrossCursor);
    setFocus(Qt::OtherFocusReason);  // Esc reaches us
    update();
}

void ArenaView::cancelPosePick() {
    if (!picking_) {
        return;
    }
    picking_ = false;
    pick_pressed_ = false;
    unsetCursor();
    update();
    emit posePickCancelled();
}

double ArenaView::currentHeading() const {
    if (history_.empty()) {
        return 0.0;
    }
    const RunSample& latest = history_.latest();
    return latest.truth ? latest.truth->pose.theta : latest.snapshot.estimate(kTheta);
}

Pose2 ArenaView::pickedPose(const QPointF& cursor) const {
    bool invertible = false;
    const QTransform to_world = worldToWidget().inverted(&invertible);
    const QPointF at = to_world.map(pick_from_);
    Pose2 pose{at.x(), at.y(), currentHeading()};
    // A drag of a few pixels aims the robot; less is a click.
    const QPointF drag = cursor - pick_from_;
    if (std::hypot(drag.x(), drag.y()) >= 8.0) {
        const QPointF to = to_world.map(cursor);
        pose.theta = std::atan2(to.y() - at.y(), to.x() - at.x());
    }
    pose.theta = wrap_angle(pose.theta);
    return pose;
}

// ---- events -----------------------------------------------------------------------------

void ArenaView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (fitted_) {
        fitToArena();
    }
}

void ArenaView::wheelEvent(QWheelEvent* event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    zoomBy(std::pow(kZoomStep, notches), event->position());
    event->accept();
}

void ArenaView::mousePressEvent(QMouseEvent* event) {
    if (picking_) {
        if (event->button() == Qt::LeftButton) {
            pick_pressed_ = true;
            pick_from_ = event->position();
            pick_cursor_ = event->position();
            update();
        } else {
            cancelPosePick();  // another button: no kidnapping
        }
        event->accept();
        return;
    }
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    dragging_ = true;
    drag_last_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    event->accept();
}

void ArenaView::mouseMoveEvent(QMouseEvent* event) {
    if (picking_) {
        if (pick_pressed_) {
            pick_cursor_ = event->position();
            update();
        }
        event->accept();
        return;
    }
    if (!dragging_) {
        // A folded legend opens while the mouse is over its tab (or over it, once open).
        if (legend_folded_) {
            setLegendOpen(legendRect().contains(event->position()));
        }
        QWidget::mouseMoveEvent(event);
        return;
    }
    const QPointF delta = event->position() - drag_last_;
    drag_last_ = event->position();
    if (delta.isNull()) {
        return;
    }
    setFollowRobot(false);
    camera_.pan_by(delta);
    fitted_ = false;
    update();
    event->accept();
}

void ArenaView::mouseReleaseEvent(QMouseEvent* event) {
    if (picking_ && pick_pressed_ && event->button() == Qt::LeftButton) {
        const Pose2 pose = pickedPose(event->position());
        picking_ = false;
        pick_pressed_ = false;
        unsetCursor();
        update();
        event->accept();
        emit posePicked(pose);
        return;
    }
    if (event->button() != Qt::LeftButton || !dragging_) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    dragging_ = false;
    unsetCursor();
    event->accept();
}

void ArenaView::mouseDoubleClickEvent(QMouseEvent* event) {
    if (picking_) {
        event->accept();  // a pick, not a fit
        return;
    }
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseDoubleClickEvent(event);
        return;
    }
    fitArena();
    event->accept();
}

void ArenaView::keyPressEvent(QKeyEvent* event) {
    // Only the zoom keys; the driving keys (arrows, WASD, space) and everything else go on
    // to the main window.
    if (picking_ && event->key() == Qt::Key_Escape) {
        cancelPosePick();
        event->accept();
        return;
    }
    switch (event->key()) {
        case Qt::Key_Plus:
        case Qt::Key_Equal:
            zoomIn();
            event->accept();
            return;
        case Qt::Key_Minus:
            zoomOut();
            event->accept();
            return;
        default:
            event->ignore();
            return;
    }
}

void ArenaView::leaveEvent(QEvent* event) {
    setLegendOpen(false);
    QWidget::leaveEvent(event);
}

void ArenaView::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    switch (event->type()) {
        case QEvent::PaletteChange:
        case QEvent::FontChange:
        case QEvent::StyleChange:
            update();
            break;
        default:
            break;
    }
}

}  // namespace legofeup::ui
