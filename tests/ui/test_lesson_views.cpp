// The views adapting to the further lessons (issue 8): beacons, bearing rays, the second
// filter's estimate and the particle cloud in the arena; the bearing, heading-sensor,
// wheel-speed, EKF/UKF/PF and particle plots shown only when the run has their data; the
// configuration panel greying what the localisation does not use, and EKF/UKF switched live from
// it.

#include <QComboBox>
#include <QImage>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <qcustomplot.h>

#include "legofeup/core/angles.hpp"
#include "legofeup/lessons/experiments.hpp"
#include "legofeup/ui/arena/arena_colors.hpp"
#include "legofeup/ui/arena/arena_view.hpp"
#include "legofeup/ui/lesson/lesson_panel.hpp"
#include "legofeup/ui/lesson/lesson_progress.hpp"
#include "legofeup/ui/panels/config_panel.hpp"
#include "legofeup/ui/plots/plots_panel.hpp"
#include "legofeup/ui/session/session.hpp"
#include "support/arena_pixels.hpp"
#include "support/lockstep_history.hpp"

namespace legofeup::ui {

namespace {

using testing::one_lap;
using testing::one_lap_samples;

constexpr int kPatienceMs = 30000;
constexpr std::size_t kSamples = 200;  ///< the first 10 s of the lap: along the bottom wall
constexpr int kGatedId = 4;
/// How far a plotted value may be from the number it was made of: the history's record keeps
/// the plots' numbers as floats (7 significant digits; headings up to π rad: ~1e-5°).
constexpr double kRecorded = 1e-5;
constexpr double kRecordedHeading = 1e-4;
/// Measured − predicted bearing of beacon `id` in the synthetic samples, rad.
double innovation_of(int id) {
    return id == kGatedId ? 0.2 : 0.05 * id;
}
const Vector2 kShadowOffset(0.25, -0.15);

/// Four beacons 0.1 m inside the corners of the walls' bounding box, ids 1–4 from the lower
/// left, counter-clockwise (as the standard arena has them).
BeaconMap corner_beacons(const std::vector<Wall>& walls) {
    double left = 1e9;
    double right = -1e9;
    double bottom = 1e9;
    double top = -1e9;
    for (const Wall& wall : walls) {
        for (const Vector2& end : {wall.start, wall.end}) {
            left = std::min(left, end.x());
            right = std::max(right, end.x());
            bottom = std::min(bottom, end.y());
            top = std::max(top, end.y());
        }
    }
    return {{1, Vector2(left + 0.1, bottom + 0.1)},
            {2, Vector2(right - 0.1, bottom + 0.1)},
            {3, Vector2(right - 0.1, top - 0.1)},
            {4, Vector2(left + 0.1, top - 0.1)}};
}

/// The direction of `beacon` seen from the estimate, relative to its heading: h(X̂).
double expected_bearing(const StateVector& x, const Beacon& beacon) {
    return wrap_angle(std::atan2(beacon.position.y() - x(kY), beacon.position.x() - x(kX))
                      - x(kTheta));
}

/// The first kSamples of a wall lap turned into a beacon run: every beacon seen at every
/// step, measured bearing = h(X̂) + innovation_of(id), beacon 4 turned away by the gate;
/// with `shadow`, a UKF beside the EKF, kShadowOffset away, with 4·P, and filter timings.
RunHistory beacon_history(bool shadow) {
    ArenaScene scene = one_lap().scene();
    scene.beacons = corner_beacons(scene.walls);
    std::vector<RunSample> samples(one_lap_samples().begin(), one_lap_samples().begin() + kSamples);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        LoopSnapshot& s = samples[i].snapshot;
        s.localisation = Localisation::Beacons;
        s.association = AssociationResult{};
        s.update = WallUpdateReport{};
        s.beacons.count = static_cast<std::uint8_t>(scene.beacons.size());
        for (std::size_t b = 0; b < scene.beacons.size(); ++b) {
            BeaconUpdate& update = s.beacons.updates[b];
            update.id = static_cast<std::uint8_t>(scene.beacons[b].id);
            update.known = true;
            update.predicted = expected_bearing(s.estimate, scene.beacons[b]);
            update.bearing = wrap_angle(update.predicted + innovation_of(scene.beacons[b].id));
            update.status =
                scene.beacons[b].id == kGatedId ? StepStatus::RejectedByGate : StepStatus::Applied;
            update.nis = 1.0;
        }
        s.filter_seconds = 20e-6 + 1e-6 * static_cast<double>(i % 7);
        if (shadow) {
            s.shadow.active = true;
            s.shadow.kind = FilterKind::Ukf;
            s.shadow.estimate = s.estimate;
            s.shadow.estimate(kX) += kShadowOffset.x();
            s.shadow.estimate(kY) += kShadowOffset.y();
            s.shadow.covariance = 4.0 * s.covariance;
            s.shadow_filter_seconds = 80e-6 + 3e-6 * static_cast<double>(i % 5);
        }
    }
    RunHistory history;
    history.restart(scene);
    history.append(std::move(samples));
    return history;
}

constexpr double kGyroHeadingError = 0.1;      ///< rad
constexpr double kCompassHeadingError = -0.2;  ///< rad
constexpr double kGyroRateError = 0.01;        ///< rad/s

/// The first kSamples of a wall lap with a gyroscope and a compass (fixed errors against
/// the truth) and the wheel-speed estimates, as the 5-state fusion lesson has them.
RunHistory sensor_history() {
    std::vector<RunSample> samples(one_lap_samples().begin(), one_lap_samples().begin() + kSamples);
    for (RunSample& sample : samples) {
        LoopSnapshot& s = sample.snapshot;
        const GroundTruth& truth = *sample.truth;
        s.localisation = Localisation::GyroFusion;
        s.readings.has_gyro = true;
        s.readings.gyro_heading = wrap_angle(truth.pose.theta + kGyroHeadingError);
        s.readings.gyro_rate = truth.velocity.w + kGyroRateError;
        s.readings.has_compass = true;
        s.readings.compass_heading = wrap_angle(truth.pose.theta + kCompassHeadingError);
        s.speeds.valid = true;
        s.speeds.wheel_kf = {truth.wheel_surface_speeds.right + 0.01,
                             truth.wheel_surface_speeds.left - 0.01};
        s.speeds.wheel_differentiated = {truth.wheel_surface_speeds.right + 0.03,
                                         truth.wheel_surface_speeds.left - 0.03};
        s.speeds.body_encoders = truth.velocity;
        s.fused_velocity = truth.velocity;
    }
    RunHistory history;
    history.restart(one_lap().scene());
    history.append(std::move(samples));
    return history;
}

/// Offsets from the estimate of the particle history's two clusters, m.
const Vector2 kHeavyCluster(0.35, 0.25);
const Vector2 kLightCluster(-0.45, 0.3);
constexpr int kParticleCount = 5000;
constexpr float kLightWeight = 0.1F;

/// The first kSamples of a wall lap as a particle filter's (filter.kind = "pf") with an EKF
/// beside it: each sample's cloud in two clusters off the estimate, the heavy one at full
/// weight, the light one at kLightWeight; N_eff falls from 5,000 by one a
/// step.
RunHistory particle_history() {
    std::vector<RunSample> samples(one_lap_samples().begin(), one_lap_samples().begin() + kSamples);
    for (std::size_t i = 0; i < samples.size(); ++i) {
        LoopSnapshot& s = samples[i].snapshot;
        s.filter_kind = FilterKind::Pf;
        s.particles.count = kParticleCount;
        s.particles.effective = kParticleCount - static_cast<double>(i);
        s.shadow.active = true;
        s.shadow.kind = FilterKind::Ekf;
        s.shadow.estimate = s.estimate;
        s.shadow.estimate(kX) += kShadowOffset.x();
        s.shadow.estimate(kY) += kShadowOffset.y();
        s.shadow.covariance = s.covariance;
        s.filter_seconds = 200e-6;
        s.shadow_filter_seconds = 20e-6;
        auto cloud = std::make_shared<std::vector<ParticlePoint>>();
        for (int k = 0; k < 400; ++k) {
            // Heavy: on top of one another (copies after a resampling); light: 5 cm apart on
            // a 20 × 10 grid from kLightCluster, so that no dot covers another (overlapping
            // faint dots add up to an opaque one, as a dense cluster does on screen).
            const bool heavy = k % 2 == 0;
            const int j = k / 2;
            const Vector2 at = heavy ? kHeavyCluster
                                     : Vector2(kLightCluster.x() + 0.05 * (j % 20),
                                               kLightCluster.y() + 0.05 * (j / 20));
            cloud->push_back({static_cast<float>(s.estimate(kX) + at.x()),
                              static_cast<float>(s.estimate(kY) + at.y()), 0.0F,
                              heavy ? 1.0F : kLightWeight});
        }
        samples[i].particles = std::move(cloud);
    }
    RunHistory history;
    history.restart(one_lap().scene());
    history.append(std::move(samples));
    return history;
}

using testing::nearest_colour_distance;
using testing::render;

/// `over` painted with `alpha` on top of `under`.
QColor blend(const QColor& over, int alpha, const QColor& under) {
    const auto mix = [alpha](int a, int b) { return (a * alpha + b * (255 - alpha)) / 255; };
    return {mix(over.red(), under.red()), mix(over.green(), under.green()),
            mix(over.blue(), under.blue())};
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

/// A point halfway along the measured bearing ray of beacon `id` in the latest sample.
QPointF ray_middle(const RunHistory& history, int id) {
    const LoopSnapshot& s = history.latest().snapshot;
    const Beacon* beacon = find_beacon(history.scene().beacons, id);
    if (beacon == nullptr) {
        qFatal("the scene has no beacon %d", id);  // the test's own history is wrong
    }
    const Pose2 pose = to_pose(s.estimate);
    const double bearing = wrap_angle(expected_bearing(s.estimate, *beacon) + innovation_of(id));
    // Independently of bearing_ray(): along θ + z, half the drawn length.
    const double half =
        0.5 * 1.15 * std::hypot(beacon->position.x() - pose.x, beacon->position.y() - pose.y);
    return {pose.x + half * std::cos(pose.theta + bearing),
            pose.y + half * std::sin(pose.theta + bearing)};
}

int visible_tabs(const PlotsPanel& panel) {
    const auto* tabs = panel.findChild<QTabWidget*>();
    int visible = 0;
    for (int t = 0; t < tabs->count(); ++t) {
        visible += tabs->isTabVisible(t) ? 1 : 0;
    }
    return visible;
}

constexpr PlotKind kLessonPlots[] = {PlotKind::Bearings,    PlotKind::HeadingSensors,
                                     PlotKind::TurnRate,    PlotKind::WheelSpeedEstimates,
                                     PlotKind::ShadowError, PlotKind::FilterCost,
                                     PlotKind::Particles};

}  // namespace

class TestLessonViews : public QObject {
    Q_OBJECT

