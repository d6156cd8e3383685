// The arena's seams that draw: the lessons' layers drawn (and in the legend) only for runs
// of their own lesson, at every stage of a frame; the legend placed beside, above or folded
// into a tab; the map pictures made once per map and palette.

#include <QtTest>
#include <memory>
#include <vector>

#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_layers.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/arena/legend_placement.hpp"
#include "legofeup/ui/arena/map_pictures.hpp"
#include "support/arena_pixels.hpp"
#include "support/lockstep_history.hpp"

namespace legofeup::ui {

namespace {

using testing::one_lap;
using testing::one_lap_samples;
using testing::render;

const QString kRecordedRow = QStringLiteral("the recording layer's row");

/// A layer that draws nothing and remembers when it was asked to draw.
class RecordingLayer final : public ArenaLayer {
  public:
    const char* name() const override { return "recording"; }
    void draw(ArenaStage stage, ArenaPainter& /*painter*/,
              const ArenaFrame& /*frame*/) const override {
        stages.push_back(stage);
    }
    void add_legend_rows(LegendSection section, const LegendContext& context,
                         std::vector<LegendRow>& rows) const override {
        if (section == LegendSection::Sensors) {
            rows.push_back({{LegendEntry::Swatch::Line, context.colors.foreground, kRecordedRow}});
        }
    }

    mutable std::vector<ArenaStage> stages;
};

/// The first 200 samples of the lap, localising as `localisation` says.
RunHistory lap_as(Localisation localisation) {
    std::vector<RunSample> samples(one_lap_samples().begin(), one_lap_samples().begin() + 200);
    for (RunSample& sample : samples) {
        sample.snapshot.localisation = localisation;
    }
    RunHistory history;
    history.restart(one_lap().scene());
    history.append(std::move(samples));
    return history;
}

std::unique_ptr<ArenaView> make_view(const RunHistory& history, ArenaLayerRegistry layers,
                                     QSize size = {900, 700}) {
    auto view = std::make_unique<ArenaView>(history, std::move(layers));
    testing::show_fitted(*view, size);
    return view;
}

std::shared_ptr<const OccupancyGrid> small_map() {
    std::vector<CellState> cells(4 * 3, CellState::Free);
    cells[5] = CellState::Occupied;
    return std::make_shared<const OccupancyGrid>(4, 3, 0.5, Pose2{0.0, 0.0, 0.0}, std::move(cells));
}

/// The picture's pixel as stored.
QRgb pixel(const QImage& image, int x, int y) {
    return reinterpret_cast<const QRgb*>(image.constScanLine(y))[x];
}

}  // namespace

class TestArenaLayers : public QObject {
    Q_OBJECT

  private slots:
    void aLayerIsDrawnOnlyForItsOwnLesson() {
        const RecordingLayer beacons_only;
        const ArenaLayerRegistry registry{{Localisation::Walls, {}},
                                          {Localisation::Beacons, {&beacons_only}}};
        const RunHistory walls = lap_as(Localisation::Walls);
        const auto wall_view = make_view(walls, registry);
        (void)render(*wall_view);
        QVERIFY(beacons_only.stages.empty());
        QVERIFY(!wall_view->legendTexts().contains(kRecordedRow));

        const RunHistory beacons = lap_as(Localisation::Beacons);
        const auto beacon_view = make_view(beacons, registry);
        beacons_only.stages.clear();
        (void)render(*beacon_view);
        // One frame: each stage once, back to front.
        const std::vector<ArenaStage> frame{ArenaStage::Marks, ArenaStage::Measurements,
                                            ArenaStage::Labels};
        QCOMPARE(beacons_only.stages, frame);
        // Its legend row among the sensors': after the trail's, before the path's.
        const QStringList texts = beacon_view->legendTexts();
        const qsizetype row = texts.indexOf(kRecordedRow);
        QVERIFY(row > texts.indexOf(QStringLiteral("past ellipses, one per second")));
        QVERIFY(row < texts.indexOf(QStringLiteral("intended path")));
    }

    void beforeTheFirstSampleALayerDrawsOnlyItsMarksAndLabels() {
        const RecordingLayer walls_layer;
        RunHistory empty;
        empty.restart(one_lap().scene());
        const auto view = make_view(empty, {{Localisation::Walls, {&walls_layer}}});
        walls_layer.stages.clear();  // the frames painted while showing it
        (void)render(*view);
        const std::vector<ArenaStage> frame{ArenaStage::Marks, ArenaStage::Labels};
        QCOMPARE(walls_layer.stages, frame);
    }

