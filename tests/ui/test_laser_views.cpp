// The views of the laser lesson (issue 9, paper 001): the occupancy map in the arena (its
// cells where the grid puts them, the camera fitted to it), the latest scan drawn at the
// estimated scanner pose and the expected one at the predicted pose, the scan matching's
// status, the legend beside the arena; the laser plots shown only with laser data; the
// kidnap tool moving the simulated robot to the pose clicked; the configuration panel
// greying the laser settings outside the laser lesson.

#include <QAction>
#include <QImage>
#include <QLocale>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include <qcustomplot.h>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/arena/map_image.hpp"
#include "legofeup/ui/panels/config_panel.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/session/session.hpp"
#include "legofeup/ui/window/kidnap_action.hpp"
#include "support/arena_pixels.hpp"
#include "support/lockstep_history.hpp"
#include "support/screenshot.hpp"

namespace legofeup::ui {

namespace {

using testing::one_lap;
using testing::one_lap_samples;

constexpr int kPatienceMs = 30000;
constexpr std::size_t kSamples = 200;        ///< the first 10 s of a wall lap
constexpr std::size_t kFirstMismatch = 150;  ///< scans from here on are mismatches
constexpr int kMatchedPoints = 160;
constexpr int kMismatchPoints = 40;
constexpr int kMinMatched = 100;
constexpr int kRecoveryAfter = 20;
const Eigen::Vector3d kInnovation(0.012, -0.02, 0.004);

/// A 4 m × 3 m map at 0.1 m, lower-left corner at (−2, −1.5): an occupied block at cells
/// 5–8 × 5–8, an unknown patch at 30–37 × 20–27, free elsewhere.
std::shared_ptr<const OccupancyGrid> test_map() {
    constexpr int kWidth = 40;
    constexpr int kHeight = 30;
    std::vector<CellState> cells(kWidth * kHeight, CellState::Free);
    for (int row = 0; row < kHeight; ++row) {
        for (int col = 0; col < kWidth; ++col) {
            CellState& cell = cells[static_cast<std::size_t>(row * kWidth + col)];
            if (col >= 5 && col <= 8 && row >= 5 && row <= 8) {
                cell = CellState::Occupied;
            } else if (col >= 30 && col <= 37 && row >= 20 && row <= 27) {
                cell = CellState::Unknown;
            }
        }
    }
    return std::make_shared<const OccupancyGrid>(kWidth, kHeight, 0.1, Pose2{-2.0, -1.5, 0.0},
                                                 std::move(cells));
}

/// 181 beams over 180°, one per degree.
ScanGeometry test_geometry() {
    ScanGeometry geometry;
    geometry.beam_count = 181;
    geometry.angle_increment = kPi / 180.0;
    geometry.angle_min = -kPi / 2.0;
    return geometry;
}

const Pose2 kMount{0.05, 0.0, 0.0};

/// Beam b of the measured scan: 1000 + 2·b mm, every tenth an error code (no echo).
std::uint16_t measured_range(int beam) {
    return beam % 10 == 0 ? std::uint16_t{kRangeNoEcho}
                          : static_cast<std::uint16_t>(1000 + 2 * beam);
}
/// Beam b of the expected scan: 1200 + b mm.
std::uint16_t expected_range(int beam) {
    return static_cast<std::uint16_t>(1200 + beam);
}
/// The predicted scanner pose the expected scans are cast from: the estimate's scanner pose
/// moved 0.1 m along x (in the synthetic history).
Pose2 predicted_scanner(const StateVector& estimate) {
    return {estimate(kX) + kMount.x * std::cos(estimate(kTheta)) + 0.1,
            estimate(kY) + kMount.x * std::sin(estimate(kTheta)), estimate(kTheta)};
}

/// The first kSamples of a wall lap as a laser run on test_map(): a scan every other step,
/// matched (kMatchedPoints) until kFirstMismatch, mismatches (kMismatchPoints) after it,
/// the recovery triggered at the kRecoveryAfter-th.
RunHistory laser_history(std::size_t samples_wanted = kSamples) {
    ArenaScene scene = one_lap().scene();
    scene.map = test_map();
    scene.laser.active = true;
    scene.laser.geometry = test_geometry();
    scene.laser.true_geometry = test_geometry();
    scene.laser.mount = kMount;
    scene.laser.true_mount = kMount;
    scene.laser.min_matched_points = kMinMatched;
    scene.laser.recovery_after_mismatches = kRecoveryAfter;
    scene.laser.kidnap_recovery = true;
    scene.laser.recovery_covariance_factor = 10.0;
    std::vector<RunSample> samples(
        one_lap_samples().begin(),
        one_lap_samples().begin() + static_cast<std::ptrdiff_t>(samples_wanted));
    int mismatches = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        LoopSnapshot& s = samples[i].snapshot;
        s.localisation = Localisation::Laser;
        s.association = AssociationResult{};
        s.update = WallUpdateReport{};
        s.laser = LaserUpdate{};
        s.laser.consecutive_mismatches = mismatches;
        if (i % 2 != 0) {
            continue;  // a scan every other period
        }
        s.frame.has_laser_scan = true;
        s.frame.laser.beam_count = 181;
        s.laser.expected.beam_count = 181;
        for (int b = 0; b < 181; ++b) {
            s.frame.laser.range_mm[static_cast<std::size_t>(b)] = measured_range(b);
            s.laser.expected.range_mm[static_cast<std::size_t>(b)] = expected_range(b);
        }
        s.laser.scan_received = true;
        s.laser.scanner_pose = predicted_scanner(s.estimate);
        s.laser.icp.converged = true;
        if (i < kFirstMismatch) {
            s.laser.matched = true;
            s.laser.icp.matched_points = kMatchedPoints;
            s.laser.status = StepStatus::Applied;
            s.laser.innovation = kInnovation;
            mismatches = 0;
        } else {
            s.laser.icp.matched_points = kMismatchPoints;
            ++mismatches;
            s.laser.recovery_triggered = mismatches == kRecoveryAfter;
            s.laser.recovery_active = mismatches >= kRecoveryAfter;
        }
        s.laser.consecutive_mismatches = mismatches;
    }
    RunHistory history;
    history.restart(scene);
    history.append(std::move(samples));
    return history;
}

/// Where beam `beam` of a scan with `range_mm` lands for a scanner at `scanner` (world),
/// computed here from the beam's angle, independently of scan_to_points().
QPointF beam_end(const Pose2& scanner, int beam, std::uint16_t range_mm) {
    const double angle = scanner.theta - kPi / 2.0 + beam * kPi / 180.0;
    const double range = range_mm / 1000.0;
    return {scanner.x + range * std::cos(angle), scanner.y + range * std::sin(angle)};
}

using testing::nearest_colour_distance;
using testing::render;

QColor pixel_at(const QImage& image, const QPointF& point) {
    const double ratio = image.devicePixelRatio();
    return image.pixelColor(static_cast<int>(std::floor(point.x() * ratio)),
                            static_cast<int>(std::floor(point.y() * ratio)));
}

std::unique_ptr<ArenaView> make_view(const RunHistory& history) {
    auto view = std::make_unique<ArenaView>(history);
    view->resize(900, 700);
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get())) {
        qWarning("window not exposed");
    }
    view->fitArena();
    return view;
}

