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

#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <QTransform>
#include <QWidget>

#include <vector>

#include "legofeup/ui/arena/arena_cache.hpp"
#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "legofeup/ui/arena/history_layer.hpp"
#include "legofeup/ui/arena/laser_layer.hpp"
#include "legofeup/ui/arena/world_camera.hpp"
#include "legofeup/ui/frame_stats.hpp"
#include "legofeup/ui/run_history.hpp"

namespace legofeup::ui {

class ArenaView : public QWidget {
    Q_OBJECT

  public:
    explicit ArenaView(const RunHistory& history, QWidget* parent = nullptr);

    void setEllipseConfidence(EllipseConfidence level);
    EllipseConfidence ellipseConfidence() const { return confidence_; }
    /// Keeps the latest estimate in the centre of the view (a drag turns it off).
    void setFollowRobot(bool on);
    bool followRobot() const { return follow_; }
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
    bool legendFolded() const { return legend_folded_; }
    bool legendOpen() const { return legend_open_; }
    /// Opens or closes a folded legend (the mouse does it over the tab).
    void setLegendOpen(bool open);
    /// The latest laser scan as drawn (world coordinates); empty without one.
    LaserScanPoints laserScanPoints() const;
    /// The laser status label as drawn ("ICP matched 512 pts"); empty without a scan.
    QString laserStatusText() const;
    /// The world's map as drawn (one pixel per cell), and where its pixels go in the world.
    const QImage& mapImage() const { return map_image_; }

    /// Kidnapping: the next press picks where the robot goes and the drag from there its
    /// heading (without a drag it keeps the true heading); emits posePicked().
    void beginPosePick();
    /// Leaves the pose picking without a pose (posePickCancelled()).
    void cancelPosePick();
    bool pickingPose() const { return picking_; }

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
    WorldCamera effectiveCamera() const;
    void fitToArena();
    /// Lays the legend out beside or above the arena, whichever leaves the arena larger, and
    /// returns the widget area the arena is fitted into.
    QRectF layoutLegend();
    /// A setting changed what the legend holds or how large the text is.
    void layoutChanged();
    void zoomBy(double factor, const QPointF& anchor);
    double lineScale() const;
    double fitMargin() const;
    QFont scaledFont() const;
    QFont legendFont() const;
    std::vector<LegendRow> legendRows() const;
    /// Remakes the map pictures when the run's map or the palette changed.
    void updateMapImages(const ArenaColors& colors);
    /// The heading a pick without a drag keeps: the truth's, else the estimate's.
    double currentHeading() const;
    /// The pose being picked, from the press and the cursor.
    Pose2 pickedPose(const QPointF& cursor) const;

    const RunHistory& history_;
    ArenaCache cache_;
    HistoryLayer layer_;
    WorldCamera camera_;
    FrameStats stats_;
    EllipseConfidence confidence_ = EllipseConfidence::OneSigma;
    bool follow_ = false;
    bool show_trail_ = true;
    bool show_odometry_ = true;
    bool show_truth_ = true;
    bool show_legend_ = true;
    bool show_frame_times_ = false;
    double text_scale_ = 1.0;
    LegendLayout legend_layout_;  ///< the legend as laid out at the last fit
    QStringList legend_texts_;    ///< the texts it was laid out for
    bool legend_folded_ = false;  ///< no room for the legend: a tab instead
    bool legend_open_ = false;    ///< the folded legend is open (the mouse is over it)
    QImage map_image_;            ///< the world's map, one pixel per cell
    QImage filter_map_image_;     ///< the laser filter's map when it is not the world's
    const OccupancyGrid* map_source_ = nullptr;
    const OccupancyGrid* filter_map_source_ = nullptr;
    QRgb map_colour_ = 0;  ///< the occupied colour the pictures were made with
    bool picking_ = false;
    bool pick_pressed_ = false;
    QPointF pick_from_;    ///< widget pixels: where the press picked the place
    QPointF pick_cursor_;  ///< widget pixels: where the drag is
    bool fitted_ = true;   ///< the view shows the fitted arena: refit when resized
    bool dragging_ = false;
    QPointF drag_last_;
};

}  // namespace legofeup::ui
