#include "legofeup/ui/arena/arena_view.hpp"

#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "legofeup/ui/arena/arena_renderer.hpp"
#include "legofeup/ui/arena/arena_sizes.hpp"
#include "legofeup/ui/arena/legend_rows.hpp"

namespace legofeup::ui {

ArenaView::ArenaView(const RunHistory& history, QWidget* parent)
    : ArenaView(history, built_in_arena_layers(), parent) {}

ArenaView::ArenaView(const RunHistory& history, ArenaLayerRegistry layers, QWidget* parent)
    : QWidget(parent), history_(history), layers_(std::move(layers)) {
    setFocusPolicy(Qt::ClickFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);  // paintEvent fills every pixel
    setMouseTracking(true);                 // a folded legend opens under the mouse
    setToolTip(ellipseNote());
    cache_.rebuild(history_, confidence_);
    fitToArena();
}

QSize ArenaView::sizeHint() const {
    return kArenaSizes.preferred;
}

QSize ArenaView::minimumSizeHint() const {
    return kArenaSizes.minimum;
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
    if (!camera_.set_following(on, follow_point(history_))) {
        return;
    }
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
    text_scale_ = std::clamp(scale, kArenaSizes.min_text_scale, kArenaSizes.max_text_scale);
    layoutChanged();  // the legend and the margin for the wall names grow with the text
}

void ArenaView::layoutChanged() {
    if (camera_.fitted()) {
        fitToArena();  // the legend's size changed
    }
    update();
}

double ArenaView::lineScale() const {
    // Lines grow more slowly than text, and never get thinner than normal.
    return std::max(1.0, 1.0 + kArenaSizes.line_growth * (text_scale_ - 1.0));
}

// ---- accessors --------------------------------------------------------------------------

QString ArenaView::ellipseLabel() const {
    return QString::fromUtf8(confidence_label(confidence_));
}

QString ArenaView::ellipseNote() const {
    return QString::fromUtf8(confidence_note(confidence_));
}

WorldCamera ArenaView::shownCamera() const {
    return camera_.shown(follow_point(history_));
}

QTransform ArenaView::worldToWidget() const {
    return shownCamera().transform(QSizeF(size()));
}

QTransform ArenaView::widgetToWorld() const {
    bool invertible = false;
    return worldToWidget().inverted(&invertible);
}

QRectF ArenaView::visibleWorldRect() const {
    return shownCamera().visible_world(QSizeF(size()));
}

qsizetype ArenaView::cachedPathPointCount() const {
    return cache_.estimate_path().size();
}

int ArenaView::trailEllipseCount() const {
    return static_cast<int>(cache_.trail().size());
}

LaserScanPoints ArenaView::laserScanPoints() const {
    return latest_laser_scan_points(history_);
}

QString ArenaView::laserStatusText() const {
    return latest_laser_status_text(history_);
}

// ---- history ----------------------------------------------------------------------------

void ArenaView::historyRestarted() {
    cache_.rebuild(history_, confidence_);
    history_picture_.clear();
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
    if (legendTexts() != legend_.texts()) {
        if (camera_.fitted()) {
            fitToArena();
        } else {
            layoutLegend();
        }
    }
    update();
}

// ---- the legend -------------------------------------------------------------------------

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

std::span<const ArenaLayer* const> ArenaView::lessonLayers() const {
    return layers_for(layers_, shown_localisation(history_));
}

std::vector<LegendRow> ArenaView::legendRows() const {
    const LegendOptions options{show_truth_, show_odometry_, show_trail_, confidence_};
    return arena_legend_rows(history_, arena_colors(palette()), options, lessonLayers());
}

QStringList ArenaView::legendTexts() const {
    return legend_texts(legendRows());
}

QRectF ArenaView::legendRect() const {
    return legend_.box(show_legend_, width(), scaledFont());
}

void ArenaView::setLegendOpen(bool open) {
    if (legend_.set_open(open)) {
        update();
    }
}

// ---- the camera -------------------------------------------------------------------------

double ArenaView::fitMargin() const {
    // Room for the wall names outside the walls.
    return kArenaSizes.fit_margin
           + QFontMetricsF(scaledFont()).height() * kArenaSizes.wall_name_font
                 * kArenaSizes.wall_name_lines;
}

QRectF ArenaView::fittedWorld() const {
    const QRectF world = cache_.world_bounds();
    return world.isNull() ? QRectF(-1.5, -1.5, 3.0, 3.0) : world;
}

QRectF ArenaView::layoutLegend() {
    const QSizeF viewport(size());
    const double margin = fitMargin();
    const QRectF area =
        QRectF(QPointF(0.0, 0.0), viewport).adjusted(margin, margin, -margin, -margin);
    return legend_.place(legendRows(), show_legend_, legendFont(), viewport, area, fittedWorld());
}

void ArenaView::fitToArena() {
    const QRectF area = layoutLegend();
    camera_.fit(fittedWorld(), area, QSizeF(size()));
}

void ArenaView::fitArena() {
    setFollowRobot(false);
    fitToArena();
    update();
}

void ArenaView::zoomBy(double factor, const QPointF& anchor) {
    camera_.zoom_by(factor, anchor, QSizeF(size()), follow_point(history_));
    update();
}

void ArenaView::zoomIn() {
    zoomBy(kArenaSizes.zoom_step, QPointF(width() / 2.0, height() / 2.0));
}

void ArenaView::zoomOut() {
    zoomBy(1.0 / kArenaSizes.zoom_step, QPointF(width() / 2.0, height() / 2.0));
}

// ---- painting ---------------------------------------------------------------------------

void ArenaView::paintEvent(QPaintEvent* /*event*/) {
    const FrameTimer timer(stats_);
    QPainter painter(this);
    ArenaFrameSettings frame;
    frame.camera = shownCamera();
    frame.following = camera_.following();
    frame.style.colors = arena_colors(palette());
    frame.style.font = scaledFont();
    frame.style.legend_font = legendFont();
    frame.style.line_scale = lineScale();
    frame.show_trail = show_trail_;
    frame.show_odometry = show_odometry_;
    frame.show_truth = show_truth_;
    frame.confidence = confidence_;
    frame.show_legend = show_legend_;
    frame.legend_tab_only = legend_.tab_only();
    if (show_legend_ && !legend_.tab_only()) {
        frame.legend_rows = legendRows();
    }
    frame.legend_layout = legend_.layout();
    frame.legend_box = legendRect();
    frame.picking = picker_.active();
    if (picker_.pressed()) {
        frame.picked_pose = picker_.pose_now(widgetToWorld(), currentHeading());
    }
    if (show_frame_times_) {
        frame.frame_times = stats_.summary();
    }
    paint_arena(painter, QRectF(rect()), history_, {cache_, history_picture_, maps_}, frame,
                lessonLayers());
}

// ---- kidnapping -------------------------------------------------------------------------

void ArenaView::beginPosePick() {
    picker_.begin();
    dragging_ = false;
    setCursor(Qt::CrossCursor);
    setFocus(Qt::OtherFocusReason);  // Esc reaches us
    update();
}

void ArenaView::cancelPosePick() {
    if (!picker_.cancel()) {
        return;
    }
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

// ---- events -----------------------------------------------------------------------------

void ArenaView::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (camera_.fitted()) {
        fitToArena();
    }
}

void ArenaView::wheelEvent(QWheelEvent* event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    zoomBy(std::pow(kArenaSizes.zoom_step, notches), event->position());
    event->accept();
}

void ArenaView::mousePressEvent(QMouseEvent* event) {
    if (picker_.active()) {
        if (event->button() == Qt::LeftButton) {
            picker_.press(event->position());
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
    if (picker_.active()) {
        if (picker_.pressed()) {
            picker_.move_to(event->position());
            update();
        }
        event->accept();
        return;
    }
    if (!dragging_) {
        // A folded legend opens while the mouse is over its tab (or over it, once open).
        if (legend_.folded()) {
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
    update();
    event->accept();
}

void ArenaView::mouseReleaseEvent(QMouseEvent* event) {
    if (picker_.pressed() && event->button() == Qt::LeftButton) {
        const std::optional<Pose2> pose =
            picker_.release(event->position(), widgetToWorld(), currentHeading());
        unsetCursor();
        update();
        event->accept();
        if (pose) {
            emit posePicked(*pose);
        }
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
    if (picker_.active()) {
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
    if (picker_.active() && event->key() == Qt::Key_Escape) {
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
