// The arena view, rendered offscreen with a lap of experiment f: what lands on which pixel,
// following, zooming, the ellipse label, incremental updates without synchronous repaints,
// a dark palette, and the driving keys passing through to the main window.

#include <QImage>
#include <QKeyEvent>
#include <QSignalSpy>
#include <QWheelEvent>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/arena/covariance_ellipse.hpp"
#include "support/arena_pixels.hpp"
#include "support/lockstep_history.hpp"

namespace legofeup::ui {

namespace {

using testing::one_lap;
using testing::one_lap_samples;

using testing::render;

/// The pixel under a widget point (device-independent) of an image grabbed from the view.
QColor pixel_at(const QImage& image, const QPointF& widget_point) {
    const double ratio = image.devicePixelRatio();
    const QPoint p(static_cast<int>(std::floor(widget_point.x() * ratio)),
                   static_cast<int>(std::floor(widget_point.y() * ratio)));
    if (!image.rect().contains(p)) {
        return {};
    }
    return image.pixelColor(p);
}

int colour_distance(const QColor& a, const QColor& b) {
    return std::max({std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                     std::abs(a.blue() - b.blue())});
}

/// `over` painted with `alpha` on top of `under`.
QColor blend(const QColor& over, int alpha, const QColor& under) {
    const auto mix = [alpha](int a, int b) { return (a * alpha + b * (255 - alpha)) / 255; };
    return {mix(over.red(), under.red()), mix(over.green(), under.green()),
            mix(over.blue(), under.blue())};
}

QPointF estimate_point(const RunHistory& history) {
    const StateVector& x = history.latest().snapshot.estimate;
    return {x(kX), x(kY)};
}

QPalette dark_palette() {
    QPalette palette;
    palette.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    palette.setColor(QPalette::WindowText, QColor(0xe6, 0xe6, 0xe6));
    palette.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    palette.setColor(QPalette::Text, QColor(0xe6, 0xe6, 0xe6));
    return palette;
}

/// A shown view of the given history at a fixed size, fitted to the arena.
std::unique_ptr<ArenaView> make_view(const RunHistory& history, QSize size = {900, 700}) {
    auto view = std::make_unique<ArenaView>(history);
    view->resize(size);
    view->show();
    if (!QTest::qWaitForWindowExposed(view.get())) {
        qWarning("window not exposed");
    }
    view->fitArena();
    return view;
}

}  // namespace

class TestArenaView : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { QVERIFY(one_lap_samples().size() > 1000); }

    void wallMidpointsHaveTheWallColour() {
        const auto view = make_view(one_lap());
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        QVERIFY(!one_lap().scene().walls.empty());
        for (const Wall& wall : one_lap().scene().walls) {
            const Vector2 middle = 0.5 * (wall.start + wall.end);
            const QColor pixel = pixel_at(image, t.map(QPointF(middle.x(), middle.y())));
            QVERIFY2(colour_distance(pixel, colors.foreground) <= 40,
                     qPrintable(QString::fromStdString(wall.name) + " " + pixel.name()));
        }
        // And an empty spot inside the arena shows the background.
        const QColor empty = pixel_at(image, t.map(QPointF(0.3, 0.2)));
        QVERIFY2(colour_distance(empty, colors.background) <= 10, qPrintable(empty.name()));
    }

    void estimateIsDrawnWithItsColour() {
        const auto view = make_view(one_lap());
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QPointF at = view->worldToWidget().map(estimate_point(one_lap()));
        QCOMPARE(colour_distance(pixel_at(image, at), colors.estimate), 0);
    }