  private:
    QTemporaryDir config_home_;

  private slots:
    void initTestCase() {
        // The lesson dock keeps its choice with the preferences: in a directory of our own.
        QVERIFY(config_home_.isValid());
        qputenv("XDG_CONFIG_HOME", config_home_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("LegoFeupTest"));
        QCoreApplication::setApplicationName(QStringLiteral("LegoFeup Lab Lesson Views Test"));
    }

    // ---- arena --------------------------------------------------------------------------

    void wallRunShowsNothingNew() {
        const auto view = make_view(one_lap());
        const QStringList legend = view->legendTexts();
        QVERIFY(legend.contains(QStringLiteral("estimate (EKF)")));
        QVERIFY(legend.contains(QStringLiteral("IR rays used; the wall matched")));
        for (const QString& text : legend) {
            QVERIFY2(!text.contains(QStringLiteral("beacon")) && !text.contains("bearing")
                         && !text.contains(QStringLiteral("UKF"))
                         && !text.contains(QStringLiteral("particle")),
                     qPrintable(text));
        }
        // Where the beacon lesson's beacon 3 would be: no beacon colour.
        const ArenaColors colors = arena_colors(view->palette());
        const Beacon beacon = corner_beacons(one_lap().scene().walls)[2];
        const QPointF at =
            view->worldToWidget().map(QPointF(beacon.position.x(), beacon.position.y()));
        QVERIFY(nearest_colour_distance(render(*view), at, colors.beacon) > 60);
    }

