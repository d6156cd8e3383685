// The arena view's geometry helpers: the world → widget transform (y up, 1:1), zooming about
// a point, the thinned and simplified paths, the scale bar's length.

#include <gtest/gtest.h>

#include <cmath>

#include "legofeup/ui/arena/arena_painter.hpp"
#include "legofeup/ui/arena/thinned_polyline.hpp"
#include "legofeup/ui/arena/world_camera.hpp"

namespace legofeup::ui {
namespace {

TEST(ArenaCamera, WorldYPointsUpAndAspectIsOneToOne) {
    WorldCamera camera;
    camera.fit(QRectF(-1.0, -1.0, 2.0, 2.0), QRectF(0.0, 0.0, 400.0, 200.0), QSizeF(400.0, 200.0));
    EXPECT_DOUBLE_EQ(camera.scale(), 100.0);  // limited by the height
    const QTransform t = camera.transform(QSizeF(400.0, 200.0));
    EXPECT_EQ(t.map(QPointF(0.0, 0.0)), QPointF(200.0, 100.0));
    EXPECT_EQ(t.map(QPointF(1.0, 0.0)), QPointF(300.0, 100.0));
    EXPECT_EQ(t.map(QPointF(0.0, 1.0)), QPointF(200.0, 0.0));  // up is up
    const QRectF visible = camera.visible_world(QSizeF(400.0, 200.0));
    EXPECT_DOUBLE_EQ(visible.width(), 4.0);
    EXPECT_DOUBLE_EQ(visible.height(), 2.0);
}

TEST(ArenaCamera, FitCentresTheWorldInTheArea) {
    WorldCamera camera;
    const QSizeF viewport(600.0, 400.0);
    camera.fit(QRectF(0.0, 0.0, 4.0, 2.0), QRectF(20.0, 0.0, 400.0, 400.0), viewport);
    EXPECT_DOUBLE_EQ(camera.scale(), 100.0);  // limited by the area's width
    const QTransform t = camera.transform(viewport);
    EXPECT_NEAR(t.map(QPointF(2.0, 1.0)).x(), 220.0, 1e-9);
    EXPECT_NEAR(t.map(QPointF(2.0, 1.0)).y(), 200.0, 1e-9);
    EXPECT_NEAR(t.map(QPointF(0.0, 2.0)).x(), 20.0, 1e-9);
    EXPECT_NEAR(t.map(QPointF(0.0, 2.0)).y(), 100.0, 1e-9);
}

TEST(ArenaCamera, ZoomKeepsTheAnchorInPlace) {
    WorldCamera camera;
    const QSizeF viewport(300.0, 200.0);
    camera.fit(QRectF(-1.0, -1.0, 2.0, 2.0), QRectF(10.0, 10.0, 280.0, 180.0), viewport);
    const QPointF anchor(40.0, 170.0);
    const QPointF world = camera.transform(viewport).inverted().map(anchor);
    camera.zoom_about(2.0, anchor, viewport);
    const QPointF again = camera.transform(viewport).map(world);
    EXPECT_NEAR(again.x(), anchor.x(), 1e-9);
    EXPECT_NEAR(again.y(), anchor.y(), 1e-9);
    camera.pan_by(QPointF(10.0, -5.0));
    const QPointF moved = camera.transform(viewport).map(world);
    EXPECT_NEAR(moved.x(), anchor.x() + 10.0, 1e-9);
    EXPECT_NEAR(moved.y(), anchor.y() - 5.0, 1e-9);
}

TEST(ArenaPolyline, ThinningKeepsTheLatestPointAndSkipsCloseOnes) {
    ThinnedPolyline path(0.002);
    for (int i = 0; i <= 1000; ++i) {
        path.append(QPointF(0.0005 * i, 0.0));  // 0.5 mm steps over 0.5 m
    }
    EXPECT_LE(path.size(), 252);
    EXPECT_GE(path.size(), 200);
    EXPECT_DOUBLE_EQ(path.points().back().x(), 0.5);
    for (qsizetype i = 1; i + 1 < path.size(); ++i) {
        EXPECT_GE(path.points()[i].x() - path.points()[i - 1].x(), 0.002 - 1e-12);
    }
}

TEST(ArenaPolyline, SimplifiedPathStaysWithinTolerance) {
    ThinnedPolyline path(0.0);
    for (int i = 0; i < 5000; ++i) {
        const double t = 0.01 * i;
        path.append(QPointF(t, 0.3 * std::sin(t)));
    }
    const double tolerance = 0.001;
    const QPolygonF simplified = path.simplified(tolerance);
    EXPECT_LT(simplified.size(), path.size() / 4);
    EXPECT_EQ(simplified.front(), path.points().front());
    EXPECT_EQ(simplified.back(), path.points().back());
    // Every original point is within the tolerance of the simplified line (x is monotonic).
    qsizetype segment = 0;
    for (const QPointF& p : path.points()) {
        while (segment + 1 < simplified.size() - 1 && simplified[segment + 1].x() < p.x()) {
            ++segment;
        }
        const QPointF a = simplified[segment];
        const QPointF b = simplified[segment + 1];
        const double y = a.y() + (b.y() - a.y()) * (p.x() - a.x()) / (b.x() - a.x());
        EXPECT_LT(std::abs(y - p.y()), tolerance * 1.5) << p.x();
    }
    // Appending more and simplifying again extends the cached result consistently.
    path.append(QPointF(60.0, 0.0));
    const QPolygonF extended = path.simplified(tolerance);
    EXPECT_EQ(extended.back(), QPointF(60.0, 0.0));
    EXPECT_GE(extended.size(), simplified.size());
}

TEST(ArenaScaleBar, PicksOneTwoOrFiveTimesAPowerOfTen) {
    EXPECT_DOUBLE_EQ(scale_bar_length(200.0, 100.0), 0.5);
    EXPECT_DOUBLE_EQ(scale_bar_length(100.0, 100.0), 1.0);
    EXPECT_NEAR(scale_bar_length(1000.0, 110.0), 0.1, 1e-12);
    EXPECT_NEAR(scale_bar_length(5000.0, 100.0), 0.02, 1e-12);
    EXPECT_EQ(scale_bar_length(0.0, 100.0), 0.0);
}

}  // namespace
}  // namespace legofeup::ui