    void ellipseIsFilledAroundTheEstimate() {
        const auto view = make_view(one_lap());
        view->setShowTruth(false);
        view->setShowOdometry(false);
        view->setShowTrail(false);
        view->setEllipseConfidence(EllipseConfidence::Percent99);
        const CovarianceEllipse e = covariance_ellipse(
            Vector2(estimate_point(one_lap()).x(), estimate_point(one_lap()).y()),
            one_lap().latest().snapshot.covariance.block<2, 2>(kX, kX),
            EllipseConfidence::Percent99);
        QVERIFY(e.valid);
        // Zoom until the minor semi-axis is 60 px, keeping the estimate centred.
        view->setFollowRobot(true);
        while (e.semi_minor * view->worldToWidget().m11() < 60.0) {
            view->zoomIn();
        }
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QColor fill = blend(colors.ellipse, 45, colors.background);
        const double heading = one_lap().latest().snapshot.estimate(kTheta);
        int filled = 0;
        int probes = 0;
        for (int i = 0; i < 12; ++i) {
            const double angle = i * kPi / 6.0;
            // Skip the arrow (along the heading) and the path behind it.
            if (std::abs(std::sin(angle - heading)) < 0.5) {
                continue;
            }
            const Vector2 u(std::cos(angle), std::sin(angle));
            QVERIFY(e.contains(e.centre + 0.5 * e.semi_minor * u));
            const Vector2 probe = e.centre + 0.5 * e.semi_minor * u;
            ++probes;
            if (colour_distance(
                    pixel_at(image, view->worldToWidget().map(QPointF(probe.x(), probe.y()))), fill)
                <= 12) {
                ++filled;
            }
        }
        QVERIFY2(filled >= probes - 1, qPrintable(QString("%1 of %2").arg(filled).arg(probes)));
        // Just outside the ellipse, on the axis most across the heading, it is not filled.
        const Vector2 major(std::cos(e.angle), std::sin(e.angle));
        const Vector2 minor(-major.y(), major.x());
        const Vector2 across(-std::sin(heading), std::cos(heading));
        const bool use_major = std::abs(major.dot(across)) > std::abs(minor.dot(across));
        const Vector2 axis = use_major ? major : minor;
        const double reach = 1.2 * (use_major ? e.semi_major : e.semi_minor);
        // On the robot's left: the IR rays are on its right.
        const Vector2 outside_point =
            e.centre + reach * (axis.dot(across) < 0.0 ? Vector2(-axis) : axis);
        const QColor outside = pixel_at(
            image, view->worldToWidget().map(QPointF(outside_point.x(), outside_point.y())));
        QVERIFY2(colour_distance(outside, fill) > 12, qPrintable(outside.name()));
    }

    void followRobotCentresTheLatestEstimate() {
        const auto view = make_view(one_lap());
        QSignalSpy spy(view.get(), &ArenaView::followRobotChanged);
        view->setFollowRobot(true);
        QCOMPARE(spy.count(), 1);
        const QPointF at = view->worldToWidget().map(estimate_point(one_lap()));
        QVERIFY(std::abs(at.x() - view->width() / 2.0) < 1e-6);
        QVERIFY(std::abs(at.y() - view->height() / 2.0) < 1e-6);
        // Without following, the fitted arena is centred instead (the robot is near a corner).
        view->fitArena();
        QVERIFY(!view->followRobot());
        const QPointF fitted = view->worldToWidget().map(estimate_point(one_lap()));
        QVERIFY(std::abs(fitted.x() - view->width() / 2.0) > 100.0);
    }

    void zoomChangesTheVisibleSpan() {
        const auto view = make_view(one_lap());
        const QRectF before = view->visibleWorldRect();
        QVERIFY(before.contains(QRectF(-1.21, -1.21, 2.42, 2.42)));
        view->zoomIn();
        const QRectF zoomed = view->visibleWorldRect();
        QVERIFY(std::abs(zoomed.width() - before.width() / 1.25) < 1e-9);
        QVERIFY(std::abs(zoomed.height() - before.height() / 1.25) < 1e-9);
        QVERIFY(std::abs(zoomed.center().x() - before.center().x()) < 1e-9);
        view->zoomOut();
        QVERIFY(std::abs(view->visibleWorldRect().width() - before.width()) < 1e-9);
    }