    void beaconsRaysAndTheSecondFilterAreDrawn() {
        const RunHistory history = beacon_history(true);
        const auto view = make_view(history);
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        // Every beacon: its colour at its place.
        for (const Beacon& beacon : history.scene().beacons) {
            const QPointF at = t.map(QPointF(beacon.position.x(), beacon.position.y()));
            QVERIFY2(nearest_colour_distance(image, at, colors.beacon) <= 8,
                     qPrintable(QString::number(beacon.id)));
        }
        // The applied bearing of beacon 3 in the "used" colour, the gated one of beacon 4 in
        // the "not used" one (both drawn at alpha 220).
        QVERIFY(nearest_colour_distance(image, t.map(ray_middle(history, 3)),
                                        blend(colors.associated, 220, colors.background))
                <= 40);
        QVERIFY(nearest_colour_distance(image, t.map(ray_middle(history, kGatedId)),
                                        blend(colors.rejected, 220, colors.background))
                <= 40);
        // The UKF's estimate in its own colour at its place.
        const StateVector& shadow = history.latest().snapshot.shadow.estimate;
        QCOMPARE(
            nearest_colour_distance(image, t.map(QPointF(shadow(kX), shadow(kY))), colors.shadow),
            0);
        const QStringList legend = view->legendTexts();
        QVERIFY(legend.contains(QStringLiteral("estimate (EKF)")));
        QVERIFY(legend.contains(QStringLiteral("UKF on the same frames, its ellipse dashed")));
        QVERIFY(legend.contains(QStringLiteral("beacons")));
        QVERIFY(legend.contains(QStringLiteral("bearings measured, applied")));
        QVERIFY(legend.contains(QStringLiteral("not applied")));
        QVERIFY(!legend.contains(QStringLiteral("IR rays used; the wall matched")));
    }