/// The world centre of grid cell (col, row) of test_map(), from the map's own numbers.
QPointF cell_centre(int col, int row) {
    return {-2.0 + 0.1 * (col + 0.5), -1.5 + 0.1 * (row + 0.5)};
}

int laser_tab(const PlotsPanel& panel) {
    const auto* tabs = panel.findChild<QTabWidget*>();
    for (int t = 0; t < tabs->count(); ++t) {
        if (tabs->tabText(t).startsWith(QStringLiteral("Laser"))) {
            return t;
        }
    }
    return -1;
}

/// The laser lesson's configuration as the configuration file would set it: the office,
/// laser localisation, the simulated scanner on.
lessons::RunConfig laser_config() {
    lessons::RunConfig config = lessons::find_experiment("f")->config;
    config.world_file = "office";
    config.lesson.localisation = Localisation::Laser;
    config.physical.laser_scanner.enabled = true;
    return config;
}

}  // namespace

class TestLaserViews : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;

  private slots:
    void initTestCase() {
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Laser Views Test"));
    }

    // ---- the map ------------------------------------------------------------------------

    void mapCellsAreDrawnWhereTheGridPutsThem() {
        const RunHistory history = laser_history();
        const auto view = make_view(history);
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        // An occupied cell is dark, and in the map's colour.
        const QColor occupied = pixel_at(image, t.map(cell_centre(6, 7)));
        QVERIFY2(occupied.lightness() < 90, qPrintable(occupied.name()));
        QVERIFY(nearest_colour_distance(image, t.map(cell_centre(6, 7)), colors.map_occupied) <= 2);
        // A free cell shows the floor (outside the walls, where nothing else is drawn).
        const QColor free = pixel_at(image, t.map(cell_centre(2, 27)));
        QVERIFY2(free.lightness() > 200, qPrintable(free.name()));
        QVERIFY(nearest_colour_distance(image, t.map(cell_centre(2, 27)), colors.background) <= 2);
        // An unknown cell is grey.
        QVERIFY(nearest_colour_distance(image, t.map(cell_centre(33, 24)), colors.map_unknown)
                <= 2);
        // The occupied block's edge: the cell beside it is free.
        QVERIFY(nearest_colour_distance(image, t.map(cell_centre(9, 7)), colors.map_occupied) > 60);
    }

    void theCameraFitsTheMap() {
        const RunHistory history = laser_history();
        const auto view = make_view(history);
        const QRectF visible = view->visibleWorldRect();
        // The map (x −2 … 2, y −1.5 … 1.5) is larger than the walls: it is all in view.
        QVERIFY(visible.contains(QRectF(-2.0, -1.5, 4.0, 3.0)));
        QCOMPARE(map_world_bounds(*history.scene().map), QRectF(-2.0, -1.5, 4.0, 3.0));
        // And the legend is beside it, not over it.
        const QRectF legend = view->legendRect();
        QVERIFY(!legend.isEmpty());
        const QRectF map_on_screen = view->worldToWidget().mapRect(QRectF(-2.0, -1.5, 4.0, 3.0));
        QVERIFY2(!legend.intersects(map_on_screen),
                 qPrintable(QStringLiteral("legend %1,%2 %3×%4, map left %5 right %6")
                                .arg(legend.x())
                                .arg(legend.y())
                                .arg(legend.width())
                                .arg(legend.height())
                                .arg(map_on_screen.left())
                                .arg(map_on_screen.right())));
    }

    void aSmallArenaFoldsTheLegendIntoATab() {
        const RunHistory history = laser_history();
        auto view = std::make_unique<ArenaView>(history);
        view->resize(560, 320);  // the window's default arena on a 1600 × 1000 screen
        view->show();
        QVERIFY(QTest::qWaitForWindowExposed(view.get()));
        view->fitArena();
        QVERIFY(view->legendFolded());
        const QRectF tab = view->legendRect();
        QVERIFY2(tab.width() < 120.0 && tab.height() < 40.0,
                 qPrintable(QString::number(tab.width())));
        const QRectF map = QRectF(-2.0, -1.5, 4.0, 3.0);
        const QRectF folded_map = view->worldToWidget().mapRect(map);
        QVERIFY(!tab.intersects(folded_map));
        // The arena as large as without a legend at all.
        view->setShowLegend(false);
        view->fitArena();
        const QRectF bare_map = view->worldToWidget().mapRect(map);
        QVERIFY(std::abs(bare_map.width() - folded_map.width()) < 1e-6);
        view->setShowLegend(true);
        view->fitArena();
        // The mouse over the tab opens the whole legend; away from it, it folds again.
        QTest::mouseMove(view.get(), tab.center().toPoint());
        QTRY_VERIFY(view->legendOpen());
        QVERIFY(view->legendRect().height() > 150.0);
        QTest::mouseMove(view.get(), QPoint(40, 300));
        QTRY_VERIFY(!view->legendOpen());
        // A larger arena has room: the legend beside or above it, not folded.
        view->resize(1100, 700);
        view->fitArena();
        QVERIFY(!view->legendFolded());
    }

    void aRotatedMapPutsEachPixelOnItsCell() {
        // yaw 30°: the picture's pixel centres go to the grid's own cell centres.
        std::vector<CellState> cells(6 * 4, CellState::Free);
        cells[static_cast<std::size_t>(1 * 6 + 4)] = CellState::Occupied;  // col 4, row 1
        const OccupancyGrid grid(6, 4, 0.25, Pose2{1.0, -0.5, kPi / 6.0}, std::move(cells));
        const QImage image = map_image(grid, {Qt::black, Qt::gray});
        QCOMPARE(image.size(), QSize(6, 4));
        // Row 1 from the bottom is the picture's line 4 − 1 − 1 = 2.
        QCOMPARE(image.pixelColor(4, 2), QColor(Qt::black));
        QCOMPARE(image.pixelColor(4, 1).alpha(), 0);
        const QTransform to_world = image_to_world(grid);
        for (const auto& [col, row] : {std::pair{0, 0}, std::pair{4, 1}, std::pair{5, 3}}) {
            const QPointF mapped = to_world.map(QPointF(col + 0.5, 4 - row - 0.5));
            // The cell centre by hand: origin + R(30°)·(r·(col + ½), r·(row + ½)).
            const double gx = 0.25 * (col + 0.5);
            const double gy = 0.25 * (row + 0.5);
            const double c = std::cos(kPi / 6.0);
            const double s = std::sin(kPi / 6.0);
            QVERIFY(std::abs(mapped.x() - (1.0 + c * gx - s * gy)) < 1e-12);
            QVERIFY(std::abs(mapped.y() - (-0.5 + s * gx + c * gy)) < 1e-12);
            const Vector2 centre = grid.centre_of(GridCell{col, row});
            QVERIFY(std::abs(mapped.x() - centre.x()) < 1e-9);
            QVERIFY(std::abs(mapped.y() - centre.y()) < 1e-9);
        }
    }

    // ---- the scans ----------------------------------------------------------------------

    void theScanIsDrawnAtTheEstimatedScannerPose() {
        const RunHistory history = laser_history(kFirstMismatch);  // matched scans only
        const auto view = make_view(history);
        const RunSample& scan_sample = *history.sample(kFirstMismatch - 2);  // the last scan
        const StateVector& x = scan_sample.snapshot.estimate;
        // X̂ ⊕ mount by hand.
        const Pose2 scanner{x(kX) + kMount.x * std::cos(x(kTheta)),
                            x(kY) + kMount.x * std::sin(x(kTheta)), x(kTheta)};
        const LaserScanPoints points = view->laserScanPoints();
        QVERIFY(points.matched);
        // Every beam but the error codes (every tenth, 19 of 181).
        QCOMPARE(points.measured.size(), qsizetype(181 - 19));
        QCOMPARE(points.expected.size(), qsizetype(181));
        QCOMPARE(points.measured_at_truth.size(), qsizetype(181 - 19));
        // Beam 45 is the 41st point after four skipped beams (0, 10, 20, 30, 40).
        const QPointF beam45 = beam_end(scanner, 45, measured_range(45));
        QVERIFY(std::hypot(points.measured[45 - 5].x() - beam45.x(),
                           points.measured[45 - 5].y() - beam45.y())
                < 1e-9);
        const QPointF expected90 = beam_end(predicted_scanner(x), 90, expected_range(90));
        QVERIFY(std::hypot(points.expected[90].x() - expected90.x(),
                           points.expected[90].y() - expected90.y())
                < 1e-9);
        // Drawn there, in the "used" colour; the expected scan in its own.
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        // (Beam 45 looks down and right, out of the view here: beam 135, 45° to the left.)
        const QPointF beam135 = beam_end(scanner, 135, measured_range(135));
        QVERIFY(std::hypot(points.measured[135 - 14].x() - beam135.x(),
                           points.measured[135 - 14].y() - beam135.y())
                < 1e-9);
        QVERIFY(view->rect().contains(t.map(beam135).toPoint()));
        QVERIFY(nearest_colour_distance(image, t.map(beam135), colors.associated) <= 10);
        QVERIFY(view->rect().contains(t.map(expected90).toPoint()));
        QVERIFY(nearest_colour_distance(image, t.map(expected90), colors.expected_scan) <= 10);
        QCOMPARE(view->laserStatusText(), QStringLiteral("ICP matched %1 pts").arg(kMatchedPoints));
    }

    void aMismatchIsDrawnInTheRejectedColour() {
        const RunHistory history = laser_history();
        const auto view = make_view(history);
        const LaserScanPoints points = view->laserScanPoints();
        QVERIFY(!points.matched);
        const RunSample& scan_sample = *history.sample(kSamples - 2);
        const StateVector& x = scan_sample.snapshot.estimate;
        const Pose2 scanner{x(kX) + kMount.x * std::cos(x(kTheta)),
                            x(kY) + kMount.x * std::sin(x(kTheta)), x(kTheta)};
        const QPointF beam123 = beam_end(scanner, 123, measured_range(123));
        QVERIFY(view->rect().contains(view->worldToWidget().map(beam123).toPoint()));
        const ArenaColors colors = arena_colors(view->palette());
        QVERIFY(nearest_colour_distance(render(*view), view->worldToWidget().map(beam123),
                                        colors.rejected)
                <= 10);
        // The 25th mismatch in a row, past the recovery threshold of 20.
        QCOMPARE(view->laserStatusText(), QStringLiteral("recovery: P×10 · mismatch ×25"));
        const RunHistory before_recovery = laser_history(kFirstMismatch + 10);
        const auto early = make_view(before_recovery);
        QCOMPARE(early->laserStatusText(),
                 QStringLiteral("mismatch ×5 · %1 pts").arg(kMismatchPoints));
    }

    void aParticleFiltersScanIsWeighedNotMatched() {
        // The particle filter runs no ICP: its scans say how much weight survived instead of
        // "ICP matched 0 pts", and a refused update says so rather than "mismatch".
        const auto as_particle_filter = [](bool applied) {
            const RunHistory matched = laser_history(kFirstMismatch);
            std::vector<RunSample> samples = testing::whole_samples(matched);
            for (RunSample& sample : samples) {
                LoopSnapshot& s = sample.snapshot;
                s.filter_kind = FilterKind::Pf;
                s.particles.count = 10000;
                s.particles.effective = 6320.4;
                s.laser.icp = IcpResult{};
                s.laser.measured_points = 91;
                s.laser.matched = applied && s.laser.scan_received;
                s.laser.status =
                    s.laser.matched ? StepStatus::Applied : StepStatus::RejectedNonFinite;
            }
            RunHistory history;
            history.restart(matched.scene());
            history.append(std::move(samples));
            return history;
        };
        const RunHistory weighed = as_particle_filter(true);
        const QLocale locale;
        QCOMPARE(make_view(weighed)->laserStatusText(),
                 QStringLiteral("scan weighed · N_eff %1 of %2")
                     .arg(locale.toString(6320), locale.toString(10000)));
        QCOMPARE(make_view(as_particle_filter(false))->laserStatusText(),
                 QStringLiteral("scan not weighed (refused)"));
    }

    void aWallRunDrawsNoScan() {
        const auto view = make_view(one_lap());
        QVERIFY(view->laserScanPoints().measured.isEmpty());
        QVERIFY(view->laserStatusText().isEmpty());
        render(*view);
        QCOMPARE(view->mapImage().isNull(), one_lap().scene().map == nullptr);
        for (const QString& text : view->legendTexts()) {
            QVERIFY2(!text.contains(QStringLiteral("scan")), qPrintable(text));
        }
    }

    void theTruthsPathIsNotJoinedAcrossAKidnapping() {
        // From sample 100 on, the robot is 0.8 m further up (the simulator's teleport count
        // says it was moved).
        RunHistory history = laser_history();
        std::vector<RunSample> samples = testing::whole_samples(history);
        for (std::size_t i = 100; i < samples.size(); ++i) {
            samples[i].truth->pose.y += 0.8;
            samples[i].truth->teleports = 1;
        }
        const ArenaScene scene = history.scene();
        history.restart(scene);
        history.append(std::move(samples));
        const auto view = make_view(history);
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        const Pose2 from = history.sample(99)->truth->pose;
        const Pose2 to = history.sample(100)->truth->pose;
        const Pose2 later = history.sample(150)->truth->pose;
        // The path after the jump is drawn (a 1 px antialiased line: at least half a pixel of
        // it), the jump itself is not (the floor or the grid there, ≥ 150 from the truth's
        // colour in some channel).
        QVERIFY(nearest_colour_distance(image, t.map(QPointF(later.x, later.y)), colors.truth)
                <= 110);
        const QPointF middle(0.5 * (from.x + to.x), 0.5 * (from.y + to.y));
        QVERIFY(nearest_colour_distance(image, t.map(middle), colors.truth) >= 150);
    }

    // ---- the plots ----------------------------------------------------------------------

    void theLaserTabAppearsOnlyWithLaserData() {
        PlotsPanel walls(one_lap());
        walls.resize(900, 600);
        walls.show();
        const int tab = laser_tab(walls);
        QVERIFY(tab >= 0);
        QVERIFY(!walls.findChild<QTabWidget*>()->isTabVisible(tab));
        QVERIFY(!walls.plotShown(PlotKind::LaserMatches));

        const RunHistory history = laser_history();
        PlotsPanel panel(history);
        panel.resize(900, 600);
        panel.show();
        QVERIFY(panel.findChild<QTabWidget*>()->isTabVisible(laser_tab(panel)));
        for (PlotKind kind :
             {PlotKind::LaserMatches, PlotKind::LaserMismatches, PlotKind::LaserInnovation}) {
            QVERIFY(panel.plotShown(kind));
        }
        // One point per scan: 75 matched scans (steps 0, 2, … 148), 25 mismatches.
        QCOMPARE(panel.graph(Series::LaserMatchedUsed)->dataCount(), 75);
        QCOMPARE(panel.graph(Series::LaserMatchedMismatch)->dataCount(), 25);
        QCOMPARE(panel.graph(Series::LaserMatchedUsed)->data()->at(0)->value,
                 double(kMatchedPoints));
        QCOMPARE(panel.graph(Series::LaserMatchedMismatch)->data()->at(0)->value,
                 double(kMismatchPoints));
        QCOMPARE(panel.graph(Series::LaserConsecutiveMismatches)->dataCount(), 100);
        QCOMPARE((panel.graph(Series::LaserConsecutiveMismatches)->data()->constEnd() - 1)->value,
                 25.0);
        // The recovery once, at the 20th mismatch.
        QCOMPARE(panel.graph(Series::LaserRecoveries)->dataCount(), 1);
        QCOMPARE(panel.graph(Series::LaserRecoveries)->data()->at(0)->value,
                 double(kRecoveryAfter));
        QCOMPARE(panel.graph(Series::LaserRecoveries)->data()->at(0)->key,
                 history.record(kFirstMismatch + 2 * (kRecoveryAfter - 1)).time);
        // The innovation of the applied updates: x, y in cm, θ in degrees.
        QCOMPARE(panel.graph(Series::LaserInnovationX)->dataCount(), 75);
        // The record keeps them as floats (7 digits).
        QVERIFY(std::abs(panel.graph(Series::LaserInnovationX)->data()->at(0)->value - 1.2) < 1e-5);
        QVERIFY(std::abs(panel.graph(Series::LaserInnovationY)->data()->at(0)->value - -2.0)
                < 1e-5);
        QVERIFY(std::abs(panel.graph(Series::LaserInnovationTheta)->data()->at(0)->value
                         - 0.004 * 180.0 / kPi)
                < 1e-5);
        // The thresholds as lines.
        QCOMPARE(panel.referenceValue(PlotKind::LaserMatches, 0), std::optional<double>(100.0));
        QCOMPARE(panel.referenceValue(PlotKind::LaserMismatches, 0), std::optional<double>(20.0));
        QVERIFY(!panel.referenceValue(PlotKind::LaserInnovation, 0).has_value());
    }

    // ---- kidnapping ---------------------------------------------------------------------

    void kidnappingMovesTheSimulatedRobotToThePoseClicked() {
        Session session(lessons::find_experiment("f")->config);
        LinkChoice fast;
        fast.speed = 10.0;
        session.setLinkChoice(fast);
        ArenaView arena(session.history());
        connect(&session, &Session::historyRestarted, &arena, &ArenaView::historyRestarted);
        connect(&session, &Session::samplesAppended, &arena, &ArenaView::samplesAppended);
        arena.resize(800, 700);
        arena.show();
        QVERIFY(QTest::qWaitForWindowExposed(&arena));
        KidnapAction kidnap(session, arena);
        QSignalSpy messages(&kidnap, &KidnapAction::done);
        QVERIFY(!kidnap.action()->isEnabled());  // no run yet
        QVERIFY(kidnap.action()->toolTip().contains(QStringLiteral("Start a run")));
        QCOMPARE(kidnap.action()->shortcut(), QKeySequence(Qt::Key_F9));

        session.start();
        QTRY_VERIFY_WITH_TIMEOUT(session.history().size() >= 40, kPatienceMs);
        QVERIFY(kidnap.action()->isEnabled());
        arena.fitArena();
        kidnap.action()->trigger();
        QVERIFY(arena.pickingPose());

        // Press at (0, 0.1), drag towards (−0.5, 0.1): heading π (west).
        const QTransform t = arena.worldToWidget();
        const QPoint press = t.map(QPointF(0.0, 0.1)).toPoint();
        const QPoint release = t.map(QPointF(-0.5, 0.1)).toPoint();
        bool invertible = false;
        const QPointF clicked = t.inverted(&invertible).map(QPointF(press));
        const std::size_t before = session.history().size();
        QTest::mousePress(&arena, Qt::LeftButton, Qt::NoModifier, press);
        QTest::mouseMove(&arena, (press + release) / 2);
        QVERIFY(arena.pickingPose());
        testing::save_screenshot(arena, "kidnap-pick");  // the robot outline being aimed
        QTest::mouseRelease(&arena, Qt::LeftButton, Qt::NoModifier, release);
        QVERIFY(!arena.pickingPose());
        QVERIFY(!kidnap.action()->isChecked());
        QCOMPARE(messages.size(), 1);
        QVERIFY(messages.front().front().toString().startsWith(QStringLiteral("Kidnapped")));

        // The simulator's truth jumps there (its teleport count says so), the estimate not.
        const auto kidnapped = [&session]() -> std::optional<std::size_t> {
            const RunHistory& history = session.history();
            for (std::size_t i = 0; i < history.size(); ++i) {
                if (history.record(i).has_truth && history.record(i).teleports > 0) {
                    return i;
                }
            }
            return std::nullopt;
        };
        QTRY_VERIFY_WITH_TIMEOUT(kidnapped().has_value(), kPatienceMs);
        const std::size_t index = *kidnapped();
        const StepRecord& after = session.history().record(index);
        QVERIFY(index >= before);
        // At rest there, then the path controller drives on: within a period's motion.
        QVERIFY2(std::hypot(after.truth.x - clicked.x(), after.truth.y - clicked.y()) < 0.03,
                 qPrintable(QStringLiteral("truth (%1, %2), clicked (%3, %4)")
                                .arg(after.truth.x)
                                .arg(after.truth.y)
                                .arg(clicked.x())
                                .arg(clicked.y())));
        QVERIFY(std::abs(wrap_angle(after.truth.theta - kPi)) < 0.1);
        const Pose2& estimate_before = session.history().record(index - 1).estimate;
        QVERIFY(
            std::hypot(after.estimate.x - estimate_before.x, after.estimate.y - estimate_before.y)
            < 0.05);
        session.stop();
    }

    void escapeCancelsAndAnNxtCannotBeKidnapped() {
        Session session(lessons::find_experiment("f")->config);
        ArenaView arena(session.history());
        arena.resize(600, 500);
        arena.show();
        QVERIFY(QTest::qWaitForWindowExposed(&arena));
        KidnapAction kidnap(session, arena);
        QSignalSpy cancelled(&arena, &ArenaView::posePickCancelled);
        QSignalSpy picked(&arena, &ArenaView::posePicked);
        arena.beginPosePick();
        QTest::keyClick(&arena, Qt::Key_Escape);
        QCOMPARE(cancelled.size(), 1);
        QCOMPARE(picked.size(), 0);
        QVERIFY(!arena.pickingPose());

        // A click without a drag keeps the heading (no run: 0), at the place clicked.
        arena.beginPosePick();
        const QPoint at = arena.worldToWidget().map(QPointF(0.4, -0.3)).toPoint();
        QTest::mouseClick(&arena, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(picked.size(), 1);
        const auto pose = picked.front().front().value<Pose2>();
        bool invertible = false;
        const QPointF world = arena.worldToWidget().inverted(&invertible).map(QPointF(at));
        QCOMPARE(pose.x, world.x());
        QCOMPARE(pose.y, world.y());
        QCOMPARE(pose.theta, 0.0);

        LinkChoice nxt;
        nxt.kind = LinkKind::Nxt;
        nxt.nxt_address = QStringLiteral("bt:00:16:53:01:02:03");
        session.setLinkChoice(nxt);
        QVERIFY(!kidnap.action()->isEnabled());
        QVERIFY(kidnap.action()->toolTip().contains(QStringLiteral("real NXT")));
        QVERIFY(!session.teleport(Pose2{0.0, 0.0, 0.0}).isEmpty());
        nxt.emulated = true;
        session.setLinkChoice(nxt);
        QVERIFY(kidnap.action()->toolTip().contains(QStringLiteral("emulated brick")));
    }

    // ---- configuration ------------------------------------------------------------------

    void laserSettingsAreGreyedOutsideTheLaserLesson() {
        Session walls(lessons::find_experiment("f")->config);
        ConfigPanel wall_panel(walls);
        for (const char* key : {"laser.min_matched_points", "laser.r_x", "laser.icp_metric",
                                "laser.recovery_after_mismatches", "laser.q_x_static"}) {
            QVERIFY2(!wall_panel.isRelevant(key), key);
        }
        QVERIFY(wall_panel.isRelevant("filter.q11"));
        QVERIFY(wall_panel.isRelevant("filter.r11"));
        // The simulated scanner and the kidnapping are the simulator's: always there.
        QVERIFY(wall_panel.isRelevant("laser_scanner.enabled"));
        QVERIFY(wall_panel.isRelevant("kidnap.time"));

        Session laser(laser_config());
        ConfigPanel laser_panel(laser);
        for (const char* key : {"laser.min_matched_points", "laser.r_x", "laser.icp_metric",
                                "laser.recovery_after_mismatches", "laser.q_x_static",
                                "filter.kind", "localisation.method"}) {
            QVERIFY2(laser_panel.isRelevant(key), key);
        }
        // The IR's and the odometry's Q11, Q22 are the other lessons'.
        for (const char* key : {"filter.r11", "filter.q11", "filter.q22", "ir_curve.a",
                                "association.max_incidence_deg", "beacons.r_bearing"}) {
            QVERIFY2(!laser_panel.isRelevant(key), key);
        }
        // "laser" among the localisation's choices.
        const lessons::Setting* method = lessons::find_setting_by_key("localisation.method");
        QVERIFY(std::find(method->choices.begin(), method->choices.end(), "laser")
                != method->choices.end());
        // The filter's laser tuning applies while running; the simulated scanner at the start.
        QVERIFY(lessons::find_setting_by_key("laser.min_matched_points")->applies_live());
        QVERIFY(!lessons::find_setting_by_key("laser_scanner.enabled")->applies_live());
    }
};

}  // namespace legofeup::ui

QTEST_MAIN(legofeup::ui::TestLaserViews)
#include "test_laser_views.moc"
