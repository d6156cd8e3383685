// The arena view's parts that need no display: the camera as the user steers it (world ↔
// widget pixels both ways, following, fitted or not), the kidnap picker's pose from a drag,
// the grid's spacing, and the registry of the lessons' layers (every lesson's localisation
// listed, the layers each draws, which lesson a run is).

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/lesson.hpp"
#include "legofeup/ui/arena/arena_camera.hpp"
#include "legofeup/ui/arena/arena_layers.hpp"
#include "legofeup/ui/arena/arena_renderer.hpp"
#include "legofeup/ui/arena/pose_picker.hpp"

namespace legofeup::ui {
namespace {

const QSizeF kViewport(800.0, 600.0);

/// A camera showing the square (−1, −1) … (1, 1) in the whole 800 × 600 widget: 300 px/m,
/// the world's origin at the widget's centre (400, 300).
ArenaCamera fitted_camera() {
    ArenaCamera camera;
    camera.fit(QRectF(-1.0, -1.0, 2.0, 2.0), QRectF(QPointF(0.0, 0.0), kViewport), kViewport);
    return camera;
}

TEST(ArenaCameraSteering, WorldToPixelsAndBackRoundTrips) {
    const ArenaCamera camera = fitted_camera();
    const QTransform to_widget = camera.shown(std::nullopt).transform(kViewport);
    // By hand: x' = 300·x + 400, y' = −300·y + 300.
    EXPECT_EQ(to_widget.map(QPointF(0.5, 0.25)), QPointF(550.0, 225.0));
    EXPECT_EQ(to_widget.map(QPointF(-1.0, -1.0)), QPointF(100.0, 600.0));
    bool invertible = false;
    const QTransform to_world = to_widget.inverted(&invertible);
    ASSERT_TRUE(invertible);
    EXPECT_EQ(to_world.map(QPointF(700.0, 0.0)), QPointF(1.0, 1.0));
    for (const QPointF world : {QPointF(0.0, 0.0), QPointF(0.37, -0.81), QPointF(-2.5, 3.25)}) {
        const QPointF back = to_world.map(to_widget.map(world));
        EXPECT_NEAR(back.x(), world.x(), 1e-12);
        EXPECT_NEAR(back.y(), world.y(), 1e-12);
    }
}

TEST(ArenaCameraSteering, FollowingCentresTheRobotAndStoppingKeepsTheView) {
    ArenaCamera camera = fitted_camera();
    EXPECT_TRUE(camera.fitted());
    const QPointF robot(0.6, -0.4);
    EXPECT_TRUE(camera.set_following(true, robot));
    EXPECT_FALSE(camera.set_following(true, robot));  // already following
    EXPECT_FALSE(camera.fitted());
    EXPECT_EQ(camera.shown(robot).transform(kViewport).map(robot), QPointF(400.0, 300.0));
    // Without an estimate to follow, the camera stays where it was.
    EXPECT_EQ(camera.shown(std::nullopt).centre(), QPointF(0.0, 0.0));
    // Zooming while following keeps the robot in the centre, whatever the anchor.
    camera.zoom_by(2.0, QPointF(10.0, 10.0), kViewport, robot);
    EXPECT_DOUBLE_EQ(camera.shown(robot).scale(), 600.0);
    EXPECT_EQ(camera.shown(robot).transform(kViewport).map(robot), QPointF(400.0, 300.0));
    // The robot drives on, the view with it; stopping leaves the view centred where
    // following left it, and the robot may move on without it.
    const QPointF later(0.9, 0.1);
    EXPECT_EQ(camera.shown(later).centre(), later);
    EXPECT_TRUE(camera.set_following(false, later));
    EXPECT_EQ(camera.shown(QPointF(5.0, 5.0)).centre(), later);
}

TEST(ArenaCameraSteering, ZoomAndPanLeaveTheFit) {
    ArenaCamera camera = fitted_camera();
    // Zoom about (550, 225), the world's (0.5, 0.25): it stays under the cursor.
    camera.zoom_by(1.25, QPointF(550.0, 225.0), kViewport, std::nullopt);
    EXPECT_FALSE(camera.fitted());
    const QPointF anchor = camera.shown(std::nullopt).transform(kViewport).map(QPointF(0.5, 0.25));
    EXPECT_NEAR(anchor.x(), 550.0, 1e-9);
    EXPECT_NEAR(anchor.y(), 225.0, 1e-9);
    camera.fit(QRectF(-1.0, -1.0, 2.0, 2.0), QRectF(QPointF(0.0, 0.0), kViewport), kViewport);
    EXPECT_TRUE(camera.fitted());
    // A drag of (30, −60) px moves the world with the mouse: 0.1 m right, 0.2 m up.
    camera.pan_by(QPointF(30.0, -60.0));
    EXPECT_FALSE(camera.fitted());
    const QPointF origin = camera.shown(std::nullopt).transform(kViewport).map(QPointF(0.0, 0.0));
    EXPECT_NEAR(origin.x(), 430.0, 1e-9);
    EXPECT_NEAR(origin.y(), 240.0, 1e-9);
}

/// Widget → world for a 100 px/m camera centred on the world's origin in an 800 × 600
/// widget: x = (x' − 400)/100, y = −(y' − 300)/100.
QTransform widget_to_world() {
    WorldCamera camera;
    camera.fit(QRectF(-4.0, -3.0, 8.0, 6.0), QRectF(QPointF(0.0, 0.0), kViewport), kViewport);
    bool invertible = false;
    return camera.transform(kViewport).inverted(&invertible);
}

TEST(PosePicker, ADragAimsTheRobotFromThePressTowardsTheCursor) {
    PosePicker picker;
    EXPECT_FALSE(picker.active());
    picker.begin();
    EXPECT_TRUE(picker.active());
    EXPECT_FALSE(picker.pressed());
    // Pressed at (300, 200): the world's (−1, 1).
    picker.press(QPointF(300.0, 200.0));
    EXPECT_TRUE(picker.pressed());
    const QTransform to_world = widget_to_world();
    // Up the screen to (300, 100), the world's (−1, 2): facing +y, θ = π/2.
    const Pose2 up = picker.pose(QPointF(300.0, 100.0), to_world, 0.0);
    EXPECT_NEAR(up.x, -1.0, 1e-12);
    EXPECT_NEAR(up.y, 1.0, 1e-12);
    EXPECT_NEAR(up.theta, kPi / 2.0, 1e-12);
    // Down and left to (200, 300), the world's (−2, 0): θ = atan2(−1, −1) = −3π/4.
    EXPECT_NEAR(picker.pose(QPointF(200.0, 300.0), to_world, 0.0).theta, -3.0 * kPi / 4.0, 1e-12);
    // A drag of 5 px (less than 8) is a click: the heading given, wrapped (5π/2 → π/2).
    EXPECT_NEAR(picker.pose(QPointF(303.0, 204.0), to_world, 2.5 * kPi).theta, kPi / 2.0, 1e-12);
    // The drag's pose as it goes, then the release ends the pick with it: to (400, 200),
    // the world's (0, 1), θ = 0.
    picker.move_to(QPointF(400.0, 200.0));
    EXPECT_NEAR(picker.pose_now(to_world, 1.0).theta, 0.0, 1e-12);
    const std::optional<Pose2> picked = picker.release(QPointF(400.0, 200.0), to_world, 1.0);
    ASSERT_TRUE(picked.has_value());
    EXPECT_NEAR(picked->x, -1.0, 1e-12);
    EXPECT_NEAR(picked->y, 1.0, 1e-12);
    EXPECT_NEAR(picked->theta, 0.0, 1e-12);
    EXPECT_FALSE(picker.active());
    EXPECT_FALSE(picker.release(QPointF(400.0, 200.0), to_world, 1.0).has_value());
}

TEST(PosePicker, CancelEndsItOnceAndAReleaseWithoutAPressPicksNothing) {
    PosePicker picker;
    EXPECT_FALSE(picker.cancel());
    picker.begin();
    EXPECT_FALSE(picker.release(QPointF(1.0, 1.0), widget_to_world(), 0.0).has_value());
    EXPECT_TRUE(picker.active());
    picker.press(QPointF(10.0, 10.0));
    EXPECT_TRUE(picker.cancel());
    EXPECT_FALSE(picker.active());
    EXPECT_FALSE(picker.pressed());
    EXPECT_FALSE(picker.cancel());
}

TEST(ArenaGrid, SpacingGrowsUntilTheLinesAre24PixelsApart) {
    EXPECT_DOUBLE_EQ(grid_spacing(48.0), 0.5);    // 0.5 m = 24 px
    EXPECT_DOUBLE_EQ(grid_spacing(47.0), 1.0);    // 0.5 m = 23.5 px: too dense
    EXPECT_DOUBLE_EQ(grid_spacing(10.0), 5.0);    // 2 m = 20 px, 5 m = 50 px
    EXPECT_DOUBLE_EQ(grid_spacing(0.01), 100.0);  // never coarser than 100 m
}

std::set<std::string> layer_names(Localisation localisation) {
    std::set<std::string> names;
    for (const ArenaLayer* layer : layers_for(built_in_arena_layers(), localisation)) {
        names.insert(layer->name());
    }
    return names;
}

TEST(ArenaLayerRegistry, ListsEveryLocalisationOnceAndEachLessonsLayers) {
    std::set<Localisation> listed;
    for (const ArenaLessonLayers& entry : built_in_arena_layers()) {
        EXPECT_TRUE(listed.insert(entry.localisation).second) << to_string(entry.localisation);
        for (const ArenaLayer* layer : entry.layers) {
            ASSERT_NE(layer, nullptr);
        }
    }
    // Every step of every lesson that ships localises in a way the registry lists.
    for (const lessons::BuiltInLesson& built_in : lessons::built_in_lessons()) {
        const lessons::Lesson* lesson = lessons::find_built_in_lesson(built_in.id);
        ASSERT_NE(lesson, nullptr) << built_in.id;
        for (const lessons::LessonStep& step : lesson->steps) {
            const Localisation localisation = step.config.lesson.localisation;
            EXPECT_TRUE(listed.contains(localisation))
                << built_in.id << ":" << step.id << " " << to_string(localisation);
        }
    }
    // The particle cloud goes with every localisation a particle filter can run (the
    // 5-state fusion is an EKF of its own).
    EXPECT_EQ(layer_names(Localisation::Walls),
              (std::set<std::string>{"particle cloud", "IR rays"}));
    EXPECT_EQ(layer_names(Localisation::Beacons),
              (std::set<std::string>{"particle cloud", "beacons"}));
    EXPECT_EQ(layer_names(Localisation::Laser),
              (std::set<std::string>{"particle cloud", "laser scans"}));
    EXPECT_TRUE(layer_names(Localisation::GyroFusion).empty());
    EXPECT_EQ(layer_names(Localisation::Compass), std::set<std::string>{"particle cloud"});
    EXPECT_TRUE(layers_for(ArenaLayerRegistry{}, Localisation::Walls).empty());
}

TEST(ArenaLayerRegistry, TheRunsLessonIsTheLatestSamplesOrBeforeItTheScenes) {
    RunHistory history;
    EXPECT_EQ(shown_localisation(history), Localisation::Walls);
    ArenaScene beacons;
    beacons.beacons = {{1, Vector2(0.5, 0.5)}};
    history.restart(beacons);
    EXPECT_EQ(shown_localisation(history), Localisation::Beacons);
    ArenaScene laser;
    laser.laser.active = true;
    history.restart(laser);
    EXPECT_EQ(shown_localisation(history), Localisation::Laser);
    RunSample sample;
    sample.snapshot.localisation = Localisation::Compass;
    history.append({sample});
    EXPECT_EQ(shown_localisation(history), Localisation::Compass);
}

}  // namespace
}  // namespace legofeup::ui