    void theParticleCloudIsDrawnWithItsWeightAsOpacity() {
        const RunHistory history = particle_history();
        const auto view = make_view(history);
        const QImage image = render(*view);
        const ArenaColors colors = arena_colors(view->palette());
        const QTransform t = view->worldToWidget();
        const StateVector& x = history.latest().snapshot.estimate;
        const QPointF heavy = t.map(QPointF(x(kX) + kHeavyCluster.x(), x(kY) + kHeavyCluster.y()));
        const QPointF light = t.map(QPointF(x(kX) + kLightCluster.x(), x(kY) + kLightCluster.y()));
        // The heavy particles opaque; the light ones in the faintest band (alpha 70).
        QVERIFY(nearest_colour_distance(image, heavy, colors.particles) <= 8);
        const QColor faint = blend(colors.particles, 70, colors.background);
        QVERIFY(nearest_colour_distance(image, light, faint) <= 24);
        QVERIFY(nearest_colour_distance(image, light, colors.particles) > 40);
        QVERIFY(view->legendTexts().contains(
            QStringLiteral("particles: the fainter, the less weight")));
        QVERIFY(view->legendTexts().contains(QStringLiteral("estimate (PF)")));

        // The same run without its clouds (an EKF's): nothing there.
        RunHistory gaussian;
        gaussian.restart(history.scene());
        std::vector<RunSample> samples = testing::whole_samples(history);
        for (RunSample& sample : samples) {
            sample.particles.reset();
            sample.snapshot.particles = {};
        }
        gaussian.append(std::move(samples));
        const auto plain = make_view(gaussian);
        QVERIFY(nearest_colour_distance(render(*plain), heavy, colors.particles) > 40);
        QVERIFY(!plain->legendTexts().contains(
            QStringLiteral("particles: the fainter, the less weight")));
    }

    void withoutTheShadowNoSecondEstimate() {
        const RunHistory history = beacon_history(false);
        const auto view = make_view(history);
        const ArenaColors colors = arena_colors(view->palette());
        const StateVector& x = history.latest().snapshot.estimate;
        const QPointF where = view->worldToWidget().map(
            QPointF(x(kX) + kShadowOffset.x(), x(kY) + kShadowOffset.y()));
        QVERIFY(nearest_colour_distance(render(*view), where, colors.shadow) > 40);
        for (const QString& text : view->legendTexts()) {
            QVERIFY2(!text.contains(QStringLiteral("UKF")), qPrintable(text));
        }
    }

