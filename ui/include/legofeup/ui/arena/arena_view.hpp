#pragma once
// The arena view (the original LegoFeup tool's "FEllipses"): the walls, the intended path,
// the real robot, the estimate with its covariance ellipse and the trail of past ellipses,
// the odometry-only ghost, the three paths, and the IR rays coloured by whether the update
// used them; the further lessons' beacons and second filter, and the laser lesson's map and
// scans. World coordinates are metres with y up, aspect 1:1.
//
// The view reads the session's RunHistory on the GUI thread. The session calls
// samplesAppended() once per batch: the view updates its caches (docs/gui.md) and schedules
// one repaint; it never paints synchronously. Every paint's duration goes to frameStats().
//
// Interaction: the wheel zooms about the cursor, a left drag pans (and stops following the
// robot), a double click fits the arena, + and − zoom. Every other key (arrows, WASD,
// space: the main window drives the robot with them) is ignored so it reaches the window.
// While a pose is being picked (kidnapping, beginPosePick()), a press picks the place, the
// drag from it the heading, the release emits posePicked(); Esc cancels.
//
// The view is the widget only: settings, events and signals. Its parts do one job each: the
// camera (ArenaCamera), the legend's place (LegendPlacement) and rows (legend_rows.hpp),
// the kidnap picker (PosePicker), the caches (ArenaCache, HistoryLayer, MapPictures), and
// the painting of a frame (paint_arena), which draws the layers the run's lesson registered
// (arena_layers.hpp).

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <QTransform>
#include <QWidget>

#include <span>
#include <vector>

#include "legofeup/ui/arena/arena_cache.hpp"
#include "legofeup/ui/arena/arena_camera.hpp"
#include "legofeup/ui/arena/arena_layers.hpp"
#include "legofeup/ui/arena/arena_legend.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "legofeup/ui/arena/history_layer.hpp"
#include "legofeup/ui/arena/laser_layer.hpp"
#include "legofeup/ui/arena/legend_placement.hpp"
#include "legofeup/ui/arena/map_pictures.hpp"
#include "legofeup/ui/arena/pose_picker.hpp"
#include "legofeup/ui/arena/world_camera.hpp"
#include "legofeup/ui/frame_stats.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

class ArenaView : public QWidget {
    Q_OBJECT

  public:
    explicit ArenaView(const RunHistory& history, QWidget* parent = nullptr);
    /// A view drawing the lessons' layers of `layers` (built_in_arena_layers() above).
    ArenaView(const RunHistory& history, ArenaLayerRegistry layers, QWidget* parent = nullptr);

    void setEllipseConfidence(EllipseConfidence level);
    EllipseConfidence ellipseConfidence() const { return confidence_; }
    /// Keeps the latest estimate in the centre of the view (a drag turns it off).
    void setFollowRobot(bool on);
    bool followRobot() const { return camera_.following(); }
    /// The trail of past ellipses, one per second of run time.
    void setShowTrail(bool on);
    bool showTrail() const { return show_trail_; }
    void setShowOdometry(bool on);
    bool showOdometry() const { return show_odometry_; }
    void setShowTruth(bool on);
    bool showTruth() const { return show_truth_; }
    /// The legend in the top-right corner, beside or above the fitted arena (whichever
    /// leaves the arena larger), in as many columns as that needs; folded into a tab when
    /// the widget is too small for both (legendFolded()).
    void setShowLegend(bool on);
    bool showLegend() const { return show_legend_; }
    /// The frame-time overlay: "frame mean x ms · p99 y ms · max z ms".
    void setShowFrameTimes(bool on);
    bool showFrameTimes() const { return show_frame_times_; }
    /// Projector mode: labels scale by `scale`, line widths by half as much (0.5 … 4).
    void setTextScale(double scale);
    double textScale() const { return text_scale_; }