    void wheelZoomsAboutTheCursorAndDragPans() {
        const auto view = make_view(one_lap());
        const QPointF cursor(200.0, 150.0);
        const QPointF world = view->worldToWidget().inverted().map(cursor);
        const double width = view->visibleWorldRect().width();
        QWheelEvent wheel(cursor, view->mapToGlobal(cursor), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(view.get(), &wheel);
        QVERIFY(view->visibleWorldRect().width() < width * 0.9);
        const QPointF again = view->worldToWidget().map(world);
        QVERIFY(std::abs(again.x() - cursor.x()) < 1e-6);
        QVERIFY(std::abs(again.y() - cursor.y()) < 1e-6);

        view->setFollowRobot(true);
        QSignalSpy spy(view.get(), &ArenaView::followRobotChanged);
        const QPointF start_world = view->worldToWidget().inverted().map(QPointF(300, 300));
        QTest::mousePress(view.get(), Qt::LeftButton, Qt::NoModifier, QPoint(300, 300));
        QTest::mouseMove(view.get(), QPoint(340, 320));
        QTest::mouseRelease(view.get(), Qt::LeftButton, Qt::NoModifier, QPoint(340, 320));
        QVERIFY(!view->followRobot());
        QCOMPARE(spy.count(), 1);
        const QPointF dragged = view->worldToWidget().map(start_world);
        QVERIFY2(std::abs(dragged.x() - 340.0) < 1e-6 && std::abs(dragged.y() - 320.0) < 1e-6,
                 qPrintable(QString("%1, %2").arg(dragged.x()).arg(dragged.y())));

        QTest::mouseDClick(view.get(), Qt::LeftButton, Qt::NoModifier, QPoint(100, 100));
        QVERIFY(view->visibleWorldRect().contains(QRectF(-1.21, -1.21, 2.42, 2.42)));
    }

    void ellipseLabelFollowsTheConfidence() {
        const auto view = make_view(one_lap());
        QCOMPARE(view->ellipseLabel(), QString::fromUtf8("1σ ellipse"));
        QVERIFY(view->ellipseNote().contains(QStringLiteral("39.3 %")));
        const QImage one_sigma = render(*view);
        view->setEllipseConfidence(EllipseConfidence::Percent95);
        QCOMPARE(view->ellipseLabel(), QStringLiteral("95 % ellipse"));
        view->setEllipseConfidence(EllipseConfidence::Percent99);
        QCOMPARE(view->ellipseLabel(), QStringLiteral("99 % ellipse"));
        QVERIFY(render(*view) != one_sigma);
    }

    void samplesAppendedUpdatesCachesAndRepaintsLater() {
        const std::vector<RunSample>& all = one_lap_samples();
        const std::size_t half = all.size() / 2;
        RunHistory history;
        history.restart(one_lap().scene());
        history.append(std::vector<RunSample>(all.begin(), all.begin() + std::ptrdiff_t(half)));
        const auto view = make_view(history);
        QTRY_VERIFY(view->frameStats().summary().total > 0);
        QCoreApplication::processEvents();
        const std::size_t frames = view->frameStats().summary().total;
        const qsizetype points = view->cachedPathPointCount();
        const int trail = view->trailEllipseCount();
        QVERIFY(points > 100);

        history.append(std::vector<RunSample>(all.begin() + std::ptrdiff_t(half), all.end()));
        view->samplesAppended(static_cast<int>(half), static_cast<int>(all.size() - half));
        QVERIFY(view->cachedPathPointCount() > points + 100);
        QVERIFY(view->trailEllipseCount() > trail + 30);
        QCOMPARE(view->frameStats().summary().total, frames);      // nothing painted yet
        QTRY_VERIFY(view->frameStats().summary().total > frames);  // one paint, from the loop

        // What the view added to its picture of the history looks like a fresh paint of the
        // whole history (a few pixels differ where old and new lines cross).
        const QImage incremental = render(*view);
        const auto fresh = make_view(history);
        const QImage whole = render(*fresh);
        QCOMPARE(incremental.size(), whole.size());
        int different = 0;
        for (int y = 0; y < whole.height(); ++y) {
            for (int x = 0; x < whole.width(); ++x) {
                different +=
                    colour_distance(incremental.pixelColor(x, y), whole.pixelColor(x, y)) > 60 ? 1
                                                                                               : 0;
            }
        }
        QVERIFY2(different < whole.width() * whole.height() / 500,
                 qPrintable(QString::number(different)));

        // A restart drops everything.
        history.restart(one_lap().scene());
        view->historyRestarted();
        QCOMPARE(view->cachedPathPointCount(), qsizetype{0});
        QCOMPARE(view->trailEllipseCount(), 0);
        (void)render(*view);  // an empty history paints
    }

    void darkPaletteKeepsContrast() {
        const auto view = make_view(one_lap());
        view->setPalette(dark_palette());
        const QImage image = render(*view);
        const QTransform t = view->worldToWidget();
        const QColor background = pixel_at(image, t.map(QPointF(0.3, 0.2)));
        QVERIFY2(background.lightness() < 50, qPrintable(background.name()));
        for (const Wall& wall : one_lap().scene().walls) {
            const Vector2 middle = 0.5 * (wall.start + wall.end);
            const QColor pixel = pixel_at(image, t.map(QPointF(middle.x(), middle.y())));
            QVERIFY2(contrast_ratio(pixel, background) > 7.0, qPrintable(pixel.name()));
        }
        const ArenaColors colors = arena_colors(view->palette());
        QVERIFY(colors.dark);
        for (const QColor& series : {colors.truth, colors.estimate, colors.odometry, colors.ellipse,
                                     colors.associated, colors.rejected}) {
            QVERIFY2(contrast_ratio(series, colors.background) >= 4.5, qPrintable(series.name()));
        }
        const ArenaColors light = arena_colors(QPalette(QColor(0xef, 0xef, 0xef)));
        QVERIFY(!light.dark);
        for (const QColor& series : {light.truth, light.estimate, light.odometry, light.ellipse,
                                     light.associated, light.rejected}) {
            QVERIFY2(contrast_ratio(series, light.background) >= 4.5, qPrintable(series.name()));
        }
    }

    void drivingKeysPassThrough() {
        const auto view = make_view(one_lap());
        QCOMPARE(view->focusPolicy(), Qt::ClickFocus);
        for (const int key : {Qt::Key_Up, Qt::Key_Down, Qt::Key_Left, Qt::Key_Right, Qt::Key_Space,
                              Qt::Key_W, Qt::Key_A, Qt::Key_S, Qt::Key_D}) {
            QKeyEvent press(QEvent::KeyPress, key, Qt::NoModifier);
            QCoreApplication::sendEvent(view.get(), &press);
            QVERIFY2(!press.isAccepted(), qPrintable(QString::number(key, 16)));
        }
        const double width = view->visibleWorldRect().width();
        QKeyEvent plus(QEvent::KeyPress, Qt::Key_Plus, Qt::NoModifier, QStringLiteral("+"));
        QCoreApplication::sendEvent(view.get(), &plus);
        QVERIFY(plus.isAccepted());
        QVERIFY(view->visibleWorldRect().width() < width);
    }

    void frameTimesOverlayAndTextScale() {
        const auto view = make_view(one_lap());
        const QImage plain = render(*view);
        view->setShowFrameTimes(true);
        QVERIFY(view->frameStats().summary().total > 0);
        const QImage overlay = render(*view);
        // The overlay sits in the bottom-right corner.
        const QRect corner(view->width() - 120, view->height() - 40, 110, 30);
        QVERIFY(plain.copy(corner) != overlay.copy(corner));
        view->setTextScale(2.0);
        QCOMPARE(view->textScale(), 2.0);
        QVERIFY(render(*view) != overlay);
        view->setTextScale(100.0);
        QCOMPARE(view->textScale(), 4.0);
    }

    /// Writes the PNGs to look at when LEGOFEUP_ARENA_PNG_DIR is set.
    void savePictures() {
        const QString dir = qEnvironmentVariable("LEGOFEUP_ARENA_PNG_DIR");
        if (dir.isEmpty()) {
            QSKIP("LEGOFEUP_ARENA_PNG_DIR not set");
        }
        const auto view = make_view(one_lap(), {1200, 900});
        view->setShowFrameTimes(true);
        QVERIFY(render(*view).save(dir + "/arena_light.png"));
        view->setPalette(dark_palette());
        QVERIFY(render(*view).save(dir + "/arena_dark.png"));
        view->setPalette(QPalette());
        view->setFollowRobot(true);
        for (int i = 0; i < 4; ++i) {
            view->zoomIn();
        }
        QVERIFY(render(*view).save(dir + "/arena_follow.png"));
        view->fitArena();
        view->setTextScale(2.0);
        view->setEllipseConfidence(EllipseConfidence::Percent95);
        QVERIFY(render(*view).save(dir + "/arena_large_text.png"));
    }
};

}  // namespace legofeup::ui

QTEST_MAIN(legofeup::ui::TestArenaView)
#include "test_arena_view.moc"