    void newColoursKeepContrast() {
        for (const bool dark : {false, true}) {
            QPalette palette;
            palette.setColor(QPalette::Base, dark ? QColor(0x1e, 0x1e, 0x1e) : Qt::white);
            palette.setColor(QPalette::Text, dark ? QColor(0xe6, 0xe6, 0xe6) : Qt::black);
            palette.setColor(QPalette::WindowText, dark ? QColor(0xe6, 0xe6, 0xe6) : Qt::black);
            const ArenaColors colors = arena_colors(palette);
            QVERIFY(contrast_ratio(colors.beacon, colors.background) >= 4.5);
            QVERIFY(contrast_ratio(colors.shadow, colors.background) >= 4.5);
            QVERIFY(contrast_ratio(colors.particles, colors.background) >= 4.5);
        }
    }

    // ---- plots --------------------------------------------------------------------------

    void wallRunHasNoLessonPlots() {
        PlotsPanel panel(one_lap());
        for (const PlotKind kind : kLessonPlots) {
            QVERIFY(!panel.plotShown(kind));
            for (int g = 0; g < panel.plot(kind)->graphCount(); ++g) {
                QCOMPARE(panel.plot(kind)->graph(g)->dataCount(), 0);
            }
        }
        QVERIFY(panel.plotShown(PlotKind::Covariance));
        QCOMPARE(visible_tabs(panel), 3);
    }

    void beaconRunPlotsInnovationsErrorsAndCosts() {
        const RunHistory history = beacon_history(true);
        PlotsPanel panel(history);
        QVERIFY(panel.plotShown(PlotKind::Bearings));
        QVERIFY(panel.plotShown(PlotKind::ShadowError));
        QVERIFY(panel.plotShown(PlotKind::FilterCost));
        QVERIFY(!panel.plotShown(PlotKind::HeadingSensors));
        QVERIFY(!panel.plotShown(PlotKind::WheelSpeedEstimates));
        QCOMPARE(visible_tabs(panel), 4);

        // Three applied bearings and one gated per step, as innovations in degrees.
        const auto applied = panel.graph(Series::BearingApplied)->data();
        const auto gated = panel.graph(Series::BearingGated)->data();
        QCOMPARE(applied->size(), 3 * static_cast<int>(kSamples));
        QCOMPARE(gated->size(), static_cast<int>(kSamples));
        for (auto it = applied->constBegin(); it != applied->constEnd(); ++it) {
            const bool one_of = std::abs(it->value - radians_to_degrees(0.05)) < kRecorded
                                || std::abs(it->value - radians_to_degrees(0.10)) < kRecorded
                                || std::abs(it->value - radians_to_degrees(0.15)) < kRecorded;
            QVERIFY2(one_of, qPrintable(QString::number(it->value)));
        }
        QVERIFY(std::abs(gated->at(0)->value - 11.459155902616464) < kRecorded);

        // Position errors against the truth: the EKF is the primary, the UKF the shadow.
        const auto ekf = panel.graph(Series::EkfPositionError)->data();
        const auto ukf = panel.graph(Series::UkfPositionError)->data();
        QCOMPARE(ekf->size(), static_cast<int>(kSamples));
        for (std::size_t i = 0; i < kSamples; i += 37) {
            const RunSample& sample = *history.sample(i);  // 200 samples: all kept whole
            const StateVector& x = sample.snapshot.estimate;
            const Pose2& truth = sample.truth->pose;
            const auto k = static_cast<int>(i);
            QVERIFY(std::abs(ekf->at(k)->value - std::hypot(x(kX) - truth.x, x(kY) - truth.y))
                    < 1e-12);
            QVERIFY(std::abs(ukf->at(k)->value
                             - std::hypot(x(kX) + kShadowOffset.x() - truth.x,
                                          x(kY) + kShadowOffset.y() - truth.y))
                    < kRecorded);  // the shadow's position is a float, the estimate a double
        }

        // Costs in µs, smoothed s ← s + (v − s)/20 from the first value.
        double ekf_cost = std::nan("");
        double ukf_cost = std::nan("");
        for (std::size_t i = 0; i < history.size(); ++i) {
            const RunSample& sample = *history.sample(i);
            const double e = sample.snapshot.filter_seconds * 1e6;
            const double u = sample.snapshot.shadow_filter_seconds * 1e6;
            ekf_cost = std::isnan(ekf_cost) ? e : ekf_cost + (e - ekf_cost) / 20.0;
            ukf_cost = std::isnan(ukf_cost) ? u : ukf_cost + (u - ukf_cost) / 20.0;
        }
        const auto ekf_costs = panel.graph(Series::EkfCost)->data();
        const auto ukf_costs = panel.graph(Series::UkfCost)->data();
        QVERIFY(std::abs(ekf_costs->at(ekf_costs->size() - 1)->value - ekf_cost) < kRecorded);
        QVERIFY(std::abs(ukf_costs->at(ukf_costs->size() - 1)->value - ukf_cost) < kRecorded);
        QVERIFY(std::abs(ekf_costs->at(0)->value - 20.0) < kRecorded);  // the first value as is
    }