    void theBuiltInLayersFollowTheLesson() {
        // The same lap's legend: IR rays for the walls, none for the compass lesson.
        const RunHistory walls = lap_as(Localisation::Walls);
        const RunHistory compass = lap_as(Localisation::Compass);
        const auto wall_view = make_view(walls, built_in_arena_layers());
        const auto compass_view = make_view(compass, built_in_arena_layers());
        QVERIFY(wall_view->legendTexts().contains(QStringLiteral("IR rays not used")));
        QVERIFY(!compass_view->legendTexts().contains(QStringLiteral("IR rays not used")));
        // And the rays are not drawn: the pictures differ.
        QVERIFY(render(*wall_view) != render(*compass_view));
    }

    void theLegendGoesBesideAboveOrIntoATab() {
        std::vector<LegendRow> rows;
        for (int i = 0; i < 6; ++i) {
            rows.push_back({{LegendEntry::Swatch::Line, Qt::black,
                             QStringLiteral("a legend row a few words long, number %1").arg(i)}});
        }
        const QFont font;
        const QRectF square(-1.0, -1.0, 2.0, 2.0);
        const auto area_of = [](QSizeF viewport) {
            return QRectF(QPointF(0.0, 0.0), viewport).adjusted(20.0, 20.0, -20.0, -20.0);
        };
        LegendPlacement placement;
        // A wide widget: beside the arena, 10 px from the corner and 10 px from the arena.
        const QSizeF wide(1200.0, 600.0);
        const QRectF beside = placement.place(rows, true, font, wide, area_of(wide), square);
        QVERIFY(!placement.folded());
        const double legend_width = placement.layout().size.width();
        QCOMPARE(beside.right(), area_of(wide).right() - legend_width - 10.0);
        QCOMPARE(beside.top(), area_of(wide).top());
        QCOMPARE(placement.box(true, wide.width(), font).topRight(), QPointF(1190.0, 10.0));
        QCOMPARE(placement.texts().size(), qsizetype(6));
        // A tall one: a strip above it.
        const QSizeF tall(600.0, 1200.0);
        const QRectF above = placement.place(rows, true, font, tall, area_of(tall), square);
        QCOMPARE(above.top(), area_of(tall).top() + placement.layout().size.height() + 10.0);
        QCOMPARE(above.width(), area_of(tall).width());
        // One too small for both: the arena keeps its whole area, the legend a tab.
        const QSizeF small(260.0, 200.0);
        const QRectF folded = placement.place(rows, true, font, small, area_of(small), square);
        QVERIFY(placement.folded());
        QCOMPARE(folded, area_of(small));
        QVERIFY(placement.tab_only());
        const QRectF tab = placement.box(true, small.width(), font);
        const QFontMetricsF metrics(font);
        QCOMPARE(tab.width(), metrics.horizontalAdvance(LegendPlacement::tab_text()) + 12.0);
        QVERIFY(placement.set_open(true));
        QVERIFY(!placement.set_open(true));
        QCOMPARE(placement.box(true, small.width(), font).size(), placement.layout().size);
        // Hidden: no room taken, no box, the texts still known.
        QCOMPARE(placement.place(rows, false, font, wide, area_of(wide), square), area_of(wide));
        QVERIFY(placement.box(true, wide.width(), font).isEmpty());
        QCOMPARE(placement.texts().size(), qsizetype(6));
    }

    void theMapPicturesAreMadeOncePerMapAndPalette() {
        MapPictures pictures;
        ArenaScene scene;
        const ArenaColors light = arena_colors(QPalette(QColor(0xef, 0xef, 0xef)));
        pictures.update(scene, light);
        QVERIFY(pictures.world_map().isNull());
        scene.map = small_map();
        pictures.update(scene, light);
        QCOMPARE(pictures.world_map().size(), QSize(4, 3));
        QVERIFY(pictures.filter_map().isNull());
        const qint64 made = pictures.world_map().cacheKey();
        pictures.update(scene, light);
        QCOMPARE(pictures.world_map().cacheKey(), made);  // the same picture, not remade
        ArenaColors dark = light;
        dark.map_occupied = QColor(0x20, 0x80, 0xff);
        pictures.update(scene, dark);
        QVERIFY(pictures.world_map().cacheKey() != made);
        // Cell 5 is (col 1, row 1): the picture's line 3 − 1 − 1 = 1, premultiplied.
        QCOMPARE(pixel(pictures.world_map(), 1, 1), qPremultiply(dark.map_occupied.rgba()));
        scene.filter_map = small_map();
        pictures.update(scene, dark);
        QCOMPARE(pixel(pictures.filter_map(), 1, 1), qPremultiply(dark.filter_map.rgba()));
    }
};

}  // namespace legofeup::ui

QTEST_MAIN(legofeup::ui::TestArenaLayers)
#include "test_arena_layers.moc"