    const FrameStats& frameStats() const { return stats_; }
    /// The label drawn at the live ellipse: "1σ ellipse", "95 % ellipse" or "99 % ellipse".
    QString ellipseLabel() const;
    /// The longer legend text for the ellipse (why 1σ holds 39.3 % in 2-D).
    QString ellipseNote() const;
    /// World (metres, y up) → widget (device-independent pixels) for the current view.
    QTransform worldToWidget() const;
    /// The world rectangle currently visible.
    QRectF visibleWorldRect() const;
    /// Points in the cached (thinned) estimate path.
    qsizetype cachedPathPointCount() const;
    /// Ellipses in the cached trail.
    int trailEllipseCount() const;
    /// The legend's texts, row by row and left to right, as drawn now.
    QStringList legendTexts() const;
    /// The legend's box in widget pixels (empty when hidden; its tab when folded).
    QRectF legendRect() const;
    /// A widget too small to give the legend room folds it into a "Legend" tab in the
    /// top-right corner, so the arena keeps its size; the tab opens under the mouse.
    bool legendFolded() const { return legend_.folded(); }
    bool legendOpen() const { return legend_.open(); }
    /// Opens or closes a folded legend (the mouse does it over the tab).
    void setLegendOpen(bool open);
    /// The latest laser scan as drawn (world coordinates); empty without one.
    LaserScanPoints laserScanPoints() const;
    /// The laser status label as drawn ("ICP matched 512 pts"); empty without a scan.
    QString laserStatusText() const;
    /// The world's map as drawn (one pixel per cell), and where its pixels go in the world.
    const QImage& mapImage() const { return maps_.world_map(); }

    /// Kidnapping: the next press picks where the robot goes and the drag from there its
    /// heading (without a drag it keeps the true heading); emits posePicked().
    void beginPosePick();
    /// Leaves the pose picking without a pose (posePickCancelled()).
    void cancelPosePick();
    bool pickingPose() const { return picker_.active(); }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  public slots:
    /// The history started over: drops the caches and fits the arena.
    void historyRestarted();
    /// Samples [first, first + count) were appended: updates the caches, schedules a repaint.
    void samplesAppended(int first, int count);
    void zoomIn();
    void zoomOut();
    /// Shows the whole arena (and stops following the robot).
    void fitArena();

  signals:
    /// Following was turned on or off (a drag turns it off).
    void followRobotChanged(bool on);
    /// The pose picked for a kidnapping (world frame).
    void posePicked(const legofeup::Pose2& pose);
    void posePickCancelled();

  protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void changeEvent(QEvent* event) override;

  private:
    /// The camera as drawn: centred on the latest estimate when following.
    WorldCamera shownCamera() const;
    /// Widget pixels → world, the inverse of worldToWidget().
    QTransform widgetToWorld() const;
    /// What "fit the arena" shows (a default square before there is anything).
    QRectF fittedWorld() const;
    void fitToArena();
    /// Lays the legend out (LegendPlacement) and returns the widget area the arena is
    /// fitted into.
    QRectF layoutLegend();
    /// A setting changed what the legend holds or how large the text is.
    void layoutChanged();
    void zoomBy(double factor, const QPointF& anchor);
    double lineScale() const;
    double fitMargin() const;
    QFont scaledFont() const;
    QFont legendFont() const;
    /// The layers of the run's lesson.
    std::span<const ArenaLayer* const> lessonLayers() const;
    std::vector<LegendRow> legendRows() const;
    /// The heading a pick without a drag keeps: the truth's, else the estimate's.
    double currentHeading() const;

    const RunHistory& history_;
    ArenaLayerRegistry layers_;
    ArenaCache cache_;
    HistoryLayer history_picture_;
    MapPictures maps_;
    ArenaCamera camera_;
    LegendPlacement legend_;
    PosePicker picker_;
    FrameStats stats_;
    EllipseConfidence confidence_ = EllipseConfidence::OneSigma;
    bool show_trail_ = true;
    bool show_odometry_ = true;
    bool show_truth_ = true;
    bool show_legend_ = true;
    bool show_frame_times_ = false;
    double text_scale_ = 1.0;
    bool dragging_ = false;
    QPointF drag_last_;
};

}  // namespace legofeup::ui