    void particleRunPlotsItsCloudAndThePfBesideTheEkf() {
        const RunHistory history = particle_history();
        PlotsPanel panel(history);
        QVERIFY(panel.plotShown(PlotKind::Particles));
        QVERIFY(panel.plotShown(PlotKind::ShadowError));
        QVERIFY(panel.plotShown(PlotKind::FilterCost));
        QVERIFY(!panel.plotShown(PlotKind::Bearings));
        QCOMPARE(visible_tabs(panel), 5);  // the three, the filters' and the particles'
        const auto count = panel.graph(Series::ParticleCount)->data();
        const auto effective = panel.graph(Series::ParticleEffective)->data();
        QCOMPARE(count->size(), static_cast<int>(kSamples));
        QCOMPARE(effective->size(), static_cast<int>(kSamples));
        for (int i = 0; i < count->size(); i += 23) {
            QCOMPARE(count->at(i)->value, static_cast<double>(kParticleCount));
            QCOMPARE(effective->at(i)->value, static_cast<double>(kParticleCount - i));
        }
        // The PF is the primary here, the EKF the shadow: each error from its own estimate.
        const auto pf = panel.graph(Series::PfPositionError)->data();
        const auto ekf = panel.graph(Series::EkfPositionError)->data();
        QCOMPARE(pf->size(), static_cast<int>(kSamples));
        QCOMPARE(ekf->size(), static_cast<int>(kSamples));
        QCOMPARE(panel.graph(Series::UkfPositionError)->dataCount(), 0);
        const RunSample& last = history.latest();
        const StateVector& x = last.snapshot.estimate;
        const Pose2& truth = last.truth->pose;
        const int k = static_cast<int>(kSamples) - 1;
        QVERIFY(std::abs(pf->at(k)->value - std::hypot(x(kX) - truth.x, x(kY) - truth.y)) < 1e-12);
        QVERIFY(std::abs(ekf->at(k)->value
                         - std::hypot(x(kX) + kShadowOffset.x() - truth.x,
                                      x(kY) + kShadowOffset.y() - truth.y))
                < kRecorded);
        const auto pf_cost = panel.graph(Series::PfCost)->data();
        QVERIFY(std::abs(pf_cost->at(pf_cost->size() - 1)->value - 200.0) < 1e-3);
        // A Gaussian filter's run has no particle plot (wallRunHasNoLessonPlots).
    }

    void withoutTheShadowNoComparisonPlots() {
        PlotsPanel panel(beacon_history(false));
        QVERIFY(panel.plotShown(PlotKind::Bearings));
        QVERIFY(!panel.plotShown(PlotKind::ShadowError));
        QVERIFY(!panel.plotShown(PlotKind::FilterCost));
    }

