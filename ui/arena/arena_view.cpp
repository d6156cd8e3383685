#include "legofeup/ui/arena/arena_view.hpp"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <vector>

#include "legofeup/ui/arena/arena_painter.hpp"

namespace legofeup::ui {

namespace {

constexpr double kZoomStep = 1.25;  ///< per wheel notch and per zoomIn()/zoomOut()

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
    // The legend grows when the run turns out to have a second filter or no IR: refit.
    const QSizeF legend = legend_size(legendEntries(), legendFont());
    if (legend != legend_size_) {
        legend_size_ = legend;
        if (fitted_) {
            fitToArena();
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

void ArenaView::fitToArena() {
    QRectF world = cache_.world_bounds();
    if (world.isNull()) {
        world = QRectF(-1.5, -1.5, 3.0, 3.0);
    }
    const QSizeF viewport(size());
    const double margin = fitMargin();
    QRectF area = QRectF(QPointF(0.0, 0.0), viewport).adjusted(margin, margin, -margin, -margin);
    if (show_legend_) {
        // Beside the legend or below it, whichever shows the arena larger; over it only when
        // both would shrink the arena a lot.
        const QSizeF legend = legend_size(legendEntries(), legendFont()) + QSizeF(20.0, 20.0);
        const QRectF beside = area.adjusted(0.0, 0.0, -std::max(0.0, legend.width() - margin), 0.0);
        const QRectF below = area.adjusted(0.0, std::max(0.0, legend.height() - margin), 0.0, 0.0);
        const auto fit_scale = [&world](const QRectF& r) {
            return std::min(r.width() / std::max(world.width(), 1e-9),
                            r.height() / std::max(world.height(), 1e-9));
        };
        const QRectF best = fit_scale(beside) >= fit_scale(below) ? beside : below;
        if (fit_scale(best) >= 0.7 * fit_scale(area)) {
            area = best;
        }
    }
    camera_.fit(world, area, viewport);
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

    // 1. The fixed scene.
    arena.grid(visible, 0.5);
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
            arena.polyline(cache_.truth_path().simplified(tolerance), colors.truth, 1.0);
        }
        arena.polyline(cache_.estimate_path().simplified(tolerance), colors.estimate, 1.0);
    }

    // 3. The latest step: beacons, ghost, real robot, IR or bearing rays, the other filter
    //    kind's estimate, ellipse, estimate.
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

    if (show_legend_) {
        arena.legend(legendEntries(), widget_rect);
    }
    arena.scale_bar(camera.scale(), widget_rect);

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
    for (const LegendEntry& entry : legendEntries()) {
        texts << entry.text;
    }
    return texts;
}

std::vector<LegendEntry> ArenaView::legendEntries() const {
    const ArenaColors colors = arena_colors(palette());
    // Before the first sample, assume the run will have truth (so the fit leaves room).
    const bool truth = history_.empty() || history_.latest().truth.has_value();
    const LoopSnapshot* latest = history_.empty() ? nullptr : &history_.latest().snapshot;
    const bool beacons = !history_.scene().beacons.empty();
    // The IR rays belong to the wall lesson; before the first sample, a world with beacons
    // is taken to be the beacon lesson's.
    const bool walls = latest != nullptr ? latest->localisation == Localisation::Walls : !beacons;
    std::vector<LegendEntry> legend;
    if (show_truth_ && truth) {
        legend.push_back({LegendEntry::Swatch::Line, colors.truth, tr("true robot")});
    }
    legend.push_back(
        {LegendEntry::Swatch::Line, colors.estimate,
         tr("estimate (%1)")
             .arg(latest != nullptr ? estimator_text(latest->localisation, latest->filter_kind)
                                    : kind_text(FilterKind::Ekf))});
    if (latest != nullptr && latest->shadow.active) {
        legend.push_back(
            {LegendEntry::Swatch::DashedEllipse, colors.shadow,
             tr("%1 on the same frames, its ellipse dashed").arg(kind_text(latest->shadow.kind))});
    }
    if (show_odometry_) {
        legend.push_back(
            {LegendEntry::Swatch::Line, colors.odometry, tr("odometry only (ghost dashed)")});
    }
    legend.push_back({LegendEntry::Swatch::Ellipse, colors.ellipse, ellipseNote()});
    if (show_trail_) {
        legend.push_back(
            {LegendEntry::Swatch::Line, colors.trail, tr("past ellipses, one per second")});
    }
    if (walls) {
        legend.push_back(
            {LegendEntry::Swatch::Band, colors.associated, tr("IR rays used; the wall matched")});
        legend.push_back({LegendEntry::Swatch::Line, colors.rejected, tr("IR rays not used")});
        legend.push_back({LegendEntry::Swatch::Dashed, colors.out_of_range, tr("IR out of range")});
    }
    if (beacons) {
        legend.push_back({LegendEntry::Swatch::Diamond, colors.beacon, tr("beacons")});
        legend.push_back(
            {LegendEntry::Swatch::Line, colors.associated, tr("bearings measured, applied")});
        legend.push_back(
            {LegendEntry::Swatch::Line, colors.rejected, tr("bearings measured, not applied")});
        legend.push_back(
            {LegendEntry::Swatch::Dashed, colors.foreground, tr("bearings the filter expected")});
    }
    if (!history_.scene().path.empty()) {
        legend.push_back({LegendEntry::Swatch::Dashed, colors.path, tr("intended path")});
    }
    return legend;
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
    if (!dragging_) {
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
    if (event->button() != Qt::LeftButton || !dragging_) {
        QWidget::mouseReleaseEvent(event);
        return;
    }
    dragging_ = false;
    unsetCursor();
    event->accept();
}

void ArenaView::mouseDoubleClickEvent(QMouseEvent* event) {
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