    void sensorRunPlotsHeadingsRatesAndWheelSpeeds() {
        const RunHistory history = sensor_history();
        PlotsPanel panel(history);
        QVERIFY(panel.plotShown(PlotKind::HeadingSensors));
        QVERIFY(panel.plotShown(PlotKind::TurnRate));
        QVERIFY(panel.plotShown(PlotKind::WheelSpeedEstimates));
        QVERIFY(!panel.plotShown(PlotKind::Bearings));
        QVERIFY(!panel.plotShown(PlotKind::ShadowError));
        QCOMPARE(visible_tabs(panel), 4);
        // The legend names only the series the run has: no bearing, no 5-state EKF… here,
        // but the gyro's.
        QVERIFY(panel.plot(PlotKind::TurnRate)
                    ->legend->hasItemWithPlottable(panel.graph(Series::TurnRateGyro)));
        QVERIFY(panel.plot(PlotKind::TurnRate)
                    ->legend->hasItemWithPlottable(panel.graph(Series::TurnRateFused)));
        const RunHistory beacons = beacon_history(false);
        PlotsPanel beacon_panel(beacons);
        QVERIFY(!beacon_panel.plot(PlotKind::Bearings)
                     ->legend->hasItemWithPlottable(beacon_panel.graph(Series::BearingApplied))
                || beacon_panel.graph(Series::BearingApplied)->dataCount() > 0);
        QVERIFY(!beacon_panel.plot(PlotKind::TurnRate)
                     ->legend->hasItemWithPlottable(beacon_panel.graph(Series::TurnRateFused)));
        const auto gyro = panel.graph(Series::HeadingErrorGyro)->data();
        const auto compass = panel.graph(Series::HeadingErrorCompass)->data();
        const auto rate = panel.graph(Series::TurnRateGyro)->data();
        const auto rate_true = panel.graph(Series::TurnRateTrue)->data();
        QCOMPARE(gyro->size(), static_cast<int>(kSamples));
        for (int i = 0; i < gyro->size(); ++i) {
            // Headings up to π rad as floats: a few 1e-6 degrees off.
            QVERIFY(std::abs(gyro->at(i)->value - radians_to_degrees(kGyroHeadingError))
                    < kRecordedHeading);
            QVERIFY(std::abs(compass->at(i)->value - radians_to_degrees(kCompassHeadingError))
                    < kRecordedHeading);
            QVERIFY(std::abs(rate->at(i)->value - rate_true->at(i)->value
                             - radians_to_degrees(kGyroRateError))
                    < kRecordedHeading);
        }
        const auto kf = panel.graph(Series::WheelRightKf)->data();
        const auto truth = panel.graph(Series::WheelRightTrue)->data();
        QCOMPARE(kf->size(), static_cast<int>(kSamples));
        QVERIFY(std::abs(kf->at(50)->value - truth->at(50)->value - 0.01) < kRecorded);
    }

    void lessonPlotsDisappearWhenTheHistoryRestarts() {
        RunHistory history = beacon_history(true);
        PlotsPanel panel(history);
        QVERIFY(panel.plotShown(PlotKind::Bearings));
        history.restart(one_lap().scene());
        panel.historyRestarted();
        QVERIFY(!panel.plotShown(PlotKind::Bearings));
        QCOMPARE(visible_tabs(panel), 3);
    }

    void theSceneHasTheBeaconsOnlyWhenTheFilterUsesThem() {
        lessons::RunConfig config = lessons::find_experiment("f")->config;
        const lessons::ResolvedRun walls = lessons::resolve(config);
        QVERIFY(scene_of(walls).beacons.empty());
        config.lesson.localisation = Localisation::Beacons;
        const lessons::ResolvedRun beacons = lessons::resolve(config);
        QVERIFY(!beacons.world.beacons.empty());
        const ArenaScene scene = scene_of(beacons);
        QCOMPARE(scene.beacons.size(), beacons.world.beacons.size());
        for (std::size_t i = 0; i < scene.beacons.size(); ++i) {
            QCOMPARE(scene.beacons[i].id, beacons.world.beacons[i].id);
            QCOMPARE(scene.beacons[i].position, beacons.world.beacons[i].position);
        }
    }

    void theWantedTabComesBackWhenItsDataDoes() {
        RunHistory history;
        history.restart(one_lap().scene());
        PlotsPanel panel(history);
        auto* tabs = panel.findChild<QTabWidget*>();
        constexpr int kBeaconTab = 3;
        QCOMPARE(tabs->tabText(kBeaconTab), QStringLiteral("Beacons && filters"));
        panel.setWantedTab(kBeaconTab);
        QCOMPARE(panel.wantedTab(), kBeaconTab);
        QCOMPARE(tabs->currentIndex(), 0);  // hidden until the run has bearings
        const RunHistory beacons = beacon_history(true);
        history.restart(beacons.scene());
        panel.historyRestarted();
        history.append(testing::whole_samples(beacons));
        panel.samplesAppended(0, static_cast<int>(history.size()));
        QCOMPARE(tabs->currentIndex(), kBeaconTab);
    }

    // ---- lesson dock --------------------------------------------------------------------

    void theLessonChoiceListsEveryBuiltInLesson() {
        Session session(lessons::find_experiment("f")->config);
        {
            LessonPanel panel(session);
            auto* choice = panel.findChild<QComboBox*>(QStringLiteral("lessonChoice"));
            QVERIFY(choice != nullptr);
            const auto& built_in = lessons::built_in_lessons();
            QVERIFY(built_in.size() >= 4);
            QCOMPARE(choice->count(), static_cast<int>(built_in.size()));
            for (std::size_t i = 0; i < built_in.size(); ++i) {
                QVERIFY(choice->itemText(static_cast<int>(i))
                            .startsWith(QString::fromStdString(built_in[i].title)));
            }
            QCOMPARE(panel.progress().lesson().id, std::string("legofeup"));
            // Choosing the beacon lesson switches to it, with its steps.
            const int beacons = choice->findData(QStringLiteral("builtin:beacons"));
            QVERIFY(beacons >= 0);
            choice->setCurrentIndex(beacons);
            emit choice->activated(beacons);
            QCOMPARE(panel.progress().lesson().id, std::string("beacons"));
            QCOMPARE(panel.progress().lesson().steps.size(),
                     lessons::find_built_in_lesson("beacons")->steps.size());
            QCOMPARE(choice->currentIndex(), beacons);
        }
        // The next start comes back to it.
        LessonPanel again(session);
        QCOMPARE(again.progress().lesson().id, std::string("beacons"));
        again.useBuiltInLesson();
        QCOMPARE(again.progress().lesson().id, std::string("legofeup"));
    }

    // ---- configuration panel ------------------------------------------------------------

    void settingsTheLocalisationDoesNotUseAreGreyed() {
        lessons::RunConfig config = lessons::find_experiment("f")->config;
        config.lesson.localisation = Localisation::Beacons;
        Session session(config);
        ConfigPanel panel(session);
        QVERIFY(panel.isRelevant("filter.q11"));
        QVERIFY(panel.isRelevant("filter.kind"));
        QVERIFY(panel.isRelevant("beacons.r_bearing"));
        QVERIFY(!panel.isRelevant("filter.r11"));
        QVERIFY(!panel.isRelevant("ir_curve.a"));
        QVERIFY(!panel.isRelevant("compass.r_compass"));

        // The loop takes the estimators' settings at the next step; the simulated sensors
        // wait for the next start.
        for (const char* key : {"filter.kind", "filter.compare_kinds", "localisation.method",
                                "beacons.r_bearing", "compass.r_compass"}) {
            QVERIFY2(lessons::find_setting_by_key(key)->applies_live(), key);
        }
        QVERIFY(!lessons::find_setting_by_key("beacon_scanner.enabled")->applies_live());

        config.lesson.localisation = Localisation::Walls;
        QVERIFY(session.setConfig(config).isEmpty());
        QVERIFY(panel.isRelevant("filter.r11"));
        QVERIFY(!panel.isRelevant("beacons.r_bearing"));
    }

    void filterKindSwitchesLiveFromThePanel() {
        lessons::RunConfig config = lessons::find_experiment("f")->config;
        config.lesson.localisation = Localisation::Beacons;
        Session session(config);
        LinkChoice fast;
        fast.speed = 10.0;
        session.setLinkChoice(fast);
        ConfigPanel panel(session);
        panel.show();
        auto* kind = panel.findChild<QComboBox*>(QStringLiteral("filter.kind"));
        QVERIFY(kind != nullptr);
        session.start();
        QTRY_VERIFY_WITH_TIMEOUT(session.history().size() >= 20, kPatienceMs);
        QCOMPARE(session.history().latest().snapshot.filter_kind, FilterKind::Ekf);
        const int ukf = kind->findText(QStringLiteral("ukf"));
        QVERIFY(ukf >= 0);
        kind->setCurrentIndex(ukf);
        emit kind->activated(ukf);  // as a click on the item does
        QCOMPARE(session.config().lesson.kind, FilterKind::Ukf);
        QVERIFY(session.running());  // live: the run goes on
        const std::size_t changed_at = session.history().size();
        QTRY_VERIFY_WITH_TIMEOUT(session.history().size() > changed_at + 20, kPatienceMs);
        QCOMPARE(session.history().latest().snapshot.filter_kind, FilterKind::Ukf);
        QCOMPARE(session.history().latest().snapshot.localisation, Localisation::Beacons);
        session.stop();
    }
};

}  // namespace legofeup::ui

QTEST_MAIN(legofeup::ui::TestLessonViews)
#include "test_lesson_views.moc"
